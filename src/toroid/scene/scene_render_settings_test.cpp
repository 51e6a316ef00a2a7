// SPDX-License-Identifier: Apache-2.0
// The items and key for the path integrator: `add: environment`,
// `add: integrator` and the material's `emissive`; and every scene the
// project ships, and every public RTC scene, renders under the path
// integrator with finite, non-negative pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "support/scene_load.h"
#include "support/scene_text.h"
#include "support/shared_dir.h"
#include "support/temp_dir.h"
#include "textures/procedural.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/shape.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

// Lines 1-7 the camera, 8-10 the light.
const std::string kStage = testing::kSceneCamera + testing::kSceneLight;

Scene load(const std::string& text) { return load_scene_from_string(text, "s.yml", "."); }

void expect_error_both_ways(const std::string& text, const std::string& message) {
  EXPECT_EQ(testing::load_text(text, "s.yml", false).error, message) << "item by item";
  EXPECT_EQ(testing::load_text(text, "s.yml", true).error, message) << "whole document";
}

TEST(SceneRenderSettings, ByDefaultNoIntegratorAndABlackEnvironment) {
  const Scene s = load(kStage);
  EXPECT_FALSE(s.integrator);
  EXPECT_EQ(s.world.environment.color.r, 0);
  EXPECT_FALSE(s.world.environment.zenith);
}

TEST(SceneRenderSettings, TheEnvironmentItemSetsColourAndZenith) {
  const Scene s = load(kStage + "- add: environment\n  color: [0.1, 0.2, 0.3]\n  zenith: [0.4, 0.5, 0.6]\n");
  EXPECT_TRUE(approx_equal(s.world.environment.color, Color{0.1, 0.2, 0.3}));
  ASSERT_TRUE(s.world.environment.zenith);
  EXPECT_TRUE(approx_equal(*s.world.environment.zenith, Color{0.4, 0.5, 0.6}));
}

TEST(SceneRenderSettings, TheIntegratorItemChoosesWhittedOrPath) {
  EXPECT_EQ(load(kStage + "- add: integrator\n  type: path\n").integrator, Integrator::path);
  EXPECT_EQ(load(kStage + "- add: integrator\n  type: whitted\n").integrator, Integrator::whitted);
}

TEST(SceneRenderSettings, EmissiveIsAMaterialKey) {
  const Scene s = load(kStage + "- add: sphere\n  material:\n    emissive: [2, 1, 0]\n");
  EXPECT_TRUE(approx_equal(s.world.objects.at(0)->material().emissive, Color{2, 1, 0}));
  // Materials that differ in emission only are not shared.
  const Scene t =
      load(kStage +
           "- add: sphere\n  material:\n    emissive: [2, 1, 0]\n- add: sphere\n  material:\n    color: [1, 1, 1]\n");
  EXPECT_EQ(t.world.objects.at(1)->material().emissive.r, 0);
}

TEST(SceneRenderSettings, BadItemsSayWhereAndWhat) {
  expect_error_both_ways(kStage + "- add: integrator\n  type: pat\n",
                         "s.yml:12:9: unknown integrator type 'pat' (did you mean 'path'?) (use whitted or path)");
  expect_error_both_ways(kStage + "- add: integrator\n  type: path\n- add: integrator\n  type: path\n",
                         "s.yml:13:8: a second integrator (the first is at line 11)");
  expect_error_both_ways(
      kStage + "- add: environment\n  color: [1, 1, 1]\n- add: sphere\n- add: environment\n  color: [1, 1, 1]\n",
      "s.yml:14:8: a second environment (the first is at line 11)");
  expect_error_both_ways(kStage + "- add: environment\n  color: [1, -1, 1]\n",
                         "s.yml:12:10: color must not be negative");
  expect_error_both_ways(kStage + "- add: environment\n  colour: [1, 1, 1]\n",
                         "s.yml:12:3: unknown key 'colour' in an environment (did you mean 'color'?)");
  expect_error_both_ways(kStage + "- add: sphere\n  material:\n    emissive: [0, 0, -0.1]\n",
                         "s.yml:13:15: emissive must not be negative");
  expect_error_both_ways(kStage + "- define: integrator\n  value: {}\n",
                         "s.yml:11:11: cannot redefine the built-in 'integrator'");
}

bool finite_and_non_negative(const Canvas& image) {
  for (const Color& c : image.pixels())
    if (!(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0))
      return false;
  return true;
}

// The scene at `path`, rendered 40 pixels wide (its camera's aspect and
// view) with the path integrator at 2 samples per pixel.
Canvas render_path_small(const fs::path& path) {
  const Scene scene = load_scene(path.string());
  const int height = std::max(1, static_cast<int>(std::lround(40.0 * scene.camera.vsize() / scene.camera.hsize())));
  Camera camera(40, height, scene.camera.field_of_view());
  camera.set_transform(scene.camera.transform());
  RenderOptions options;
  options.integrator = Integrator::path;
  options.samples = 2;
  options.threads = 2;
  return render_image(camera, scene.world, options);
}

TEST(ScenesUnderThePathIntegrator, EveryShippedSceneRendersFinite) {
  int n = 0;
  const fs::path scenes = fs::path(TOROID_SOURCE_DIR) / "scenes";
  for (const fs::path& dir : {scenes, scenes / "rtc-chapters", scenes / "stress"})
    for (const auto& e : fs::directory_iterator(dir)) {
      if (e.path().extension() != ".yaml") continue;
      ++n;
      EXPECT_TRUE(finite_and_non_negative(render_path_small(e.path()))) << e.path();
    }
  EXPECT_GE(n, 23);
}

TEST(ScenesUnderThePathIntegrator, EveryPublicRtcSceneRendersFinite) {
  TOROID_REQUIRE_SHARED_DIR();
  int n = 0;
  for (const auto& e : fs::directory_iterator(fs::path(TOROID_SHARED_DIR) / "rtc-scenes")) {
    if (e.path().extension() != ".yml") continue;
    ++n;
    // earth.yml and skybox.yml name images the folder does not ship:
    // procedural stand-ins beside a copy (as tests/rtc_scenes_render_test.cpp).
    const testing::TempDir dir("path_rtc_" + e.path().filename().string());
    fs::copy_file(e.path(), dir.path() / e.path().filename());
    textures::write_scene_textures(dir.path(), 32);
    EXPECT_TRUE(finite_and_non_negative(render_path_small(dir.path() / e.path().filename()))) << e.path();
  }
  EXPECT_GE(n, 16);
}

}  // namespace
}  // namespace toroid
