// SPDX-License-Identifier: Apache-2.0
// cylinders.feature
#include "toroid/shapes/cylinder.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/approx.h"

namespace toroid {
namespace {

struct CountExample {
  Tuple origin, direction;
  std::size_t count;
};

std::size_t count_hits(const Cylinder& cyl, const CountExample& e) {
  Intersections xs;
  cyl.local_intersect({e.origin, normalize(e.direction)}, xs);
  return xs.size();
}

TEST(Cylinders, ARayMissesACylinder) {
  const CountExample examples[] = {
      {point(1, 0, 0), vector(0, 1, 0), 0},
      {point(0, 0, 0), vector(0, 1, 0), 0},
      {point(0, 0, -5), vector(1, 1, 1), 0},
  };
  const Cylinder cyl;
  for (const CountExample& e : examples) {
    SCOPED_TRACE(::testing::Message() << e.origin << " " << e.direction);
    EXPECT_EQ(count_hits(cyl, e), 0u);
  }
}

TEST(Cylinders, ARayStrikesACylinder) {
  struct Example {
    Tuple origin, direction;
    double t0, t1;
  };
  const Example examples[] = {
      {point(1, 0, -5), vector(0, 0, 1), 5, 5},
      {point(0, 0, -5), vector(0, 0, 1), 4, 6},
      {point(0.5, 0, -5), vector(0.1, 1, 1), 6.80798, 7.08872},
  };
  const Cylinder cyl;
  for (const Example& e : examples) {
    SCOPED_TRACE(::testing::Message() << e.origin << " " << e.direction);
    Intersections xs;
    cyl.local_intersect({e.origin, normalize(e.direction)}, xs);
    ASSERT_EQ(xs.size(), 2u);
    EXPECT_NEAR(xs[0].t, e.t0, kEpsilon);
    EXPECT_NEAR(xs[1].t, e.t1, kEpsilon);
  }
}

TEST(Cylinders, NormalVectorOnACylinder) {
  const std::pair<Tuple, Tuple> examples[] = {
      {point(1, 0, 0), vector(1, 0, 0)},
      {point(0, 5, -1), vector(0, 0, -1)},
      {point(0, -2, 1), vector(0, 0, 1)},
      {point(-1, 1, 0), vector(-1, 0, 0)},
  };
  const Cylinder cyl;
  for (const auto& [p, normal] : examples) EXPECT_APPROX(cyl.local_normal_at(p, {}), normal);
}

TEST(Cylinders, TheDefaultMinimumAndMaximumForACylinder) {
  const Cylinder cyl;
  EXPECT_TRUE(std::isinf(cyl.minimum) && cyl.minimum < 0);
  EXPECT_TRUE(std::isinf(cyl.maximum) && cyl.maximum > 0);
}

TEST(Cylinders, IntersectingAConstrainedCylinder) {
  const CountExample examples[] = {
      {point(0, 1.5, 0), vector(0.1, 1, 0), 0}, {point(0, 3, -5), vector(0, 0, 1), 0},
      {point(0, 0, -5), vector(0, 0, 1), 0},    {point(0, 2, -5), vector(0, 0, 1), 0},
      {point(0, 1, -5), vector(0, 0, 1), 0},    {point(0, 1.5, -2), vector(0, 0, 1), 2},
  };
  Cylinder cyl;
  cyl.minimum = 1;
  cyl.maximum = 2;
  for (const CountExample& e : examples) {
    SCOPED_TRACE(::testing::Message() << e.origin << " " << e.direction);
    EXPECT_EQ(count_hits(cyl, e), e.count);
  }
}

TEST(Cylinders, TheDefaultClosedValueForACylinder) {
  const Cylinder cyl;
  EXPECT_FALSE(cyl.closed);
}

TEST(Cylinders, IntersectingTheCapsOfAClosedCylinder) {
  const CountExample examples[] = {
      {point(0, 3, 0), vector(0, -1, 0), 2},  {point(0, 3, -2), vector(0, -1, 2), 2},
      {point(0, 4, -2), vector(0, -1, 1), 2},                                          // corner case
      {point(0, 0, -2), vector(0, 1, 2), 2},  {point(0, -1, -2), vector(0, 1, 1), 2},  // corner case
  };
  Cylinder cyl;
  cyl.minimum = 1;
  cyl.maximum = 2;
  cyl.closed = true;
  for (const CountExample& e : examples) {
    SCOPED_TRACE(::testing::Message() << e.origin << " " << e.direction);
    EXPECT_EQ(count_hits(cyl, e), e.count);
  }
}

TEST(Cylinders, TheNormalVectorOnACylindersEndCaps) {
  const std::pair<Tuple, Tuple> examples[] = {
      {point(0, 1, 0), vector(0, -1, 0)}, {point(0.5, 1, 0), vector(0, -1, 0)}, {point(0, 1, 0.5), vector(0, -1, 0)},
      {point(0, 2, 0), vector(0, 1, 0)},  {point(0.5, 2, 0), vector(0, 1, 0)},  {point(0, 2, 0.5), vector(0, 1, 0)},
  };
  Cylinder cyl;
  cyl.minimum = 1;
  cyl.maximum = 2;
  cyl.closed = true;
  for (const auto& [p, normal] : examples) EXPECT_APPROX(cyl.local_normal_at(p, {}), normal);
}

}  // namespace
}  // namespace toroid
