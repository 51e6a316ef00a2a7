// SPDX-License-Identifier: Apache-2.0
// camera.feature
#include "toroid/render/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/render/world.h"

namespace toroid {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Camera, ConstructingACamera) {
  const int hsize = 160;
  const int vsize = 120;
  const double field_of_view = kPi / 2;
  const Camera c(hsize, vsize, field_of_view);
  EXPECT_EQ(c.hsize(), 160);
  EXPECT_EQ(c.vsize(), 120);
  EXPECT_APPROX(c.field_of_view(), kPi / 2);
  EXPECT_APPROX(c.transform(), Matrix4::identity());
}

TEST(Camera, ThePixelSizeForAHorizontalCanvas) {
  const Camera c(200, 125, kPi / 2);
  EXPECT_APPROX(c.pixel_size(), 0.01);
}

TEST(Camera, ThePixelSizeForAVerticalCanvas) {
  const Camera c(125, 200, kPi / 2);
  EXPECT_APPROX(c.pixel_size(), 0.01);
}

TEST(Camera, ConstructingARayThroughTheCenterOfTheCanvas) {
  const Camera c(201, 101, kPi / 2);
  const Ray r = c.ray_for_pixel(100, 50);
  EXPECT_APPROX(r.origin, point(0, 0, 0));
  EXPECT_APPROX(r.direction, vector(0, 0, -1));
}

TEST(Camera, ConstructingARayThroughACornerOfTheCanvas) {
  const Camera c(201, 101, kPi / 2);
  const Ray r = c.ray_for_pixel(0, 0);
  EXPECT_APPROX(r.origin, point(0, 0, 0));
  EXPECT_APPROX(r.direction, vector(0.66519, 0.33259, -0.66851));
}

TEST(Camera, ConstructingARayWhenTheCameraIsTransformed) {
  Camera c(201, 101, kPi / 2);
  c.set_transform(rotation_y(kPi / 4) * translation(0, -2, 5));
  const Ray r = c.ray_for_pixel(100, 50);
  EXPECT_APPROX(r.origin, point(0, 2, -5));
  EXPECT_APPROX(r.direction, vector(std::sqrt(2.0) / 2, 0, -std::sqrt(2.0) / 2));
}

TEST(Camera, RenderingAWorldWithACamera) {
  const World w = default_world();
  Camera c(11, 11, kPi / 2);
  const Tuple from = point(0, 0, -5);
  const Tuple to = point(0, 0, 0);
  const Tuple up = vector(0, 1, 0);
  c.set_transform(view_transform(from, to, up));
  const Canvas image = render(c, w);
  EXPECT_APPROX(image.pixel_at(5, 5), (Color{0.38066, 0.47583, 0.2855}));
}

// Beyond the book.

TEST(CameraSubPixel, SubPixelOffsetsMoveTheRayWithinThePixel) {
  const Camera c(201, 101, kPi / 2);
  // The centre offsets give the book's ray; the pixel's top-left corner is
  // the bottom-right corner of the pixel before it, diagonally.
  EXPECT_APPROX(c.ray_for_pixel(100, 50, 0.5, 0.5).direction, c.ray_for_pixel(100, 50).direction);
  EXPECT_APPROX(c.ray_for_pixel(100, 50, 0.0, 0.0).direction, c.ray_for_pixel(99, 49, 1.0, 1.0).direction);
  // Canvas x grows to the camera's right (-x in its space), y downwards.
  const Ray left = c.ray_for_pixel(100, 50, 0.0, 0.5);
  const Ray right = c.ray_for_pixel(100, 50, 0.99, 0.5);
  EXPECT_GT(left.direction.x, right.direction.x);
  const Ray top = c.ray_for_pixel(100, 50, 0.5, 0.0);
  const Ray bottom = c.ray_for_pixel(100, 50, 0.5, 0.99);
  EXPECT_GT(top.direction.y, bottom.direction.y);
}

}  // namespace
}  // namespace toroid
