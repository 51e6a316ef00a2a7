// SPDX-License-Identifier: Apache-2.0
// End to end: the book's default world through camera, renderer and PPM.
#include <gtest/gtest.h>

#include <numbers>
#include <sstream>
#include <string>

#include "support/approx.h"
#include "toroid/core/canvas.h"
#include "toroid/math/transform.h"
#include "toroid/render/camera.h"
#include "toroid/render/world.h"

namespace toroid {
namespace {

TEST(EndToEnd, TheDefaultWorldRendersToAPpmWithTheBooksCentrePixel) {
  const World w = default_world();
  Camera c(11, 11, std::numbers::pi / 2);
  c.set_transform(view_transform(point(0, 0, -5), point(0, 0, 0), vector(0, 1, 0)));
  const Canvas image = render(c, w);
  ASSERT_EQ(image.width(), 11);
  ASSERT_EQ(image.height(), 11);
  EXPECT_APPROX(image.pixel_at(5, 5), (Color{0.38066, 0.47583, 0.2855}));
  // The corners look past the spheres: black.
  EXPECT_APPROX(image.pixel_at(0, 0), (Color{0, 0, 0}));
  EXPECT_APPROX(image.pixel_at(10, 10), (Color{0, 0, 0}));

  // In the PPM the centre pixel is the 61st of 121: round(255 * c).
  std::istringstream ppm(canvas_to_ppm(image));
  std::string magic;
  int width = 0, height = 0, max = 0;
  ppm >> magic >> width >> height >> max;
  EXPECT_EQ(magic, "P3");
  EXPECT_EQ(width, 11);
  EXPECT_EQ(height, 11);
  EXPECT_EQ(max, 255);
  int r = -1, g = -1, b = -1;
  for (int i = 0; i <= 5 * 11 + 5; ++i) ppm >> r >> g >> b;
  ASSERT_TRUE(ppm);
  EXPECT_EQ(r, 97);   // 0.38066 * 255 = 97.07
  EXPECT_EQ(g, 121);  // 0.47583 * 255 = 121.34
  EXPECT_EQ(b, 73);   // 0.2855 * 255 = 72.80
}

}  // namespace
}  // namespace toroid
