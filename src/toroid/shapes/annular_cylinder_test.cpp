// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/annular_cylinder.h"

#include <gtest/gtest.h>

#include <limits>

namespace toroid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The washer around the torus R = 1, r = 0.25.
const AnnularCylinder kWasher{0.75, 1.25, 0.25};

TEST(AnnularCylinder, AcceptsARayThroughTheTube) {
  EXPECT_TRUE(kWasher.may_meet(point(-5, 0, 0), vector(1, 0, 0), 0, kInf));
  EXPECT_TRUE(kWasher.may_meet(point(1, 0, 5), vector(0, 0, -1), 0, kInf));
}

TEST(AnnularCylinder, RejectsARayDownTheHole) {
  EXPECT_FALSE(kWasher.may_meet(point(0, 0, 5), vector(0, 0, -1), -kInf, kInf));
  // Slanted, but within the hole all the way through the slab.
  EXPECT_FALSE(kWasher.may_meet(point(0.2, 0, 5), vector(-0.05, 0, -1), -kInf, kInf));
}

TEST(AnnularCylinder, RejectsRaysOutsideTheSlabOrTheOuterCylinder) {
  EXPECT_FALSE(kWasher.may_meet(point(-5, 0, 0.3), vector(1, 0, 0), -kInf, kInf));
  EXPECT_FALSE(kWasher.may_meet(point(-5, 1.3, 0), vector(1, 0, 0), -kInf, kInf));
  EXPECT_FALSE(kWasher.may_meet(point(1.3, 0, 5), vector(0, 0, -1), -kInf, kInf));
}

TEST(AnnularCylinder, HonoursTheInterval) {
  // The washer spans t in [3.75, 6.25] along this ray.
  EXPECT_FALSE(kWasher.may_meet(point(-5, 0, 0), vector(1, 0, 0), 0, 3.7));
  EXPECT_TRUE(kWasher.may_meet(point(-5, 0, 0), vector(1, 0, 0), 0, 3.8));
  EXPECT_FALSE(kWasher.may_meet(point(-5, 0, 0), vector(1, 0, 0), 6.3, kInf));
  // Behind the origin: only with negative t allowed.
  EXPECT_FALSE(kWasher.may_meet(point(5, 0, 0), vector(1, 0, 0), 0, kInf));
  EXPECT_TRUE(kWasher.may_meet(point(5, 0, 0), vector(1, 0, 0), -kInf, kInf));
}

TEST(AnnularCylinder, IsConservativeAtTheEdgesAndFarAway) {
  // Grazing the outer cylinder and the top of the slab exactly.
  EXPECT_TRUE(kWasher.may_meet(point(-5, 1.25, 0), vector(1, 0, 0), 0, kInf));
  EXPECT_TRUE(kWasher.may_meet(point(-5, 0, 0.25), vector(1, 0, 0), 0, kInf));
  // A distant origin (1e6 away), aimed at the tube.
  EXPECT_TRUE(kWasher.may_meet(point(-1e6, 1, 0), vector(1, 0, 0), 0, kInf));
  EXPECT_TRUE(kWasher.may_meet(point(1e6, 0, 1e6), vector(-1, 1.0 / 1e6, -1), 0, kInf));
}

TEST(AnnularCylinder, WithoutAHoleAcceptsTheAxis) {
  const AnnularCylinder spindle{-0.5, 1.5, 1};
  EXPECT_TRUE(spindle.may_meet(point(0, 0, 5), vector(0, 0, -1), 0, kInf));
}

}  // namespace
}  // namespace toroid
