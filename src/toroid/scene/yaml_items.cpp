// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/yaml_items.h"

#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/parser.h>

#include <istream>
#include <streambuf>

namespace toroid {

namespace {

// Reads text in place (an istringstream would copy it).
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(std::string_view text) {
    char* begin = const_cast<char*>(text.data());  // only read: the get area
    setg(begin, begin, begin + text.size());
  }
};

// Records where the top node and the nodes of its items start; builds nothing.
class ItemFinder : public YAML::EventHandler {
 public:
  bool top_is_block_list = false;
  bool has_alias = false;
  YAML::Mark list;
  std::vector<YAML::Mark> items;

  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t) override { node(mark); }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    has_alias = true;
    node(mark);
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t, const std::string&) override { node(mark); }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t,
                       YAML::EmitterStyle::value style) override {
    if (depth_ == 0 && style == YAML::EmitterStyle::Block) {
      top_is_block_list = true;
      list = mark;
    }
    node(mark);
    ++depth_;
  }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    node(mark);
    ++depth_;
  }
  void OnMapEnd() override { --depth_; }

 private:
  void node(const YAML::Mark& mark) {
    if (depth_ == 1) items.push_back(mark);
  }
  int depth_ = 0;
};

bool starts_document_marker(std::string_view line) {
  return (line.starts_with("---") || line.starts_with("...")) &&
         (line.size() == 3 || line[3] == ' ' || line[3] == '\t' || line[3] == '\r' || line[3] == '\n');
}

}  // namespace

std::optional<YamlItems> split_items(std::string_view text) {
  ItemFinder finder;
  {
    TextBuffer buffer(text);
    std::istream in(&buffer);
    YAML::Parser parser(in);
    if (!parser.HandleNextDocument(finder)) return std::nullopt;  // an empty document
  }
  if (!finder.top_is_block_list || finder.has_alias || finder.items.empty()) return std::nullopt;

  // yaml-cpp counts lines at '\n' and columns in bytes (UTF-8). Each item's
  // '-' must stand at the list's column of the line where its node starts,
  // after nothing but spaces.
  const int dash = finder.list.column;
  YamlItems out;
  out.list = finder.list;
  std::size_t line_begin = 0;
  int line = 0;
  std::vector<std::size_t> begins;
  for (const YAML::Mark& m : finder.items) {
    if (m.line < line || (!begins.empty() && m.line == line) || m.column <= dash) return std::nullopt;
    for (; line < m.line; ++line) {
      line_begin = text.find('\n', line_begin);
      if (line_begin == std::string_view::npos) return std::nullopt;
      ++line_begin;
    }
    const std::string_view lead = text.substr(line_begin, static_cast<std::size_t>(dash) + 1);
    if (lead.size() != static_cast<std::size_t>(dash) + 1 || lead.back() != '-' ||
        lead.find_first_not_of(' ') != static_cast<std::size_t>(dash))
      return std::nullopt;
    begins.push_back(line_begin);
    out.items.push_back({{}, m.line, m.column});
  }
  for (std::size_t i = 0; i < begins.size(); ++i) {
    const std::size_t end = i + 1 < begins.size() ? begins[i + 1] : text.size();
    out.items[i].text = text.substr(begins[i], end - begins[i]);
  }
  // The last item runs to the end of the text: a second document there ends
  // the first one (YAML::Load reads only the first).
  std::string_view tail = out.items.back().text;
  for (std::size_t nl = tail.find('\n'); nl != std::string_view::npos; nl = tail.find('\n', nl + 1))
    if (starts_document_marker(tail.substr(nl + 1))) return std::nullopt;
  return out;
}

std::optional<YAML::Node> load_item(const YamlItemText& item) {
  TextBuffer buffer(item.text);
  std::istream in(&buffer);
  YAML::Node list;
  try {
    list = YAML::Load(in);
  } catch (const YAML::Exception&) {
    return std::nullopt;
  }
  if (!list.IsSequence() || list.size() != 1) return std::nullopt;
  const YAML::Node node = list[0];
  if (node.Mark().line != 0 || node.Mark().column != item.column) return std::nullopt;
  return node;
}

}  // namespace toroid
