// SPDX-License-Identifier: Apache-2.0
// The keys of one scene item (a shape, a light, a pattern, ...) as a builder
// reads them, after pbrt's ParameterDictionary: get() marks a key as read,
// and report_unused() fails at the first key nobody asked for. The keys a
// builder asks for are thus the keys its kind allows.
//
// get() does not look at the value: a builder asks for all its keys, calls
// report_unused() and reads the values after, so that an unknown key is
// reported before a bad value of a known one.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "toroid/scene/scene_reader.h"

namespace toroid {

class ItemParams;

// One key of an item; false when the item does not give it.
class Param {
 public:
  Param(const ItemParams& params, std::string key, const Entry* entry)
      : params_(&params), key_(std::move(key)), entry_(entry) {}
  explicit operator bool() const { return entry_ != nullptr; }
  const std::string& key() const { return key_; }
  // The value and key nodes: only when given.
  const YAML::Node& value() const { return entry_->value; }
  const YAML::Node& key_node() const { return entry_->key_node; }
  // The value; fails with "WHAT needs 'KEY'" at the item when not given.
  const YAML::Node& need(const std::string& what) const;

  // The value read as one type (SceneReader), failing at the value's node.
  double number() const;
  double positive(const std::string& what) const;
  int integer() const;
  bool boolean() const;
  std::string name(const std::string& what) const;
  Color color(const std::string& what) const;
  Tuple point3(const std::string& what) const;
  Tuple vector3(const std::string& what) const;

 private:
  const SceneReader& reader() const;
  const ItemParams* params_;
  std::string key_;
  const Entry* entry_;
};

class ItemParams {
 public:
  // `entries` in file order (SceneReader::entries); `where` is the node that
  // "needs 'KEY'" messages point at.
  ItemParams(const SceneReader& reader, std::vector<Entry> entries, YAML::Node where)
      : reader_(reader), entries_(std::move(entries)), where_(std::move(where)) {}
  ItemParams(const ItemParams&) = delete;  // Params point into entries_
  ItemParams& operator=(const ItemParams&) = delete;

  // The key, marked as read.
  Param get(const std::string& key);
  // Whether the item gives the key, without marking it read.
  bool has(const std::string& key) const;
  // Fails "unknown key 'K' in WHAT" at the first key in file order not read,
  // suggesting the nearest read key (the earliest asked for on a tie).
  void report_unused(const std::string& what) const;

  const std::vector<Entry>& entries() const { return entries_; }
  const YAML::Node& where() const { return where_; }
  const SceneReader& reader() const { return reader_; }

 private:
  const SceneReader& reader_;
  std::vector<Entry> entries_;
  YAML::Node where_;
  std::vector<std::string> read_;  // in the order first asked for
};

// A builder of one kind (a shape, a pattern, ...) in a table by name; the
// table's order is the order of the names in "did you mean" suggestions.
template <class Build>
struct NamedBuilder {
  std::string_view name;
  Build build;
};

template <class Build>
const NamedBuilder<Build>* find_builder(std::span<const NamedBuilder<Build>> table, std::string_view name) {
  for (const auto& b : table)
    if (b.name == name) return &b;
  return nullptr;
}

template <class Build>
std::vector<std::string> builder_names(std::span<const NamedBuilder<Build>> table) {
  std::vector<std::string> names;
  for (const auto& b : table) names.emplace_back(b.name);
  return names;
}

}  // namespace toroid
