// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/yaml_items.h"

#include <yaml-cpp/eventhandler.h>

#include <istream>
#include <streambuf>
#include <string>
#include <utility>

namespace toroid {

namespace {

// Reads text in place (an istringstream would copy it), then `then`.
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(std::string_view text, std::string_view then = {}) : then_(then) { read(text); }

 private:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (then_.empty()) return traits_type::eof();
    read(std::exchange(then_, {}));
    return traits_type::to_int_type(*gptr());
  }
  void read(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // only read: the get area
    setg(begin, begin, begin + text.size());
  }
  std::string_view then_;
};

bool starts_document_marker(std::string_view line) {
  return (line.starts_with("---") || line.starts_with("...")) &&
         (line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r' || line[3] == '\n');
}

// Whether `c` ends a line's content: the line's end, or a comment.
bool ends_content(char c) { return c == '\n' || c == '\r' || c == '#'; }

// Whether the quoted scalar whose opening quote is at text[pos] closes
// inside `text`: yaml-cpp takes a quoted scalar that runs to the end of its
// input as ended there, so an item cut inside one (split_items cut it at a
// line that only looks like an item start) would load, wrongly.
bool quote_closes(std::string_view text, std::size_t pos) {
  const char quote = text[pos];
  for (std::size_t i = pos + 1; i < text.size(); ++i) {
    if (quote == '"' && text[i] == '\\') {
      ++i;  // an escape: the next character is not the end
    } else if (text[i] == quote) {
      if (quote == '\'' && i + 1 < text.size() && text[i + 1] == '\'') {
        ++i;  // '' stands for one quote
      } else {
        return true;
      }
    }
  }
  return false;
}

// Whether every scalar of `node` that is not plain is a block scalar or a
// quoted one that closes inside `text`; false also for an explicitly tagged
// or anchored one, whose style its mark does not show.
bool scalars_end_inside(const YAML::Node& node, std::string_view text) {
  switch (node.Type()) {
    case YAML::NodeType::Scalar: {
      if (node.Tag() == "?") return true;  // plain
      const std::size_t pos = static_cast<std::size_t>(node.Mark().pos);
      if (pos >= text.size()) return false;
      const char c = text[pos];
      if (c == '|' || c == '>') return true;
      return (c == '"' || c == '\'') && quote_closes(text, pos);
    }
    case YAML::NodeType::Sequence:
      for (const YAML::Node& child : node)
        if (!scalars_end_inside(child, text)) return false;
      return true;
    case YAML::NodeType::Map:
      for (const auto& entry : node)
        if (!scalars_end_inside(entry.first, text) || !scalars_end_inside(entry.second, text)) return false;
      return true;
    default: return true;
  }
}

// Takes a document's events and keeps none of them.
class IgnoreEvents : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

// Keeps the mark where its document starts.
class DocumentStart : public IgnoreEvents {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { start = mark; }
  YAML::Mark start;
};

}  // namespace

std::optional<YAML::Mark> second_document(std::string_view text) {
  TextBuffer buffer(text);
  std::istream in(&buffer);
  YAML::Parser parser(in);
  IgnoreEvents first;
  if (!parser.HandleNextDocument(first)) return std::nullopt;
  // One call only: on some stray tokens (a ',' or ']' after the list)
  // yaml-cpp gives an empty document each call without reading on.
  DocumentStart second;
  if (!parser.HandleNextDocument(second)) return std::nullopt;
  return second.start;
}

std::optional<YamlItems> split_items(std::string_view text) {
  // The first line with content must be an item: '-' and a space, after
  // nothing but spaces; its column is the list's. Every later line with '-'
  // at that column starts the next item; every other line with content must
  // stand right of that column. A line that only looks like an item start
  // (inside a flow collection or a quoted scalar of the item before) cuts
  // that item short, so that it does not load alone: load_item refuses it
  // and the loader reads the whole document instead.
  YamlItems out;
  std::vector<std::size_t> begins;
  int dash = -1;
  int line = 0;
  for (std::size_t pos = 0; pos < text.size(); ++line) {
    const std::size_t newline = text.find('\n', pos);
    const std::size_t next = newline == std::string_view::npos ? text.size() : newline + 1;
    const std::string_view l = text.substr(pos, next - pos);
    if (starts_document_marker(l)) return std::nullopt;  // several documents, or an explicit one
    const std::size_t indent = l.find_first_not_of(' ');
    if (indent != std::string_view::npos && !ends_content(l[indent])) {
      if (dash < 0) {
        if (l[indent] != '-') return std::nullopt;  // not a block list (or a byte-order mark)
        dash = static_cast<int>(indent);
      }
      if (static_cast<int>(indent) < dash || (static_cast<int>(indent) == dash && l[indent] != '-')) {
        // Content at or left of the list's column that is not an item:
        // yaml-cpp may end the document there, or read on into the next
        // item, where an item alone would not.
        return std::nullopt;
      }
      if (static_cast<int>(indent) == dash) {
        // The item's node must start on its '-' line, after a space.
        if (indent + 1 >= l.size() || l[indent + 1] != ' ') return std::nullopt;
        const std::size_t node = l.find_first_not_of(' ', indent + 1);
        if (node == std::string_view::npos || ends_content(l[node])) return std::nullopt;
        if (begins.empty()) {
          out.list.pos = static_cast<int>(pos + indent);
          out.list.line = line;
          out.list.column = dash;
        }
        begins.push_back(pos);
        out.items.push_back({{}, line, static_cast<int>(node)});
      }
    }
    pos = next;
  }
  if (begins.empty()) return std::nullopt;
  for (std::size_t i = 0; i < begins.size(); ++i) {
    const std::size_t end = i + 1 < begins.size() ? begins[i + 1] : text.size();
    out.items[i].text = text.substr(begins[i], end - begins[i]);
    out.items[i].followed = i + 1 < begins.size();
  }
  return out;
}

std::optional<YAML::Node> load_item(const YamlItemText& item) {
  // An item that another follows is read with a stand-in for that one after
  // it: what an item leaves behind can break the next one's first key in
  // yaml-cpp (a plain scalar where a key belongs, with no ':' after it, makes
  // the next "key:" an "illegal map value"), which its text alone would hide.
  std::string next_item;
  if (item.followed) {
    const std::size_t dash = item.text.find_first_not_of(' ');
    next_item.assign(dash == std::string_view::npos ? 0 : dash, ' ');
    next_item += "- a:\n";
  }
  TextBuffer buffer(item.text, next_item);
  std::istream in(&buffer);
  YAML::Node list;
  try {
    list = YAML::Load(in);
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
  if (!list.IsSequence() || list.size() != (item.followed ? 2u : 1u)) return std::nullopt;
  const YAML::Node node = list[0];
  if (node.Mark().line != 0 || node.Mark().column != item.column) return std::nullopt;
  if (item.text.find_first_of("\"'") != std::string_view::npos && !scalars_end_inside(node, item.text))
    return std::nullopt;
  return node;
}

}  // namespace toroid
