// SPDX-License-Identifier: Apache-2.0
// rays.feature
#include "toroid/core/ray.h"

#include <gtest/gtest.h>

#include "support/approx.h"
#include "toroid/math/transform.h"

namespace toroid {
namespace {

TEST(Rays, CreatingAndQueryingARay) {
  const Tuple origin = point(1, 2, 3);
  const Tuple direction = vector(4, 5, 6);
  const Ray r{origin, direction};
  EXPECT_APPROX(r.origin, origin);
  EXPECT_APPROX(r.direction, direction);
}

TEST(Rays, ComputingAPointFromADistance) {
  const Ray r{point(2, 3, 4), vector(1, 0, 0)};
  EXPECT_APPROX(r.position(0), point(2, 3, 4));
  EXPECT_APPROX(r.position(1), point(3, 3, 4));
  EXPECT_APPROX(r.position(-1), point(1, 3, 4));
  EXPECT_APPROX(r.position(2.5), point(4.5, 3, 4));
}

TEST(Rays, TranslatingARay) {
  const Ray r{point(1, 2, 3), vector(0, 1, 0)};
  const Ray r2 = transform(r, translation(3, 4, 5));
  EXPECT_APPROX(r2.origin, point(4, 6, 8));
  EXPECT_APPROX(r2.direction, vector(0, 1, 0));
}

TEST(Rays, ScalingARay) {
  const Ray r{point(1, 2, 3), vector(0, 1, 0)};
  const Ray r2 = transform(r, scaling(2, 3, 4));
  EXPECT_APPROX(r2.origin, point(2, 6, 12));
  EXPECT_APPROX(r2.direction, vector(0, 3, 0));
}

}  // namespace
}  // namespace toroid
