// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/yaml_items.h"

#include <gtest/gtest.h>

#include <string>

namespace toroid {
namespace {

TEST(SplitItems, FindsEachItemsLinesFromItsDashToTheNextItem) {
  const std::string text =
      "# a scene\n"
      "\n"
      "- add: camera\n"
      "  width: 8\n"
      "# between items\n"
      "\n"
      "-   add: light\n"
      "- add: sphere\n";
  const auto items = split_items(text);
  ASSERT_TRUE(items);
  EXPECT_EQ(items->list.line, 2);
  EXPECT_EQ(items->list.column, 0);
  ASSERT_EQ(items->items.size(), 3u);
  EXPECT_EQ(items->items[0].text, "- add: camera\n  width: 8\n# between items\n\n");
  EXPECT_EQ(items->items[0].first_line, 2);
  EXPECT_EQ(items->items[0].column, 2);
  EXPECT_EQ(items->items[1].text, "-   add: light\n");
  EXPECT_EQ(items->items[1].first_line, 6);
  EXPECT_EQ(items->items[1].column, 4);
  EXPECT_EQ(items->items[2].text, "- add: sphere\n");
  EXPECT_EQ(items->items[2].first_line, 7);
}

TEST(SplitItems, TakesAnIndentedList) {
  const auto items = split_items("  - a: [1,\n     2]\n  - b\n");
  ASSERT_TRUE(items);
  EXPECT_EQ(items->list.column, 2);
  ASSERT_EQ(items->items.size(), 2u);
  EXPECT_EQ(items->items[0].text, "  - a: [1,\n     2]\n");
  EXPECT_EQ(items->items[0].column, 4);
  EXPECT_EQ(items->items[1].text, "  - b\n");
  EXPECT_EQ(items->items[1].first_line, 2);
}

TEST(SplitItems, LeavesEveryOtherDocumentToBeLoadedWhole) {
  const char* const whole[] = {
      "",                                  // empty
      "# only a comment\n",                // empty
      "[{add: camera}, {add: sphere}]\n",  // a flow list
      "add: camera\n",                     // a map
      "camera\n",                          // a scalar
      "-\n  add: camera\n",                // the item's node is below its '-'
      "- a\n-\n- c\n",                     // an empty item
      "- a\n---\n- b\n",                   // a second document
      "- a\n...\n",                        // the end of the document
      "\xEF\xBB\xBF- a\n- b\n",            // a byte-order mark
      "  - a: [1,\n2]\n  - b\n",           // a line left of the list's column (yaml-cpp reads on)
      "- a: x\nQ y\n- b\n",                // a line at the list's column that is no item (yaml-cpp stops)
  };
  for (const char* text : whole) {
    SCOPED_TRACE(text);
    EXPECT_FALSE(split_items(text));
  }
}

// split_items parses nothing: an item that holds a syntax error, or that a
// line looking like an item start cut short, does not load alone (the
// loader then reads the whole document, and YAML::Load reports the error).
TEST(SplitItems, LeavesSyntaxErrorsToTheItemsThatHoldThem) {
  const auto unterminated = split_items("- add: camera\n  width: 8\n- add: [1, 2\n- add: light\n");
  ASSERT_TRUE(unterminated);
  ASSERT_EQ(unterminated->items.size(), 3u);
  EXPECT_TRUE(load_item(unterminated->items[0]));
  EXPECT_FALSE(load_item(unterminated->items[1]));

  const auto bad_indent = split_items("- add: camera\n   width: 8\n  height: 6\n");
  ASSERT_TRUE(bad_indent);
  EXPECT_FALSE(load_item(bad_indent->items[0]));

  // A quoted scalar and a flow list running on to a line that starts with
  // '- ' at the list's column: the item is cut there and does not load.
  for (const char* text : {"- a: \"x\n- b\"\n- c\n", "- a: [1,\n- 2]\n- c\n"}) {
    SCOPED_TRACE(text);
    const auto cut = split_items(text);
    ASSERT_TRUE(cut);
    EXPECT_FALSE(load_item(cut->items[0]));
  }
}

TEST(SplitItems, AnAliasLoadsAloneOnlyWithItsAnchorInTheSameItem) {
  const auto items = split_items("- add: sphere\n  material: &m {}\n  again: *m\n- {add: cube, material: *m}\n");
  ASSERT_TRUE(items);
  ASSERT_EQ(items->items.size(), 2u);
  EXPECT_TRUE(load_item(items->items[0]));
  EXPECT_FALSE(load_item(items->items[1]));  // its anchor is in the first item
}

TEST(LoadItem, GivesTheItemsNodeWithMarksCountedFromItsFirstLine) {
  const auto items = split_items("- add: camera\n- add: sphere\n  material:\n    color: [1, 0, 0]\n");
  ASSERT_TRUE(items);
  ASSERT_EQ(items->items.size(), 2u);
  const auto sphere = load_item(items->items[1]);
  ASSERT_TRUE(sphere);
  EXPECT_EQ((*sphere)["add"].Scalar(), "sphere");
  const YAML::Mark color = (*sphere)["material"]["color"].Mark();
  EXPECT_EQ(items->items[1].first_line + color.line, 3);  // the file's line
  EXPECT_EQ(color.column, 11);
}

// In yaml-cpp a plain scalar where a key belongs, with no ':' after it,
// makes the first key of the next item an "illegal map value"; the item is
// refused when another follows it, so that the whole document's load
// reports that error, and loads when it is the last, as the document does.
TEST(LoadItem, RefusesAnItemThatBreaksTheNextItemsFirstKey) {
  const char* text = "- a: b\n  c: d\n  stray\n- e: f\n";
  EXPECT_THROW(YAML::Load(text), YAML::ParserException);
  const auto items = split_items(text);
  ASSERT_TRUE(items);
  ASSERT_EQ(items->items.size(), 2u);
  EXPECT_TRUE(items->items[0].followed);
  EXPECT_FALSE(items->items[1].followed);
  EXPECT_FALSE(load_item(items->items[0]));
  EXPECT_TRUE(load_item(items->items[1]));

  const auto last = split_items("- e: f\n- a: b\n  c: d\n  stray\n");
  ASSERT_TRUE(last);
  ASSERT_EQ(last->items.size(), 2u);
  EXPECT_NO_THROW(YAML::Load("- e: f\n- a: b\n  c: d\n  stray\n"));
  EXPECT_TRUE(load_item(last->items[0]));
  EXPECT_TRUE(load_item(last->items[1]));
}

TEST(LoadItem, RefusesTextThatIsNotThatOneItem) {
  EXPECT_FALSE(load_item({"- a\n- b\n", 0, 2}));  // two items
  EXPECT_FALSE(load_item({"a: b\n", 0, 0}));      // no list
  EXPECT_FALSE(load_item({"- a\n", 0, 4}));       // not at the expected column
  EXPECT_FALSE(load_item({"- [a\n", 0, 2}));      // a syntax error
  EXPECT_TRUE(load_item({"- a\n", 0, 2}));
}

}  // namespace
}  // namespace toroid
