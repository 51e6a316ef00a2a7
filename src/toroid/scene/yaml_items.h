// SPDX-License-Identifier: Apache-2.0
// The top-level items of a YAML scene one at a time, so that loading a big
// scene never holds yaml-cpp's node tree of the whole document:
// split_items() parses the text once without building nodes and finds where
// each item of the top-level block list is; load_item() builds one item.
#pragma once

#include <yaml-cpp/yaml.h>

#include <optional>
#include <string_view>
#include <vector>

namespace toroid {

// One item of the top-level list: whole lines, from the one its '-' is on to
// the line before the next item's.
struct YamlItemText {
  std::string_view text;
  int first_line = 0;  // 0-based line of the file where `text` starts
  int column = 0;      // 0-based column of the item's node on that line
};

struct YamlItems {
  YAML::Mark list;  // the top-level list
  std::vector<YamlItemText> items;
};

// The items of a document whose top node is a block list. Returns nullopt for
// anything else, to be loaded whole with YAML::Load: a flow list, a map, an
// empty document, aliases (an anchor may be named in another item), several
// documents, a byte-order mark, an item whose node is not on its '-' line.
// Throws YAML::Exception for a syntax error, as YAML::Load of `text` does.
std::optional<YamlItems> split_items(std::string_view text);

// The node of one item, with the marks of its own text: add `first_line` to
// a mark's line for the file's (columns are the file's). Returns nullopt when
// the text alone does not read as that one item (say a tag directive of the
// document that it needs): load the whole document instead.
std::optional<YAML::Node> load_item(const YamlItemText& item);

}  // namespace toroid
