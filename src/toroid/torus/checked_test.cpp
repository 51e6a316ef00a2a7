// SPDX-License-Identifier: Apache-2.0
// The checked calls (checked.h): invalid inputs get their
// documented answers, valid ones exactly intersect_torus's.
#include "toroid/torus/checked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(TorusChecked, InvalidRadiiGiveMinusOne) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double t[4], n[3];
  for (const double bad : {0.0, -0.0, -1.0, kNaN, kInf, -kInf}) {
    SCOPED_TRACE(bad);
    EXPECT_FALSE(torus_radii_valid(bad, 0.25));
    EXPECT_FALSE(torus_radii_valid(1, bad));
    EXPECT_EQ(intersect_torus_checked(bad, 0.25, o, d, t), -1);
    EXPECT_EQ(intersect_torus_checked(1, bad, o, d, t), -1);
    EXPECT_EQ(intersect_torus_nearest_checked(bad, 0.25, o, d, 0, kInf, t), -1);
    EXPECT_EQ(intersect_torus_nearest_checked(1, bad, o, d, 0, kInf, t), -1);
    torus_unit_normal(1, bad, o, n);
    EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
  }
  EXPECT_TRUE(torus_radii_valid(1e-300, 1e300));
}

TEST(TorusChecked, InvalidRaysHaveNoRoots) {
  const double good_o[3] = {-5, 0, 0}, good_d[3] = {1, 0, 0};
  for (int k = 0; k < 3; ++k)
    for (const double bad : {kNaN, kInf, -kInf}) {
      double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0}, t[4] = {7, 7, 7, 7};
      o[k] = bad;
      EXPECT_EQ(intersect_torus_checked(1, 0.25, o, good_d, t), 0);
      EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, good_d, -kInf, kInf, t), 0);
      d[k] = bad;
      EXPECT_EQ(intersect_torus_checked(1, 0.25, good_o, d, t), 0);
      EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, good_o, d, -kInf, kInf, t), 0);
      EXPECT_EQ(t[0], 7);  // untouched
    }
  const double zero[3] = {0, -0.0, 0};
  double t[4];
  EXPECT_EQ(intersect_torus_checked(1, 0.25, good_o, zero, t), 0);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, good_o, zero, -kInf, kInf, t), 0);
}

TEST(TorusChecked, NearestWithNaNBoundsFindsNothing) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double t = 7;
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, kNaN, kInf, &t), 0);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, 0, kNaN, &t), 0);
  EXPECT_EQ(t, 7);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, 4, kInf, &t), 1);
  EXPECT_EQ(t, 4.25);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, 6.25, kInf, &t), 0);
}

TEST(TorusChecked, UnitNormalIsTheNormalScaled) {
  const double p[3] = {1.25, 0, 0};
  double n[3];
  torus_unit_normal(1, 0.25, p, n);
  EXPECT_EQ(n[0], 1);
  EXPECT_EQ(n[1], 0);
  EXPECT_EQ(n[2], 0);
  // Where n / |n| neither overflows nor underflows, the same bits.
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 1000; ++i) {
    const double q[3] = {2 * u(gen), 2 * u(gen), u(gen)};
    double m[3], plain[3];
    torus_normal(1, 0.4, q, m);
    const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (int k = 0; k < 3; ++k) plain[k] = m[k] / len;
    torus_unit_normal(1, 0.4, q, n);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_bits(n[k], plain[k])) << i << " " << k;
  }
  // Far from unit scale the plain formula overflows or underflows; this
  // one still gives unit length.
  for (const double s : {1e-200, 1e200}) {
    const double q[3] = {s * 1.5, s * 0.5, s * 0.25};
    torus_unit_normal(s, s * 0.75, q, n);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-15) << s;
  }
  // The centre circle has no normal; nor has a non-finite point.
  const double centre[3] = {1, 0, 0}, far[3] = {kInf, 0, 0};
  torus_unit_normal(1, 0.25, centre, n);
  EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
  torus_unit_normal(1, 0.25, far, n);
  EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
}

}  // namespace
}  // namespace toroid
