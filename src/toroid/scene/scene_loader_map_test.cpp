// SPDX-License-Identifier: Apache-2.0
// The scene loader's texture mapping: `pattern: {type: map, ...}` as the
// RTC scenes write it, the torus mapping, image files and their errors.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/approx.h"
#include "support/scene_text.h"
#include "support/temp_dir.h"
#include "toroid/io/image_writer.h"
#include "toroid/render/pattern.h"
#include "toroid/render/texture_map.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/shape.h"

namespace toroid {
namespace {

using testing::TempDir;

const std::string& kCamera = testing::kSceneCamera;  // 7 lines: the items below start on line 8

class MapPatterns : public ::testing::Test {
 protected:
  MapPatterns() : dir_(::testing::UnitTest::GetInstance()->current_test_info()->name()) {}

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(dir_.file(name), std::ios::binary) << text;
    return dir_.file(name);
  }
  Scene load(const std::string& items) const { return load_scene(write("scene.yml", kCamera + items)); }
  // The colour of object `i`'s pattern at an object-space point.
  static Color colour(const Scene& s, std::size_t i, const Tuple& p) {
    return s.world.objects.at(i)->material().pattern->pattern_at_object(p);
  }
  void expect_error(const std::string& items, const std::string& message) const {
    const std::string path = write("scene.yml", kCamera + items);
    try {
      load_scene(path);
      ADD_FAILURE() << "loaded; expected " << message;
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()), path + ":" + message);
    }
  }

  TempDir dir_;
};

const Color black{0, 0, 0}, white{1, 1, 1};

TEST_F(MapPatterns, EveryMappingAndUvPatternOfTheBooksScenes) {
  Canvas image(2, 1);
  image.write_pixel(0, 0, Color{1, 0, 0});
  image.write_pixel(1, 0, Color{0, 0, 1});
  write_image(image, dir_.file("two.ppm"));
  const Scene s = load(
      "- add: sphere\n"
      "  material:\n"
      "    pattern:\n"
      "      type: map\n"
      "      mapping: spherical\n"
      "      uv_pattern: {type: checkers, width: 16, height: 8, colors: [[0, 0, 0], [1, 1, 1]]}\n"
      "- add: plane\n"
      "  material:\n"
      "    pattern:\n"
      "      type: map\n"
      "      mapping: planar\n"
      "      uv_pattern:\n"
      "        type: align_check\n"
      "        colors: {main: [1, 1, 1], ul: [1, 0, 0], ur: [1, 1, 0], bl: [0, 1, 0], br: [0, 1, 1]}\n"
      "- add: cylinder\n"
      "  material:\n"
      "    pattern:\n"
      "      type: map\n"
      "      mapping: cylindrical\n"
      "      uv_pattern: {type: image, file: two.ppm}\n"
      "      transform: [[scale, 1, 2, 1]]\n"
      "- add: cube\n"
      "  material:\n"
      "    pattern:\n"
      "      type: map\n"
      "      mapping: cube\n"
      "      left: {type: checkers, width: 1, height: 1, colors: [[1, 0, 0], [1, 0, 0]]}\n"
      "      right: {type: checkers, width: 1, height: 1, colors: [[0, 1, 0], [0, 1, 0]]}\n"
      "      front: {type: image, file: two.ppm}\n"
      "      back: {type: checkers, width: 1, height: 1, colors: [[0, 0, 1], [0, 0, 1]]}\n"
      "      up: {type: checkers, width: 1, height: 1, colors: [[1, 1, 0], [1, 1, 0]]}\n"
      "      down: {type: checkers, width: 1, height: 1, colors: [[0, 1, 1], [0, 1, 1]]}\n");
  ASSERT_EQ(s.world.objects.size(), 4u);
  // The book's spherical-map scenario, two of its examples.
  EXPECT_APPROX(colour(s, 0, point(0.4315, 0.4670, 0.7719)), white);
  EXPECT_APPROX(colour(s, 0, point(-0.9654, 0.2552, -0.0534)), black);
  // Planar: the corners of each unit square.
  EXPECT_APPROX(colour(s, 1, point(0.1, 0, 0.9)), (Color{1, 0, 0}));
  EXPECT_APPROX(colour(s, 1, point(2.9, 0, 0.1)), (Color{0, 1, 1}));
  EXPECT_APPROX(colour(s, 1, point(0.5, 0, -0.5)), white);
  // Cylindrical through the pattern's transform: u < 0.5 is the red
  // column; v = (y / 2) mod 1 does not change it.
  EXPECT_APPROX(colour(s, 2, point(0.5, 0.9, -0.5)), (Color{1, 0, 0}));
  EXPECT_APPROX(colour(s, 2, point(-0.5, 1.9, 0.5)), (Color{0, 0, 1}));
  // Cube: a colour per face; the front's image left to right.
  EXPECT_APPROX(colour(s, 3, point(-1, 0.2, 0.3)), (Color{1, 0, 0}));
  EXPECT_APPROX(colour(s, 3, point(1, 0.2, 0.3)), (Color{0, 1, 0}));
  EXPECT_APPROX(colour(s, 3, point(0.2, 0.3, -1)), (Color{0, 0, 1}));
  EXPECT_APPROX(colour(s, 3, point(0.2, 1, 0.3)), (Color{1, 1, 0}));
  EXPECT_APPROX(colour(s, 3, point(0.2, -1, 0.3)), (Color{0, 1, 1}));
  EXPECT_APPROX(colour(s, 3, point(-0.9, 0, 1)), (Color{1, 0, 0}));
  EXPECT_APPROX(colour(s, 3, point(0.9, 0, 1)), (Color{0, 0, 1}));
}

// Eight patterns naming one image (as the book's skybox and mapped cubes
// do) share one canvas: the file is read once.
TEST_F(MapPatterns, AnImageNamedTwiceIsReadOnce) {
  write_image(Canvas(4, 2), dir_.file("shared.ppm"));
  const std::string sphere =
      "- add: sphere\n"
      "  material:\n"
      "    pattern: {type: map, mapping: spherical, uv_pattern: {type: image, file: shared.ppm}}\n";
  const Scene s = load(sphere + sphere +
                       "- add: sphere\n  material:\n    pattern: {type: map, mapping: spherical, "
                       "uv_pattern: {type: image, file: ./shared.ppm}}\n");
  auto canvas_of = [&](std::size_t i) {
    const auto& map = dynamic_cast<const TextureMapPattern&>(*s.world.objects.at(i)->material().pattern);
    return &dynamic_cast<const UvImage&>(map.uv_pattern()).canvas();
  };
  EXPECT_EQ(canvas_of(0), canvas_of(1));
  EXPECT_EQ(canvas_of(0), canvas_of(2));
  EXPECT_EQ(canvas_of(0)->width(), 4);
}

// 8 x 4 checkers on tori: either side of the top of the tube (v = 0.25)
// is a different row, wherever the tube's centre circle is.
const std::string kTorusCheckers =
    "    pattern:\n"
    "      type: map\n"
    "      mapping: torus\n"
    "      uv_pattern: {type: checkers, width: 8, height: 4, colors: [[0, 0, 0], [1, 1, 1]]}\n";

TEST_F(MapPatterns, TheTorusMappingTakesTheRadiiOfItsTorus) {
  const Scene s = load(
      "- define: iced\n"
      "  value:\n" +
      kTorusCheckers +
      "- add: torus\n"
      "  major: 2\n"
      "  minor: 0.5\n"
      "  material: iced\n"
      "- add: torus\n"
      "  material: iced\n"
      "- add: sphere\n"
      "  material:\n" +
      kTorusCheckers +
      "      major: 3\n"
      "      minor: 1\n");
  // R = 2: the top of the tube is over x = 2.
  EXPECT_APPROX(colour(s, 0, point(2.01, 0, 0.5)), black);
  EXPECT_APPROX(colour(s, 0, point(1.99, 0, 0.5)), white);
  // The same material on the default torus (R = 1, r = 0.25).
  EXPECT_APPROX(colour(s, 1, point(1.01, 0, 0.25)), black);
  EXPECT_APPROX(colour(s, 1, point(0.99, 0, 0.25)), white);
  // Radii given on the pattern: R = 3.
  EXPECT_APPROX(colour(s, 2, point(3.01, 0, 1)), black);
  EXPECT_APPROX(colour(s, 2, point(2.99, 0, 1)), white);
}

TEST_F(MapPatterns, Errors) {
  expect_error("- add: sphere\n  material:\n" + kTorusCheckers,
               "12:16: mapping 'torus' needs the radii of the torus: use it in the material of a torus, or give "
               "'major' and 'minor'");
  expect_error("- add: sphere\n  material:\n    pattern: {type: map, mapping: spherial}\n",
               "10:35: unknown mapping 'spherial' (did you mean 'spherical'?) (use spherical, planar, cylindrical, "
               "cube or torus)");
  expect_error("- add: sphere\n  material:\n    pattern: {type: map, mapping: planar}\n",
               "10:14: a map pattern needs 'uv_pattern'");
  expect_error("- add: sphere\n  material:\n    pattern: {type: map, mapping: planar, uv_patern: {}}\n",
               "10:43: unknown key 'uv_patern' in a 'planar' map pattern (did you mean 'uv_pattern'?)");
  expect_error("- add: sphere\n  material:\n    pattern: {type: map, mapping: planar, major: 2}\n",
               "10:43: unknown key 'major' in a 'planar' map pattern");
  expect_error("- add: sphere\n  material:\n    pattern: {type: map, mapping: planar, uv_pattern: {type: checker}}\n",
               "10:62: unknown uv pattern type 'checker' (did you mean 'checkers'?) (use checkers, align_check or "
               "image)");
  expect_error(
      "- add: sphere\n  material:\n    pattern: {type: map, mapping: planar, uv_pattern: {type: checkers, "
      "width: 0, height: 2, colors: [[0, 0, 0], [1, 1, 1]]}}\n",
      "10:79: 'width' must be > 0, got 0");
  expect_error(
      "- add: plane\n  material:\n    pattern: {type: map, mapping: planar, uv_pattern: {type: align_check, "
      "colors: {main: [1, 1, 1], ul: [1, 0, 0], ur: [1, 1, 0], bl: [0, 1, 0]}}}\n",
      "10:83: align_check 'colors' needs 'br'");
  expect_error("- add: cube\n  material:\n    pattern: {type: map, mapping: cube, left: {type: image, file: a.ppm}}\n",
               "10:14: a cube map pattern needs 'right'");
  expect_error(
      "- add: cube\n  material:\n    pattern:\n      type: map\n      mapping: cube\n"
      "      left: {type: image, file: nope.ppm}\n      right: {type: image, file: nope.ppm}\n"
      "      front: {type: image, file: nope.ppm}\n      back: {type: image, file: nope.ppm}\n"
      "      up: {type: image, file: nope.ppm}\n      down: {type: image, file: nope.ppm}\n",
      "13:33: image file 'nope.ppm' not found (looked for '" + dir_.file("nope.ppm") + "')");
}

// Errors in an image come out at the scene's `file:` entry, followed by the
// image's own FILE:LINE: problem.
TEST_F(MapPatterns, ImageErrorsNameTheSceneEntryAndTheImageProblem) {
  write("bad.ppm", "P3\n2 1\n255\n0 0 0\n0 0 x\n");
  expect_error(
      "- add: sphere\n  material:\n    pattern:\n      type: map\n      mapping: spherical\n"
      "      uv_pattern: {type: image, file: bad.ppm}\n",
      "13:39: cannot load image 'bad.ppm': " + dir_.file("bad.ppm") +
          ":5: expected a whole number for the blue of pixel (1, 0), got 'x'");
  write("bad.png", std::string("\x89PNG\r\n\x1a\n", 8) + "not really");
  const std::string path = write("scene.yml", kCamera +
                                                  "- add: sphere\n  material:\n    pattern:\n      type: map\n"
                                                  "      mapping: spherical\n"
                                                  "      uv_pattern: {type: image, file: bad.png}\n");
  try {
    load_scene(path);
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    const std::string want = path + ":13:39: cannot load image 'bad.png': " + dir_.file("bad.png") + ": corrupt PNG: ";
    EXPECT_EQ(std::string(e.what()).rfind(want, 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace toroid
