// SPDX-License-Identifier: Apache-2.0
// Reading values out of a scene's yaml-cpp nodes, with every error reported
// as "FILE:LINE:COLUMN: message" at the node it is about.
#pragma once

#include <yaml-cpp/yaml.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "toroid/math/color.h"
#include "toroid/math/tuple.h"

namespace toroid {

// One key/value pair of a YAML map, keeping the nodes for their positions.
struct Entry {
  std::string key;
  YAML::Node key_node;
  YAML::Node value;
};

// `- define: NAME` with its `value` and `extend`, and the scene item it came
// from (for positions, see SceneReader::file_mark).
struct Define {
  YAML::Node name_node;
  YAML::Node value;
  std::optional<YAML::Node> extend;
  YAML::Node item;
  int item_line = 0;
};
using Defines = std::map<std::string, Define>;

// " (did you mean 'x'?)" for the nearest candidate if it is near enough, else
// empty. On a tie the earliest candidate wins.
std::string suggestion(const std::string& word, const std::vector<std::string>& candidates);

// "'text'", "a list", "a map" or "nothing": what a node is, for messages.
std::string describe(const YAML::Node& node);

class SceneReader {
 public:
  // `defines` are the scene's defines so far: their nodes' positions count
  // from their own items (file_mark).
  SceneReader(std::string source, const Defines& defines) : source_(std::move(source)), defines_(defines) {}

  // Loading item by item: `item` is the current top-level item, whose nodes'
  // lines count from `first_line` of the file.
  void start_item(const YAML::Node& item, int first_line);
  bool item_by_item() const { return item_by_item_; }
  int item_line() const { return item_line_; }

  [[noreturn]] void fail(const YAML::Mark& mark, const std::string& what) const;
  [[noreturn]] void fail(const YAML::Node& node, const std::string& what) const { fail(file_mark(node), what); }
  // The node's position in the file. Loaded item by item, a node's mark
  // counts lines from its item's first line: the current item's or, for a
  // define's node, the define's. Only errors need it, so the item is found by
  // searching.
  YAML::Mark file_mark(const YAML::Node& node) const;

  // The pairs of a map in order; fails unless `map` is a map with plain,
  // distinct keys. `what` names the map in messages ("a shape").
  std::vector<Entry> entries(const YAML::Node& map, const std::string& what) const;

  double number(const YAML::Node& n) const;
  double positive(const YAML::Node& n, const std::string& what) const;  // > 0
  int integer(const YAML::Node& n) const;                               // within +-2^30
  bool boolean(const YAML::Node& n) const;
  std::string name(const YAML::Node& n, const std::string& what) const;  // a non-empty scalar
  std::vector<double> numbers(const YAML::Node& n, std::size_t count, const std::string& what) const;
  Color color(const YAML::Node& n, const std::string& what) const;
  Tuple point3(const YAML::Node& n, const std::string& what) const;
  Tuple vector3(const YAML::Node& n, const std::string& what) const;

 private:
  std::string source_;
  const Defines& defines_;
  bool item_by_item_ = false;
  std::optional<YAML::Node> item_;
  int item_line_ = 0;
};

}  // namespace toroid
