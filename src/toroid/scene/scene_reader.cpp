// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/scene_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "toroid/io/number_text.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {

int edit_distance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const int sub = prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, sub});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  int best_d = 1 << 30;
  for (const auto& c : candidates) {
    const int d = edit_distance(word, c);
    if (d < best_d) best_d = d, best = c;
  }
  const int limit = std::max<int>(2, static_cast<int>(word.size()) / 3);
  if (best.empty() || best_d > limit) return {};
  return " (did you mean '" + best + "'?)";
}

std::string describe(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Scalar: return "'" + n.Scalar() + "'";
    case YAML::NodeType::Sequence: return "a list";
    case YAML::NodeType::Map: return "a map";
    default: return "nothing";
  }
}

namespace {

bool contains(const YAML::Node& tree, const YAML::Node& node) {
  if (tree.is(node)) return true;
  if (tree.IsSequence())
    for (const YAML::Node& child : tree)
      if (contains(child, node)) return true;
  if (tree.IsMap())
    for (const auto& entry : tree)
      if (contains(entry.first, node) || contains(entry.second, node)) return true;
  return false;
}

}  // namespace

void SceneReader::start_item(const YAML::Node& item, int first_line) {
  item_by_item_ = true;
  item_.emplace(item);  // not operator=: a YAML::Node assigned to rewrites the node it held
  item_line_ = first_line;
}

void SceneReader::fail(const YAML::Mark& mark, const std::string& what) const {
  std::ostringstream os;
  os << source_ << ':';
  if (mark.line >= 0)
    os << mark.line + 1 << ':' << mark.column + 1 << ": ";
  else
    os << ' ';
  os << what;
  throw SceneError(os.str());
}

YAML::Mark SceneReader::file_mark(const YAML::Node& node) const {
  YAML::Mark mark = node.Mark();
  if (!item_by_item_ || mark.is_null()) return mark;
  int line = item_line_;
  if (!(item_ && contains(*item_, node)))
    for (const auto& [_, d] : defines_)
      if (contains(d.item, node)) line = d.item_line;
  mark.line += line;
  return mark;
}

std::vector<Entry> SceneReader::entries(const YAML::Node& map, const std::string& what) const {
  if (!map.IsMap()) fail(map, what + " must be a map, got " + describe(map));
  std::vector<Entry> out;
  std::set<std::string> seen;
  for (auto it = map.begin(); it != map.end(); ++it) {
    if (!it->first.IsScalar()) fail(it->first, "keys must be plain names");
    const std::string key = it->first.Scalar();
    if (!seen.insert(key).second) fail(it->first, "duplicate key '" + key + "'");
    out.push_back({key, it->first, it->second});
  }
  return out;
}

namespace {

// A decimal read_finite_double takes ("-12", "0.5", "3e-2") without
// building a stream: from_chars rounds as the stream of YAML::convert does
// (both correctly). False, for YAML::convert to decide as before, for a
// leading '+' (read_finite_double would take "+-1"), and for a value that
// under- or overflows.
bool read_plain_decimal(const std::string& text, double& v) {
  if (text.starts_with('+') || read_finite_double(text, v) != NumberText::Ok) return false;
  if (v != 0) return std::isnormal(v);
  const std::string_view mantissa = std::string_view(text).substr(0, text.find_first_of("eE"));
  return mantissa.find_first_of("123456789") == std::string_view::npos;  // a true zero
}

}  // namespace

double SceneReader::number(const YAML::Node& n) const {
  if (!n.IsScalar()) fail(n, "expected a number, got " + describe(n));
  double v = 0;
  if (read_plain_decimal(n.Scalar(), v)) return v;
  if (!YAML::convert<double>::decode(n, v)) {
    const char* text = n.Scalar().c_str();
    char* end = nullptr;
    errno = 0;
    std::strtod(text, &end);
    if (errno == ERANGE && end != text && *end == '\0') fail(n, "number out of range: '" + n.Scalar() + "'");
    fail(n, "expected a number, got '" + n.Scalar() + "'");
  }
  if (!std::isfinite(v)) fail(n, "expected a finite number, got '" + n.Scalar() + "'");
  return v;
}

double SceneReader::positive(const YAML::Node& n, const std::string& what) const {
  const double v = number(n);
  if (v <= 0) fail(n, what + " must be > 0, got " + n.Scalar());
  return v;
}

int SceneReader::integer(const YAML::Node& n) const {
  if (!n.IsScalar()) fail(n, "expected an integer, got " + describe(n));
  long long v = 0;
  if (!YAML::convert<long long>::decode(n, v)) fail(n, "expected an integer, got '" + n.Scalar() + "'");
  if (v < -(1LL << 30) || v > (1LL << 30)) fail(n, "integer out of range: " + n.Scalar());
  return static_cast<int>(v);
}

bool SceneReader::boolean(const YAML::Node& n) const {
  bool b = false;
  if (!n.IsScalar() || !YAML::convert<bool>::decode(n, b)) fail(n, "expected true or false, got " + describe(n));
  return b;
}

std::string SceneReader::name(const YAML::Node& n, const std::string& what) const {
  if (!n.IsScalar() || n.Scalar().empty()) fail(n, what + " must be a name, got " + describe(n));
  return n.Scalar();
}

std::vector<double> SceneReader::numbers(const YAML::Node& n, std::size_t count, const std::string& what) const {
  if (!n.IsSequence()) fail(n, what + " must be a list of " + std::to_string(count) + " numbers, got " + describe(n));
  if (n.size() != count)
    fail(n, what + " must have " + std::to_string(count) + " numbers, got " + std::to_string(n.size()));
  std::vector<double> v;
  for (std::size_t i = 0; i < count; ++i) v.push_back(number(n[i]));
  return v;
}

Color SceneReader::color(const YAML::Node& n, const std::string& what) const {
  const auto v = numbers(n, 3, what);
  return Color{v[0], v[1], v[2]};
}

Tuple SceneReader::point3(const YAML::Node& n, const std::string& what) const {
  const auto v = numbers(n, 3, what);
  return point(v[0], v[1], v[2]);
}

Tuple SceneReader::vector3(const YAML::Node& n, const std::string& what) const {
  const auto v = numbers(n, 3, what);
  return vector(v[0], v[1], v[2]);
}

}  // namespace toroid
