// SPDX-License-Identifier: Apache-2.0
// Loading a scene one top-level item at a time (the default) against loading
// its whole YAML document: positions in messages are the file's, and the
// documents that are loaded whole (flow lists, aliases) still load.
#include <gtest/gtest.h>

#include <string>

#include "support/scene_load.h"
#include "support/scene_text.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/shape.h"

namespace toroid {
namespace {

// The message of the SceneError that loading `text` throws ("" when it loads).
std::string error_of(const std::string& text, bool whole_document) {
  return testing::load_text(text, "s.yml", whole_document).error;
}

void expect_error_both_ways(const std::string& text, const std::string& message) {
  EXPECT_EQ(error_of(text, false), message) << "item by item";
  EXPECT_EQ(error_of(text, true), message) << "whole document";
}

// Lines 1-7 the camera, 8 a comment, 9-11 the light.
const std::string kCamera = testing::kSceneCamera + "# the light\n" + testing::kSceneLight;

TEST(SceneLoaderItems, AnErrorInTheThirdItemHasItsFileLineAndColumn) {
  expect_error_both_ways(kCamera +
                             "\n"                         // 12
                             "- add: sphere\n"            // 13
                             "  material:\n"              // 14
                             "    specular: 0.5\n"        // 15
                             "    color: [1, 0, red]\n",  // 16
                         "s.yml:16:19: expected a number, got 'red'");
  // Indented list, an item's key at another column.
  expect_error_both_ways(
      "  -   add: light\n"
      "      at: [0, 0, 0]\n"
      "      intensity: [1, 1, 1]\n"
      "  -   add: sphere\n"
      "  -     add: cube\n"
      "        shadw: false\n",
      "s.yml:6:9: unknown key 'shadw' in a cube (did you mean 'shadow'?)");
}

TEST(SceneLoaderItems, AnErrorInADefineHasTheDefinesPositionWhereALaterItemUsesIt) {
  const std::string defines = kCamera +
                              "- define: base\n"           // 12
                              "  value:\n"                 // 13
                              "    ambient: 0.2\n"         // 14
                              "    colr: [1, 0, 0]\n"      // 15
                              "- define: shiny\n"          // 16
                              "  extend: base\n"           // 17
                              "  value:\n"                 // 18
                              "    specular: 1\n"          // 19
                              "- define: turn\n"           // 20
                              "  value:\n"                 // 21
                              "    - [rotate-y, 1, 2]\n";  // 22
  expect_error_both_ways(defines +
                             "- add: sphere\n"       // 23
                             "  material: shiny\n",  // 24
                         "s.yml:15:5: unknown key 'colr' in a material (did you mean 'color'?)");
  expect_error_both_ways(defines +
                             "- add: sphere\n"         // 23
                             "  transform: [turn]\n",  // 24
                         "s.yml:22:7: 'rotate-y' takes 1 number, got 2");
  // The using item's own node, after the defines' items.
  expect_error_both_ways(defines +
                             "- add: sphere\n"        // 23
                             "  material: shiney\n",  // 24
                         "s.yml:24:13: undefined material 'shiney' (did you mean 'shiny'?)");
}

// A syntax error anywhere in the file is reported before an earlier item's
// mistake, as the whole document's YAML::Load finds it first.
TEST(SceneLoaderItems, ASyntaxErrorLaterInTheFileComesFirst) {
  const std::string text = kCamera +
                           "- add: sphere\n"                    // 12
                           "  colr: [1, 0, 0]\n"                // 13: an unknown key
                           "- add: cube\n"                      // 14
                           "  transform: [[scale, 1, 1, 1]\n";  // 15: an unterminated list
  const std::string whole = error_of(text, true);
  EXPECT_NE(whole.find("YAML syntax error"), std::string::npos) << whole;
  EXPECT_EQ(error_of(text, false), whole);
}

// A quoted scalar running on to a line that starts like an item: the item
// is read as the whole document reads it ("re - d"), not cut there.
TEST(SceneLoaderItems, AQuotedNameOverSeveralLinesIsReadWhole) {
  const std::string text = kCamera +
                           "- add: sphere\n"     // 12
                           "  material: \"re\n"  // 13
                           "- d\"\n";            // 14
  EXPECT_EQ(error_of(text, true), "s.yml:13:13: undefined material 're - d'");
  EXPECT_EQ(error_of(text, false), error_of(text, true));
}

TEST(SceneLoaderItems, AnErrorAboutTheWholeListHasTheListsPosition) {
  expect_error_both_ways(
      "# no camera\n"
      "  - add: light\n"
      "    at: [0, 0, 0]\n"
      "    intensity: [1, 1, 1]\n",
      "s.yml:2:3: the scene has no camera (add one with '- add: camera')");
}

TEST(SceneLoaderItems, AFlowListLoads) {
  const Scene s = load_scene_from_string(
      "[{add: camera, width: 8, height: 6, field-of-view: 0.8, from: [0, 2, -5], to: [0, 0, 0], up: [0, 1, 0]},\n"
      " {add: light, at: [-10, 10, -10], intensity: [1, 1, 1]},\n"
      " {add: sphere, material: {color: [0.5, 0.25, 1]}}]\n",
      "s.yml", ".");
  ASSERT_EQ(s.world.objects.size(), 1u);
  EXPECT_TRUE(approx_equal(s.world.objects[0]->material().color, Color{0.5, 0.25, 1}));
  EXPECT_EQ(error_of("[{add: light, at: [0, 0, 0], intensity: [1, 1, 1]},\n {add: cub}]\n", false),
            "s.yml:2:8: unknown shape 'cub' (did you mean 'cube'?)");
}

TEST(SceneLoaderItems, AnAliasToAnAnchorInAnotherItemLoads) {
  const Scene s = load_scene_from_string(kCamera +
                                             "- add: sphere\n"
                                             "  material: &red\n"
                                             "    color: [1, 0, 0]\n"
                                             "- add: cube\n"
                                             "  material: *red\n",
                                         "s.yml", ".");
  ASSERT_EQ(s.world.objects.size(), 2u);
  EXPECT_TRUE(approx_equal(s.world.objects[0]->material().color, Color{1, 0, 0}));
  EXPECT_TRUE(approx_equal(s.world.objects[1]->material().color, Color{1, 0, 0}));
}

TEST(SceneLoaderItems, ASyntaxErrorAfterABadItemIsReportedFirstAsBefore) {
  // The whole text is parsed before any item is built.
  expect_error_both_ways(kCamera +
                             "- add: spher\n"      // 12
                             "- add: cube\n"       // 13
                             "  transform: [[\n",  // 14
                         "s.yml:15:1: YAML syntax error: end of sequence flow not found");
}

// Found by CI's scene_fuzz: the item alone loaded (an unused define with a
// stray line), the whole document did not.
TEST(SceneLoaderItems, AStrayLineThatBreaksTheNextItemIsTheDocumentsSyntaxError) {
  expect_error_both_ways(kCamera +
                             "- define: shell\n"   // 12
                             "  value:\n"          // 13
                             "    ambient: 0.1\n"  // 14
                             "    specu, 1, 0]\n"  // 15
                             "\n"                  // 16
                             "- add: sphere\n",    // 17
                         "s.yml:17:6: YAML syntax error: illegal map value");
}

// yaml-cpp's YAML::Load stops at the end of the first document's list and
// drops what follows; the scene is refused there instead, both ways.
TEST(SceneLoaderItems, TextAfterTheListIsAnError) {
  const std::string after =
      "s.yml:12:1: the scene's list ends before this (a scene is one YAML document: a list of "
      "items, each '- ' at the list's column)";
  expect_error_both_ways(kCamera + "add: sphere\n", after);         // 12: a map key at the list's column
  expect_error_both_ways(kCamera + "\f- add: sphere\n", after);     // 12: a form feed before the '-'
  expect_error_both_ways(kCamera + "---\n- add: sphere\n", after);  // 12: a second document
  expect_error_both_ways(kCamera + ", 1]\n", after);  // 12: stray tokens, which yaml-cpp reads as an empty document
  expect_error_both_ways(kCamera + "---\n", after);   // 12: even an empty second document
  EXPECT_EQ(error_of(kCamera + "...\n# the end\n", false), "");  // the document's end marker, then a comment
}

// A carriage return alone (old Mac line endings) is no line break to
// yaml-cpp: it may drop the rest of the file or read an item otherwise than
// the whole document does. It is refused, both ways; Windows line endings
// load.
TEST(SceneLoaderItems, ACarriageReturnThatEndsNoLineIsAnError) {
  const std::string message =
      ": a carriage return that does not end a line (save the file with Unix or Windows line endings)";
  expect_error_both_ways(kCamera + "- add: sphere\n  \r material: {}\n" + testing::kSceneLight, "s.yml:13:3" + message);
  expect_error_both_ways(kCamera + "\r- add: sphere\n", "s.yml:12:1" + message);
  expect_error_both_ways(kCamera + "- add: sphere\r", "s.yml:12:14" + message);
  std::string windows;
  for (char c : kCamera + "- add: sphere\n  material: {}\n" + testing::kSceneLight) {
    if (c == '\n') windows += '\r';
    windows += c;
  }
  EXPECT_EQ(error_of(windows, false), "");
  EXPECT_EQ(error_of(windows, true), "");
}

}  // namespace
}  // namespace toroid
