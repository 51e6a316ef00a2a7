// SPDX-License-Identifier: Apache-2.0
// Texture mapping bonus chapter: uv_checkers, uv_align_check, uv_image.
#include "toroid/render/uv_pattern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/approx.h"
#include "toroid/io/image_reader.h"

namespace toroid {
namespace {

const Color black{0, 0, 0};
const Color white{1, 1, 1};

TEST(UvPatterns, CheckerPatternIn2D) {
  const UvCheckers checkers(2, 2, black, white);
  EXPECT_APPROX(checkers.uv_pattern_at(0.0, 0.0), black);
  EXPECT_APPROX(checkers.uv_pattern_at(0.5, 0.0), white);
  EXPECT_APPROX(checkers.uv_pattern_at(0.0, 0.5), white);
  EXPECT_APPROX(checkers.uv_pattern_at(0.5, 0.5), black);
  EXPECT_APPROX(checkers.uv_pattern_at(1.0, 1.0), black);
}

TEST(UvPatterns, LayoutOfTheAlignCheckPattern) {
  const Color main{1, 1, 1}, ul{1, 0, 0}, ur{1, 1, 0}, bl{0, 1, 0}, br{0, 1, 1};
  const UvAlignCheck pattern(main, ul, ur, bl, br);
  EXPECT_APPROX(pattern.uv_pattern_at(0.5, 0.5), main);
  EXPECT_APPROX(pattern.uv_pattern_at(0.1, 0.9), ul);
  EXPECT_APPROX(pattern.uv_pattern_at(0.9, 0.9), ur);
  EXPECT_APPROX(pattern.uv_pattern_at(0.1, 0.1), bl);
  EXPECT_APPROX(pattern.uv_pattern_at(0.9, 0.1), br);
}

// The book names this scenario "Checker pattern in 2D" too: uv_image over
// a canvas read from a PPM.
TEST(UvPatterns, CheckerPatternIn2DFromAnImage) {
  const char* ppm =
      "P3\n"
      "10 10\n"
      "10\n"
      "0 0 0  1 1 1  2 2 2  3 3 3  4 4 4  5 5 5  6 6 6  7 7 7  8 8 8  9 9 9\n"
      "1 1 1  2 2 2  3 3 3  4 4 4  5 5 5  6 6 6  7 7 7  8 8 8  9 9 9  0 0 0\n"
      "2 2 2  3 3 3  4 4 4  5 5 5  6 6 6  7 7 7  8 8 8  9 9 9  0 0 0  1 1 1\n"
      "3 3 3  4 4 4  5 5 5  6 6 6  7 7 7  8 8 8  9 9 9  0 0 0  1 1 1  2 2 2\n"
      "4 4 4  5 5 5  6 6 6  7 7 7  8 8 8  9 9 9  0 0 0  1 1 1  2 2 2  3 3 3\n"
      "5 5 5  6 6 6  7 7 7  8 8 8  9 9 9  0 0 0  1 1 1  2 2 2  3 3 3  4 4 4\n"
      "6 6 6  7 7 7  8 8 8  9 9 9  0 0 0  1 1 1  2 2 2  3 3 3  4 4 4  5 5 5\n"
      "7 7 7  8 8 8  9 9 9  0 0 0  1 1 1  2 2 2  3 3 3  4 4 4  5 5 5  6 6 6\n"
      "8 8 8  9 9 9  0 0 0  1 1 1  2 2 2  3 3 3  4 4 4  5 5 5  6 6 6  7 7 7\n"
      "9 9 9  0 0 0  1 1 1  2 2 2  3 3 3  4 4 4  5 5 5  6 6 6  7 7 7  8 8 8\n";
  const UvImage pattern(std::make_shared<const Canvas>(canvas_from_ppm(ppm)));
  EXPECT_APPROX(pattern.uv_pattern_at(0, 0), (Color{0.9, 0.9, 0.9}));
  EXPECT_APPROX(pattern.uv_pattern_at(0.3, 0), (Color{0.2, 0.2, 0.2}));
  EXPECT_APPROX(pattern.uv_pattern_at(0.6, 0.3), (Color{0.1, 0.1, 0.1}));
  EXPECT_APPROX(pattern.uv_pattern_at(1, 1), (Color{0.9, 0.9, 0.9}));
}

// Beyond the book: a (u, v) a hair outside [0, 1], or NaN from a degenerate
// point, samples the nearest edge pixel instead of reading outside the image.
TEST(UvPatterns, AnImageClampsCoordinatesOutsideTheUnitSquare) {
  auto canvas = std::make_shared<Canvas>(2, 2);
  canvas->write_pixel(0, 0, Color{1, 0, 0});  // top left
  canvas->write_pixel(1, 0, Color{0, 1, 0});  // top right
  canvas->write_pixel(0, 1, Color{0, 0, 1});  // bottom left
  canvas->write_pixel(1, 1, Color{1, 1, 1});  // bottom right
  const UvImage pattern(canvas);
  EXPECT_APPROX(pattern.uv_pattern_at(-0.5, 2.0), (Color{1, 0, 0}));
  EXPECT_APPROX(pattern.uv_pattern_at(1.5, 1.5), (Color{0, 1, 0}));
  EXPECT_APPROX(pattern.uv_pattern_at(-1e-12, -3), (Color{0, 0, 1}));
  EXPECT_APPROX(pattern.uv_pattern_at(std::nan(""), std::nan("")), (Color{1, 0, 0}));
}

}  // namespace
}  // namespace toroid
