// SPDX-License-Identifier: Apache-2.0
// Every public RTC scene in TOROID_SHARED_DIR/rtc-scenes loads and renders
// (small). earth.yml and skybox.yml name images that the directory does not
// ship: each scene is copied into a temporary directory beside procedural
// stand-ins for them (tests/textures/procedural.h), as a user would supply
// their own.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <set>
#include <string>

#include "support/shared_dir.h"
#include "support/temp_dir.h"
#include "textures/procedural.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

const fs::path kScenes = fs::path(TOROID_SHARED_DIR) / "rtc-scenes";

const char* const kSharedScenes[] = {
    "align-check-plane.yml",
    "chap7-putting-it-together.yml",
    "checkered-cube.yml",
    "checkered-cylinder.yml",
    "checkered-plane.yml",
    "checkered-sphere.yml",
    "cover.yml",
    "csg_difference.kjeldahl.yml",
    "cylinders.yml",
    "earth.yml",
    "group.yml",
    "reflect-refract.yml",
    "shadow-glamour-shot.yml",
    "skybox.yml",
    "table.yml",
    "three-spheres.yml",
};

TEST(SharedScenes, TheListNamesEveryScene) {
  TOROID_REQUIRE_SHARED_DIR();
  std::set<std::string> found;
  for (const auto& e : fs::directory_iterator(kScenes))
    if (e.path().extension() == ".yml" || e.path().extension() == ".yaml") found.insert(e.path().filename().string());
  EXPECT_EQ(found, std::set<std::string>(std::begin(kSharedScenes), std::end(kSharedScenes)));
}

// The scene rendered `width` pixels wide (its camera's aspect and view).
Canvas render_small(const std::string& scene_name, int width) {
  const TempDir dir("rtc_scene_" + scene_name);
  fs::copy_file(kScenes / scene_name, dir.path() / scene_name);
  textures::write_scene_textures(dir.path(), 32);
  const Scene scene = load_scene(dir.file(scene_name));
  const int height =
      std::max(1, static_cast<int>(std::lround(width * double(scene.camera.vsize()) / scene.camera.hsize())));
  Camera camera(width, height, scene.camera.field_of_view());
  camera.set_transform(scene.camera.transform());
  RenderOptions options;
  options.threads = 1;
  return render_image(camera, scene.world, options);
}

int count_pixels(const Canvas& c, const std::function<bool(const Color&)>& pred) {
  return static_cast<int>(std::count_if(c.pixels().begin(), c.pixels().end(), pred));
}

class SharedScene : public ::testing::TestWithParam<const char*> {};

TEST_P(SharedScene, LoadsAndRenders) {
  TOROID_REQUIRE_SHARED_DIR();
  const Canvas image = render_small(GetParam(), 48);
  EXPECT_EQ(count_pixels(image, [](const Color& c) { return !std::isfinite(c.r + c.g + c.b); }), 0);
  // Something is in view: not one flat colour.
  auto luminance = [](const Color& c) { return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b; };
  const auto [lo, hi] =
      std::minmax_element(image.pixels().begin(), image.pixels().end(),
                          [&](const Color& a, const Color& b) { return luminance(a) < luminance(b); });
  EXPECT_GT(luminance(*hi) - luminance(*lo), 0.1);
}

std::string test_name(const ::testing::TestParamInfo<const char*>& info) {
  std::string n = fs::path(info.param).stem().string();
  std::replace_if(
      n.begin(), n.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); }, '_');
  return n;
}

INSTANTIATE_TEST_SUITE_P(RtcScenes, SharedScene, ::testing::ValuesIn(kSharedScenes), test_name);

// A colour is "mostly" a hue when its weak channels are well below its
// strong ones (shading scales all three alike).
bool mostly(const Color& c, bool r, bool g, bool b) {
  const double strong = std::min({r ? c.r : 1e9, g ? c.g : 1e9, b ? c.b : 1e9});
  const double weak = std::max({r ? -1.0 : c.r, g ? -1.0 : c.g, b ? -1.0 : c.b});
  return strong > 0.05 && weak < 0.3 * strong;
}

// The textures show: each of align_check's corner colours on the plane; both
// checker colours on the sphere; ocean and land on the planet; sky above and
// fields below the horizon in the skybox.
TEST(SharedScenes, TextureMappedScenesShowTheirTextures) {
  TOROID_REQUIRE_SHARED_DIR();
  const Canvas plane = render_small("align-check-plane.yml", 64);
  EXPECT_GT(count_pixels(plane, [](const Color& c) { return mostly(c, true, false, false); }), 0) << "red";
  EXPECT_GT(count_pixels(plane, [](const Color& c) { return mostly(c, true, true, false); }), 0) << "yellow";
  EXPECT_GT(count_pixels(plane, [](const Color& c) { return mostly(c, false, true, false); }), 0) << "green";
  EXPECT_GT(count_pixels(plane, [](const Color& c) { return mostly(c, false, true, true); }), 0) << "cyan";
  EXPECT_GT(count_pixels(plane, [](const Color& c) { return mostly(c, true, true, true) && c.r > 0.5; }), 0) << "white";

  const Canvas sphere = render_small("checkered-sphere.yml", 64);
  const int green = count_pixels(sphere, [](const Color& c) { return mostly(c, false, true, false); });
  const int white = count_pixels(sphere, [](const Color& c) { return c.r > 0.3 && std::abs(c.r - c.b) < 0.05; });
  EXPECT_GT(green, 100);
  EXPECT_GT(white, 100);

  const Canvas earth = render_small("earth.yml", 96);
  const int ocean = count_pixels(earth, [](const Color& c) { return c.b > 0.05 && c.b > 2 * c.r && c.b > 1.5 * c.g; });
  const int land = count_pixels(earth, [](const Color& c) { return c.g > 0.03 && c.g > 1.2 * c.b; });
  EXPECT_GT(ocean, 20);
  EXPECT_GT(land, 20);

  // The top row is blue sky but where the sun or a cloud is; the bottom
  // row is all fields.
  const Canvas sky = render_small("skybox.yml", 64);
  int blue = 0;
  for (int x = 0; x < sky.width(); ++x) {
    const Color top = sky.pixel_at(x, 0), bottom = sky.pixel_at(x, sky.height() - 1);
    blue += top.b > 1.1 * top.r;
    EXPECT_GT(bottom.g, 1.2 * bottom.b) << "fields at column " << x << ": " << bottom;
  }
  EXPECT_GT(blue, sky.width() / 2);
}

}  // namespace
}  // namespace toroid
