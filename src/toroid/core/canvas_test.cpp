// SPDX-License-Identifier: Apache-2.0
// canvas.feature
#include "toroid/core/canvas.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "support/approx.h"

namespace toroid {
namespace {

// Lines first..last (1-based, inclusive) of a text, each without its newline.
std::vector<std::string> lines(const std::string& text, int first, int last) {
  std::istringstream in(text);
  std::vector<std::string> result;
  std::string line;
  for (int n = 1; n <= last && std::getline(in, line); ++n)
    if (n >= first) result.push_back(line);
  return result;
}

TEST(Canvas, CreatingACanvas) {
  const Canvas c(10, 20);
  EXPECT_EQ(c.width(), 10);
  EXPECT_EQ(c.height(), 20);
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) EXPECT_APPROX(c.pixel_at(x, y), (Color{0, 0, 0}));
}

TEST(Canvas, WritingPixelsToACanvas) {
  Canvas c(10, 20);
  const Color red{1, 0, 0};
  c.write_pixel(2, 3, red);
  EXPECT_APPROX(c.pixel_at(2, 3), red);
}

TEST(Canvas, ConstructingThePpmHeader) {
  const Canvas c(5, 3);
  const std::string ppm = canvas_to_ppm(c);
  EXPECT_EQ(lines(ppm, 1, 3), (std::vector<std::string>{"P3", "5 3", "255"}));
}

TEST(Canvas, ConstructingThePpmPixelData) {
  Canvas c(5, 3);
  const Color c1{1.5, 0, 0};
  const Color c2{0, 0.5, 0};
  const Color c3{-0.5, 0, 1};
  c.write_pixel(0, 0, c1);
  c.write_pixel(2, 1, c2);
  c.write_pixel(4, 2, c3);
  const std::string ppm = canvas_to_ppm(c);
  EXPECT_EQ(lines(ppm, 4, 6), (std::vector<std::string>{
                                  "255 0 0 0 0 0 0 0 0 0 0 0 0 0 0",
                                  "0 0 0 0 0 0 0 128 0 0 0 0 0 0 0",
                                  "0 0 0 0 0 0 0 0 0 0 0 0 0 0 255",
                              }));
}

TEST(Canvas, SplittingLongLinesInPpmFiles) {
  Canvas c(10, 2);
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) c.write_pixel(x, y, Color{1, 0.8, 0.6});
  const std::string ppm = canvas_to_ppm(c);
  EXPECT_EQ(lines(ppm, 4, 7), (std::vector<std::string>{
                                  "255 204 153 255 204 153 255 204 153 255 204 153 255 204 153 255 204",
                                  "153 255 204 153 255 204 153 255 204 153 255 204 153",
                                  "255 204 153 255 204 153 255 204 153 255 204 153 255 204 153 255 204",
                                  "153 255 204 153 255 204 153 255 204 153 255 204 153",
                              }));
}

TEST(Canvas, PpmFilesAreTerminatedByANewlineCharacter) {
  const Canvas c(5, 3);
  const std::string ppm = canvas_to_ppm(c);
  ASSERT_FALSE(ppm.empty());
  EXPECT_EQ(ppm.back(), '\n');
}

}  // namespace
}  // namespace toroid
