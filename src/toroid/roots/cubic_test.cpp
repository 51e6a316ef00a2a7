// SPDX-License-Identifier: Apache-2.0
// solve_cubic against roots chosen exactly or refined with MPFR.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/mp_poly.h"
#include "toroid/roots/polynomial.h"

namespace toroid {
namespace {

using testing::ComplexPair;
using testing::poly_from_roots;
using testing::reference_roots;
using testing::RootsMatch;

// Simple, well-separated roots (after the Newton polish): a few ulps.
constexpr double kTolSimple = 1e-15;
// Multiple roots are ill-conditioned; exact coefficients still give them to
// about the cube root (triple) or square root (double) of the rounding error
// in the intermediate quantities; these inputs hit them far more closely.
constexpr double kTolMultiple = 1e-12;

int solve(const testing::Poly& p, double r[3]) { return solve_cubic(p.c[0], p.c[1], p.c[2], p.c[3], r); }

TEST(SolveCubic, ThreeDistinctRealRoots) {
  for (const std::vector<double>& roots :
       {std::vector<double>{1, 2, 3}, {-4.5, 0.25, 10}, {-100, -99.5, 64}, {0, 1, 2}, {-1, 0, 1}}) {
    const auto p = poly_from_roots(-2, roots);
    ASSERT_TRUE(p.exact);
    double r[3];
    EXPECT_TRUE(RootsMatch(r, solve(p, r), reference_roots(p, roots), kTolSimple));
  }
}

TEST(SolveCubic, OneRealRootAndAComplexPair) {
  for (auto [x, z] :
       {std::pair{1.0, ComplexPair{0, 1}}, {-3.5, {2, 0.5}}, {0.0, {-1, 4}}, {1e3, {1, 1}}, {1e-3, {10, 10}}}) {
    const auto p = poly_from_roots(0.5, {x}, {z});
    double r[3];
    EXPECT_TRUE(RootsMatch(r, solve(p, r), reference_roots(p, {x}), kTolSimple)) << x;
  }
}

TEST(SolveCubic, DoubleRootReportedTwice) {
  for (const std::vector<double>& roots : {std::vector<double>{1, 1, 2}, {-3, 0.5, 0.5}, {-2, -2, 6}}) {
    const auto p = poly_from_roots(1, roots);
    ASSERT_TRUE(p.exact);
    double r[3];
    EXPECT_TRUE(RootsMatch(r, solve(p, r), roots, kTolMultiple));
  }
}

TEST(SolveCubic, TripleRoot) {
  for (double x : {0.0, 1.0, -2.5, 7.0}) {
    const auto p = poly_from_roots(3, {x, x, x});
    ASSERT_TRUE(p.exact);
    double r[3];
    EXPECT_TRUE(RootsMatch(r, solve(p, r), {x, x, x}, kTolMultiple)) << x;
  }
}

TEST(SolveCubic, RoundedCoefficientsAgainstMpfr) {
  for (const std::vector<double>& roots :
       {std::vector<double>{0.1, 0.2, 0.3}, {-std::sqrt(2.0), std::exp(1.0), 1e3 / 3}, {1e-4 / 3, 1.0 / 7, 5.5}}) {
    const auto p = poly_from_roots(1, roots);
    double r[3];
    EXPECT_TRUE(RootsMatch(r, solve(p, r), reference_roots(p, roots), kTolSimple));
  }
  const auto p = poly_from_roots(1, {std::sqrt(3.0)}, {{0.3, 0.9}});
  double r[3];
  EXPECT_TRUE(RootsMatch(r, solve(p, r), reference_roots(p, {std::sqrt(3.0)}), kTolSimple));
}

TEST(SolveCubic, DegenerateLeadingCoefficientFallsBackToQuadratic) {
  double r[3];
  ASSERT_EQ(solve_cubic(0, 1, -3, 2, r), 2);
  EXPECT_TRUE(RootsMatch(r, 2, {1, 2}, kTolSimple));
}

}  // namespace
}  // namespace toroid
