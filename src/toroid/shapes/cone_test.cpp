// SPDX-License-Identifier: Apache-2.0
// cones.feature
#include "toroid/shapes/cone.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/approx.h"

namespace toroid {
namespace {

TEST(Cones, IntersectingAConeWithARay) {
  struct Example {
    Tuple origin, direction;
    double t0, t1;
  };
  const Example examples[] = {
      {point(0, 0, -5), vector(0, 0, 1), 5, 5},
      {point(0, 0, -5), vector(1, 1, 1), 8.66025, 8.66025},
      {point(1, 1, -5), vector(-0.5, -1, 1), 4.55006, 49.44994},
  };
  const Cone shape;
  for (const Example& e : examples) {
    SCOPED_TRACE(::testing::Message() << e.origin << " " << e.direction);
    Intersections xs;
    shape.local_intersect({e.origin, normalize(e.direction)}, xs);
    ASSERT_EQ(xs.size(), 2u);
    EXPECT_NEAR(xs[0].t, e.t0, kEpsilon);
    EXPECT_NEAR(xs[1].t, e.t1, kEpsilon);
  }
}

TEST(Cones, IntersectingAConeWithARayParallelToOneOfItsHalves) {
  const Cone shape;
  Intersections xs;
  shape.local_intersect({point(0, 0, -1), normalize(vector(0, 1, 1))}, xs);
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_NEAR(xs[0].t, 0.35355, kEpsilon);
}

TEST(Cones, IntersectingAConesEndCaps) {
  struct Example {
    Tuple origin, direction;
    std::size_t count;
  };
  const Example examples[] = {
      {point(0, 0, -5), vector(0, 1, 0), 0},
      {point(0, 0, -0.25), vector(0, 1, 1), 2},
      {point(0, 0, -0.25), vector(0, 1, 0), 4},
  };
  Cone shape;
  shape.minimum = -0.5;
  shape.maximum = 0.5;
  shape.closed = true;
  for (const Example& e : examples) {
    SCOPED_TRACE(::testing::Message() << e.origin << " " << e.direction);
    Intersections xs;
    shape.local_intersect({e.origin, normalize(e.direction)}, xs);
    EXPECT_EQ(xs.size(), e.count);
  }
}

TEST(Cones, ComputingTheNormalVectorOnACone) {
  const std::pair<Tuple, Tuple> examples[] = {
      {point(0, 0, 0), vector(0, 0, 0)},
      {point(1, 1, 1), vector(1, -std::sqrt(2.0), 1)},
      {point(-1, -1, 0), vector(-1, 1, 0)},
  };
  const Cone shape;
  for (const auto& [p, normal] : examples) EXPECT_APPROX(shape.local_normal_at(p, {}), normal);
}

}  // namespace
}  // namespace toroid
