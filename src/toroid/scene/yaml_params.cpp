// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/yaml_params.h"

#include <algorithm>

namespace toroid {

const SceneReader& Param::reader() const { return params_->reader(); }

const YAML::Node& Param::need(const std::string& what) const {
  if (!entry_) reader().fail(params_->where(), what + " needs '" + key_ + "'");
  return entry_->value;
}

double Param::number() const { return reader().number(value()); }
double Param::positive(const std::string& what) const { return reader().positive(value(), what); }
int Param::integer() const { return reader().integer(value()); }
bool Param::boolean() const { return reader().boolean(value()); }
std::string Param::name(const std::string& what) const { return reader().name(value(), what); }
Color Param::color(const std::string& what) const { return reader().color(value(), what); }
Tuple Param::point3(const std::string& what) const { return reader().point3(value(), what); }
Tuple Param::vector3(const std::string& what) const { return reader().vector3(value(), what); }

Param ItemParams::get(const std::string& key) {
  if (std::find(read_.begin(), read_.end(), key) == read_.end()) read_.push_back(key);
  const auto it = std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
  return Param(*this, key, it == entries_.end() ? nullptr : &*it);
}

bool ItemParams::has(const std::string& key) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.key == key; });
}

void ItemParams::report_unused(const std::string& what) const {
  for (const Entry& e : entries_)
    if (std::find(read_.begin(), read_.end(), e.key) == read_.end())
      reader_.fail(e.key_node, "unknown key '" + e.key + "' in " + what + suggestion(e.key, read_));
}

}  // namespace toroid
