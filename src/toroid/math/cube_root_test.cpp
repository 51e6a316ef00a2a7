// SPDX-License-Identifier: Apache-2.0
#include "toroid/math/cube_root.h"

#include <gtest/gtest.h>
#include <mpfr.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace toroid {
namespace {

// The cube root rounded to nearest, by MPFR.
double exact_cube_root(double x) {
  mpfr_t m;
  mpfr_init2(m, 53);
  mpfr_set_d(m, x, MPFR_RNDN);
  mpfr_cbrt(m, m, MPFR_RNDN);
  const double r = mpfr_get_d(m, MPFR_RNDN);
  mpfr_clear(m);
  return r;
}

std::int64_t ulps_apart(double a, double b) {
  const std::int64_t i = std::bit_cast<std::int64_t>(a), j = std::bit_cast<std::int64_t>(b);
  return i > j ? i - j : j - i;
}

TEST(CubeRoot, WithinOneUlpOverEveryExponent) {
  // Uniform bit patterns: every exponent, subnormals included, both signs.
  std::mt19937_64 rng(20261204);
  int checked = 0;
  for (int i = 0; i < 400000; ++i) {
    const double x = std::bit_cast<double>(rng());
    if (!std::isfinite(x)) continue;
    ++checked;
    const double expected = exact_cube_root(x), got = cube_root(x);
    ASSERT_EQ(std::signbit(got), std::signbit(x)) << std::hexfloat << x;
    ASSERT_LE(ulps_apart(got, expected), 1) << std::hexfloat << x << " -> " << got << ", exact " << expected;
  }
  EXPECT_GT(checked, 390000);
}

TEST(CubeRoot, ExactOnCubes) {
  for (double k = 1; k <= 2000; ++k) {
    EXPECT_EQ(cube_root(k * k * k), k);
    EXPECT_EQ(cube_root(-k * k * k), -k);
  }
  EXPECT_EQ(cube_root(0x1p-1074), 0x1p-358);  // 2^-1074 = (2^-358)^3
  EXPECT_EQ(cube_root(0x1p1023), 0x1p341);
}

TEST(CubeRoot, ZerosInfinitiesAndNaN) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(std::bit_cast<std::uint64_t>(cube_root(0.0)), std::bit_cast<std::uint64_t>(0.0));
  EXPECT_EQ(std::bit_cast<std::uint64_t>(cube_root(-0.0)), std::bit_cast<std::uint64_t>(-0.0));
  EXPECT_EQ(cube_root(inf), inf);
  EXPECT_EQ(cube_root(-inf), -inf);
  EXPECT_TRUE(std::isnan(cube_root(std::numeric_limits<double>::quiet_NaN())));
}

}  // namespace
}  // namespace toroid
