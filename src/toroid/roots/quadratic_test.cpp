// SPDX-License-Identifier: Apache-2.0
// solve_quadratic against roots chosen exactly or refined with MPFR.
#include <gtest/gtest.h>

#include <cmath>

#include "support/mp_poly.h"
#include "toroid/roots/polynomial.h"

namespace toroid {
namespace {

using testing::poly_from_roots;
using testing::reference_roots;
using testing::RootsMatch;

// Two roots with exact coefficients come back to within a few ulps.
constexpr double kTol = 4e-16;

TEST(SolveQuadratic, TwoDistinctRootsAscending) {
  double r[2];
  ASSERT_EQ(solve_quadratic(1, -5, 6, r), 2);
  EXPECT_TRUE(RootsMatch(r, 2, {2, 3}, kTol));
  ASSERT_EQ(solve_quadratic(-2, 10, -12, r), 2);  // negative leading coefficient
  EXPECT_TRUE(RootsMatch(r, 2, {2, 3}, kTol));
}

TEST(SolveQuadratic, ExactDyadicRoots) {
  for (auto [r1, r2] : {std::pair{-3.25, 0.125}, {-1e3, 7.5}, {0.0, 2.0}, {-0.5, -0.5}}) {
    const auto p = poly_from_roots(1.5, {r1, r2});
    ASSERT_TRUE(p.exact);
    double r[2];
    const int n = solve_quadratic(p.c[0], p.c[1], p.c[2], r);
    EXPECT_TRUE(RootsMatch(r, n, reference_roots(p, {r1, r2}), kTol)) << r1 << ", " << r2;
  }
}

TEST(SolveQuadratic, NoCancellationForWidelySeparatedRoots) {
  // x^2 - (1e8 + 1e-8) x + 1 = 0 has roots 1e-8 and 1e8; the naive formula
  // loses the small one entirely.
  const auto p = poly_from_roots(1, {1e-8, 1e8});
  const auto want = reference_roots(p, {1e-8, 1e8});
  double r[2];
  ASSERT_EQ(solve_quadratic(p.c[0], p.c[1], p.c[2], r), 2);
  EXPECT_NEAR(r[0], want[0], 4e-16 * want[0]);
  EXPECT_NEAR(r[1], want[1], 4e-16 * want[1]);
}

TEST(SolveQuadratic, DoubleRootReportedTwice) {
  double r[2];
  ASSERT_EQ(solve_quadratic(4, -12, 9, r), 2);  // (2x - 3)^2
  EXPECT_EQ(r[0], 1.5);
  EXPECT_EQ(r[1], 1.5);
  ASSERT_EQ(solve_quadratic(1, 0, 0, r), 2);
  EXPECT_EQ(r[0], 0);
  EXPECT_EQ(r[1], 0);
}

TEST(SolveQuadratic, NoRealRoots) {
  double r[2];
  EXPECT_EQ(solve_quadratic(1, 0, 1, r), 0);
  EXPECT_EQ(solve_quadratic(1, -2, 5, r), 0);  // 1 +- 2i
}

TEST(SolveQuadratic, LinearAndConstant) {
  double r[2];
  ASSERT_EQ(solve_quadratic(0, 2, -3, r), 1);
  EXPECT_EQ(r[0], 1.5);
  EXPECT_EQ(solve_quadratic(0, 0, 1, r), 0);
  EXPECT_EQ(solve_quadratic(0, 0, 0, r), 0);
}

TEST(SolveQuadratic, RoundedCoefficientsAgainstMpfr) {
  // Irrational-looking roots: the coefficients are rounded, and the true roots
  // of the rounded polynomial come from MPFR Newton refinement.
  for (auto [r1, r2] : {std::pair{0.1, 0.7}, {-std::sqrt(2.0), std::acos(-1.0)}, {1.0 / 3, 1e5 / 7}}) {
    const auto p = poly_from_roots(1, {r1, r2});
    double r[2];
    const int n = solve_quadratic(p.c[0], p.c[1], p.c[2], r);
    EXPECT_TRUE(RootsMatch(r, n, reference_roots(p, {r1, r2}), 1e-15)) << r1 << ", " << r2;
  }
}

}  // namespace
}  // namespace toroid
