// SPDX-License-Identifier: Apache-2.0
// Warnings: values that are allowed but almost surely a mistake. A rotation
// beyond a full turn is almost surely in degrees: the scene loads as written
// and the loader says where, and what the angle would be in radians. A field
// of view beyond pi cannot be rendered: an error, which says the same.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "support/approx.h"
#include "support/scene_load.h"
#include "support/scene_text.h"
#include "toroid/math/transform.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/shape.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

// Lines 1-7 the camera, 8-10 the light.
const std::string kCamera = testing::kSceneCamera + testing::kSceneLight;

using Loaded = testing::LoadedText;

Loaded load(const std::string& text, bool whole_document) {
  return testing::load_text(text, "scene.yml", whole_document);
}

// The warnings of a scene that loads, the same item by item and whole.
std::vector<std::string> warnings_of(const std::string& text) {
  const Loaded by_item = load(text, false), whole = load(text, true);
  EXPECT_EQ(by_item.error, "");
  EXPECT_EQ(whole.error, "");
  EXPECT_EQ(by_item.warnings, whole.warnings);
  return by_item.warnings;
}

using Lines = std::vector<std::string>;

const std::string kDegrees =
    "scene.yml:13:18: warning: rotate-x angle -90 is more than 2 pi radians (a full turn); if it is in degrees, "
    "write -1.5708 (angles are in radians)";

TEST(SceneWarnings, ARotationInDegreesWarnsAtTheNumberAndLoadsAsWritten) {
  const std::string text = kCamera +
                           "- add: torus\n"            // 11
                           "  transform:\n"            // 12
                           "    - [rotate-x, -90]\n";  // 13
  EXPECT_EQ(warnings_of(text), Lines{kDegrees});
  SceneLoadOptions quiet;
  quiet.on_warning = [](const std::string&) {};
  const Scene s = load_scene_from_string(text, "scene.yml", ".", quiet);
  ASSERT_EQ(s.world.objects.size(), 1u);
  EXPECT_APPROX(s.world.objects[0]->transform(), rotation_x(-90));
}

TEST(SceneWarnings, EveryRotationBeyondAFullTurnWarnsAndNoneWithin) {
  const std::string within = kCamera +
                             "- add: sphere\n"
                             "  transform:\n"
                             "    - [rotate-x, 1.5708]\n"
                             "    - [rotate-y, -6.283185]\n"
                             "    - [rotate-z, 6.2831853]\n"
                             "    - [rotate-x, 0]\n"
                             "    - [translate, 90, -720, 45]\n"
                             "    - [scale, 100, 100, 100]\n"
                             "    - [shear, 10, 0, 0, 0, 0, 0]\n";
  EXPECT_EQ(warnings_of(within), Lines{});
  EXPECT_EQ(warnings_of(kCamera + "- add: cube\n"                  // 11
                                  "  transform:\n"                 // 12
                                  "    - [rotate-y, 45]\n"         // 13
                                  "    - [rotate-z, 6.2832]\n"     // 14
                                  "    - [ rotate-x,   180 ]\n"),  // 15
            (Lines{"scene.yml:13:18: warning: rotate-y angle 45 is more than 2 pi radians (a full turn); if it is in "
                   "degrees, write 0.785398 (angles are in radians)",
                   "scene.yml:14:18: warning: rotate-z angle 6.2832 is more than 2 pi radians (a full turn); if it is "
                   "in degrees, write 0.109663 (angles are in radians)",
                   "scene.yml:15:21: warning: rotate-x angle 180 is more than 2 pi radians (a full turn); if it is in "
                   "degrees, write 3.14159 (angles are in radians)"}));
}

TEST(SceneWarnings, PatternsAndGroupsWarnToo) {
  EXPECT_EQ(warnings_of(kCamera + "- add: group\n"                              // 11
                                  "  transform: [[rotate-z, 30]]\n"             // 12
                                  "  children:\n"                               // 13
                                  "    - add: plane\n"                          // 14
                                  "      material:\n"                           // 15
                                  "        pattern:\n"                          // 16
                                  "          type: stripes\n"                   // 17
                                  "          colors: [[1, 1, 1], [0, 0, 0]]\n"  // 18
                                  "          transform:\n"                      // 19
                                  "            - [rotate-y, -30]\n"),           // 20
            (Lines{"scene.yml:12:26: warning: rotate-z angle 30 is more than 2 pi radians (a full turn); if it is in "
                   "degrees, write 0.523599 (angles are in radians)",
                   "scene.yml:20:26: warning: rotate-y angle -30 is more than 2 pi radians (a full turn); if it is in "
                   "degrees, write -0.523599 (angles are in radians)"}));
}

// A define is read again at each use (and recomposed after every new
// define): its warning is given once, where the angle is written.
TEST(SceneWarnings, ADefineWarnsOnceWhereItIsWritten) {
  EXPECT_EQ(warnings_of(kCamera + "- define: stand-up\n"                             // 11
                                  "  value:\n"                                       // 12
                                  "    - [rotate-x, -90]\n"                          // 13
                                  "- add: sphere\n"                                  // 14
                                  "  transform: [stand-up]\n"                        // 15
                                  "- define: other\n"                                // 16
                                  "  value: [[scale, 1, 2, 1]]\n"                    // 17
                                  "- add: cube\n"                                    // 18
                                  "  transform: [stand-up, [translate, 1, 0, 0]]\n"  // 19
                                  "- define: lifted\n"                               // 20
                                  "  extend: stand-up\n"                             // 21
                                  "  value: [[translate, 0, 1, 0]]\n"                // 22
                                  "- add: sphere\n"                                  // 23
                                  "  transform: [lifted, stand-up]\n"),              // 24
            Lines{kDegrees});
  EXPECT_EQ(warnings_of(kCamera + "- define: tilted\n"               // 11
                                  "  value:\n"                       // 12
                                  "    add: sphere\n"                // 13
                                  "    transform:\n"                 // 14
                                  "      - [rotate-z, 45]\n"         // 15
                                  "- add: tilted\n"                  // 16
                                  "- add: tilted\n"                  // 17
                                  "- add: group\n"                   // 18
                                  "  children: [{add: tilted}]\n"),  // 19
            Lines{"scene.yml:15:20: warning: rotate-z angle 45 is more than 2 pi radians (a full turn); if it is in "
                  "degrees, write 0.785398 (angles are in radians)"});
}

// Documents loaded whole (a flow list; an alias) warn once, with the
// positions of the file.
TEST(SceneWarnings, DocumentsLoadedWholeWarnOnce) {
  EXPECT_EQ(warnings_of("[{add: camera, width: 8, height: 6, field-of-view: 0.8, from: [0, 2, -5], to: [0, 0, 0], "
                        "up: [0, 1, 0]},\n"
                        " {add: sphere, transform: [[rotate-x, 90]]}]\n"),
            Lines{"scene.yml:2:39: warning: rotate-x angle 90 is more than 2 pi radians (a full turn); if it is in "
                  "degrees, write 1.5708 (angles are in radians)"});
  EXPECT_EQ(warnings_of(kCamera + "- add: torus\n"           // 11
                                  "  transform:\n"           // 12
                                  "    - [rotate-x, -90]\n"  // 13
                                  "  material: &red\n"       // 14
                                  "    color: [1, 0, 0]\n"   // 15
                                  "- add: cube\n"            // 16
                                  "  material: *red\n"),     // 17
            Lines{kDegrees});
}

TEST(SceneWarnings, WarningsComeBeforeTheErrorThatStopsTheLoad) {
  const std::string text = kCamera +
                           "- add: torus\n"           // 11
                           "  transform:\n"           // 12
                           "    - [rotate-x, -90]\n"  // 13
                           "- add: spher\n";          // 14
  for (const bool whole : {false, true}) {
    const Loaded l = load(text, whole);
    EXPECT_EQ(l.warnings, Lines{kDegrees}) << whole;
    EXPECT_EQ(l.error, "scene.yml:14:8: unknown shape 'spher' (did you mean 'sphere'?)") << whole;
  }
}

// Without on_warning, each warning is a line on std::cerr (so that the
// command line shows them with nothing to set up).
TEST(SceneWarnings, WithoutASinkWarningsGoToStandardError) {
  std::ostringstream captured;
  std::streambuf* const old = std::cerr.rdbuf(captured.rdbuf());
  try {
    load_scene_from_string(kCamera +
                               "- add: torus\n"
                               "  transform:\n"
                               "    - [rotate-x, -90]\n"
                               "- add: sphere\n"
                               "  transform: [[rotate-y, 360]]\n",
                           "scene.yml", ".");
  } catch (...) {
    std::cerr.rdbuf(old);
    throw;
  }
  std::cerr.rdbuf(old);
  EXPECT_EQ(captured.str(), kDegrees +
                                "\n"
                                "scene.yml:15:26: warning: rotate-y angle 360 is more than 2 pi radians (a full turn); "
                                "if it is in degrees, write 6.28319 (angles are in radians)\n");
}

TEST(SceneWarnings, AFieldOfViewInDegreesIsAnErrorThatSaysSo) {
  const auto camera = [](const std::string& fov) {
    return "- add: camera\n  width: 8\n  height: 6\n  field-of-view: " + fov +
           "\n  from: [0, 2, -5]\n  to: [0, 0, 0]\n  up: [0, 1, 0]\n";
  };
  for (const bool whole : {false, true}) {
    EXPECT_EQ(load(camera("60"), whole).error,
              "scene.yml:4:18: field-of-view must be between 0 and pi radians, got 60; if it is in degrees, write "
              "1.0472");
    EXPECT_EQ(load(camera("3.5"), whole).error,
              "scene.yml:4:18: field-of-view must be between 0 and pi radians, got 3.5; if it is in degrees, write "
              "0.0610865");
    // Not an angle in degrees either way: no hint.
    EXPECT_EQ(load(camera("180"), whole).error,
              "scene.yml:4:18: field-of-view must be between 0 and pi radians, got 180");
    EXPECT_EQ(load(camera("0"), whole).error, "scene.yml:4:18: field-of-view must be between 0 and pi radians, got 0");
    EXPECT_EQ(load(camera("-45"), whole).error,
              "scene.yml:4:18: field-of-view must be between 0 and pi radians, got -45");
    EXPECT_EQ(load(camera("3.14159"), whole).error, "");
  }
}

// The scenes of the repository and the RTC reference scenes are in radians:
// none of them warns.
TEST(SceneWarnings, TheCommittedScenesGiveNoWarnings) {
  std::vector<fs::path> files;
  for (const char* dir : {"scenes", "scenes/rtc-chapters", "scenes/stress"})
    for (const auto& e : fs::directory_iterator(fs::path(TOROID_SOURCE_DIR) / dir))
      if (e.path().extension() == ".yaml") files.push_back(e.path());
  if (fs::exists(fs::path(TOROID_SHARED_DIR) / "rtc-scenes"))
    for (const auto& e : fs::directory_iterator(fs::path(TOROID_SHARED_DIR) / "rtc-scenes"))
      if (e.path().extension() == ".yml") files.push_back(e.path());
  ASSERT_GT(files.size(), 20u);
  std::size_t loaded = 0;
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    std::vector<std::string> warnings;
    SceneLoadOptions options;
    options.on_warning = [&](const std::string& w) { warnings.push_back(w); };
    try {
      load_scene(f.string(), options);
      ++loaded;
    } catch (const SceneError&) {
      // A reference scene that needs a texture this checkout lacks.
    }
    EXPECT_EQ(warnings, Lines{});
  }
  EXPECT_GT(loaded, 20u);
}

}  // namespace
}  // namespace toroid
