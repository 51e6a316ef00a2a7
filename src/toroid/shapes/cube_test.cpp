// SPDX-License-Identifier: Apache-2.0
// cubes.feature
#include "toroid/shapes/cube.h"

#include <gtest/gtest.h>

#include "support/approx.h"

namespace toroid {
namespace {

TEST(Cubes, ARayIntersectsACube) {
  struct Example {
    const char* name;
    Tuple origin, direction;
    double t1, t2;
  };
  const Example examples[] = {
      {"+x", point(5, 0.5, 0), vector(-1, 0, 0), 4, 6},     {"-x", point(-5, 0.5, 0), vector(1, 0, 0), 4, 6},
      {"+y", point(0.5, 5, 0), vector(0, -1, 0), 4, 6},     {"-y", point(0.5, -5, 0), vector(0, 1, 0), 4, 6},
      {"+z", point(0.5, 0, 5), vector(0, 0, -1), 4, 6},     {"-z", point(0.5, 0, -5), vector(0, 0, 1), 4, 6},
      {"inside", point(0, 0.5, 0), vector(0, 0, 1), -1, 1},
  };
  const Cube c;
  for (const Example& e : examples) {
    SCOPED_TRACE(e.name);
    Intersections xs;
    c.local_intersect({e.origin, e.direction}, xs);
    ASSERT_EQ(xs.size(), 2u);
    EXPECT_NEAR(xs[0].t, e.t1, kEpsilon);
    EXPECT_NEAR(xs[1].t, e.t2, kEpsilon);
  }
}

TEST(Cubes, ARayMissesACube) {
  const Ray rays[] = {
      {point(-2, 0, 0), vector(0.2673, 0.5345, 0.8018)},
      {point(0, -2, 0), vector(0.8018, 0.2673, 0.5345)},
      {point(0, 0, -2), vector(0.5345, 0.8018, 0.2673)},
      {point(2, 0, 2), vector(0, 0, -1)},
      {point(0, 2, 2), vector(0, -1, 0)},
      {point(2, 2, 0), vector(-1, 0, 0)},
  };
  const Cube c;
  for (const Ray& r : rays) {
    SCOPED_TRACE(::testing::Message() << r.origin << " " << r.direction);
    Intersections xs;
    c.local_intersect(r, xs);
    EXPECT_EQ(xs.size(), 0u);
  }
}

TEST(Cubes, TheNormalOnTheSurfaceOfACube) {
  const std::pair<Tuple, Tuple> examples[] = {
      {point(1, 0.5, -0.8), vector(1, 0, 0)},  {point(-1, -0.2, 0.9), vector(-1, 0, 0)},
      {point(-0.4, 1, -0.1), vector(0, 1, 0)}, {point(0.3, -1, -0.7), vector(0, -1, 0)},
      {point(-0.6, 0.3, 1), vector(0, 0, 1)},  {point(0.4, 0.4, -1), vector(0, 0, -1)},
      {point(1, 1, 1), vector(1, 0, 0)},       {point(-1, -1, -1), vector(-1, 0, 0)},
  };
  const Cube c;
  for (const auto& [p, normal] : examples) EXPECT_APPROX(c.local_normal_at(p, {}), normal);
}

}  // namespace
}  // namespace toroid
