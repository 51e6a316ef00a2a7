// SPDX-License-Identifier: Apache-2.0
// The top-level items of a YAML scene one at a time, so that loading a big
// scene never holds yaml-cpp's node tree of the whole document:
// split_items() cuts the text into items by their lines, without parsing it;
// load_item() parses and builds one item, and refuses one that does not read
// as that item alone (then the document is loaded whole).
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
  int first_line = 0;     // 0-based line of the file where `text` starts
  int column = 0;         // 0-based column of the item's node on that line
  bool followed = false;  // whether another item comes after it
};

struct YamlItems {
  YAML::Mark list;  // the top-level list
  std::vector<YamlItemText> items;
};

// The items of a document whose first content is a block list item: from
// each line with '-' and a space at the list's column to the next such line.
// Returns nullopt for anything else, to be loaded whole with YAML::Load: a
// flow list, a map, a scalar, an empty document, a document marker ("---",
// "..."), a byte-order mark, an item whose node is not on its '-' line. It
// parses nothing: a syntax error, or an alias of another item's anchor,
// makes that item's load_item fail.
std::optional<YamlItems> split_items(std::string_view text);

// The node of one item, with the marks of its own text: add `first_line` to
// a mark's line for the file's (columns are the file's). Returns nullopt when
// the text alone does not read as that one item (say a tag directive of the
// document that it needs), or, when `followed`, as an item that another can
// follow: load the whole document instead.
std::optional<YAML::Node> load_item(const YamlItemText& item);

// Where a second YAML document starts in `text` (yaml-cpp's YAML::Load reads
// the first and drops the rest, which may be anything from '---' to a line at
// the list's column that is no item); nullopt when there is none. Throws
// YAML::Exception on a syntax error. It parses the first document again,
// without building its nodes.
std::optional<YAML::Mark> second_document(std::string_view text);

}  // namespace toroid
