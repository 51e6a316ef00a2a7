// SPDX-License-Identifier: Apache-2.0
// solve_quartic_ferrari on the shared quartics (every Tianheng branch, so
// every kind of root multiplicity) and a random sweep, against the exact or
// MPFR reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/mp_poly.h"
#include "support/quartic_cases.h"
#include "toroid/roots/polynomial.h"

namespace toroid {
namespace {

using testing::QuarticCase;
using testing::RootsMatch;

// Simple roots of the hand-picked polynomials.
constexpr double kTolSimple = 1e-13;
// Multiple roots of exactly degenerate polynomials: the resolvent's dominant
// root is exact or nearly so, and the quadratics then split cleanly.
constexpr double kTolMultiple = 1e-12;
// Random sweep, roots >= 0.5 apart in [-8, 8], rounded coefficients.
constexpr double kTolSweep = 1e-10;

int solve(const QuarticCase& q, double r[4]) {
  const auto& c = q.p.c;
  return solve_quartic_ferrari(c[0], c[1], c[2], c[3], c[4], r);
}

TEST(Ferrari, SharedCases) {
  for (const QuarticCase& q : testing::branch_cases()) {
    double r[4];
    const int n = solve(q, r);
    EXPECT_TRUE(RootsMatch(r, n, q.want, q.multiple ? kTolMultiple : kTolSimple)) << q.name;
  }
}

TEST(Ferrari, BiquadraticWhenTheDepressedCubicTermVanishes) {
  double r[4];
  // 2(x-1)^4 - 2(x-1)^2 - 6: q = 0 and the resolvent m (m^2 - m + 13/4) has
  // no positive root, so the y^4 + p y^2 + r branch solves it.
  const auto p = std::vector<double>{2, -8, 10, -4, -6};
  ASSERT_EQ(solve_quartic_ferrari(p[0], p[1], p[2], p[3], p[4], r), 2);
  EXPECT_TRUE(RootsMatch(r, 2, {testing::refine_root(p, -0.5), testing::refine_root(p, 2.5)}, kTolSimple));
  // q = 0 with a positive resolvent root goes through the quadratics instead.
  ASSERT_EQ(solve_quartic_ferrari(1, 0, -5, 0, 4, r), 4);  // +-1, +-2
  EXPECT_TRUE(RootsMatch(r, 4, {-2, -1, 1, 2}, kTolSimple));
  EXPECT_EQ(solve_quartic_ferrari(1, 0, 1, 0, 1, r), 0);
}

TEST(Ferrari, NegativeLeadingCoefficientAndScale) {
  for (double s : {-1.0, std::ldexp(1.0, -30), -std::ldexp(1.0, 30)}) {
    const auto q = testing::from_roots("scaled", s, {-3, 0.5, 1, 6}, {}, TianhengCase::DeltaNegative);
    double r[4];
    EXPECT_TRUE(RootsMatch(r, solve(q, r), q.want, kTolSimple)) << s;
  }
}

TEST(Ferrari, RandomSweepAgainstMpfr) {
  double worst = 0;
  ASSERT_TRUE(testing::random_sweep(solve, kTolSweep, &worst));
  std::printf("ferrari random sweep: max relative error %.3g\n", worst);
  RecordProperty("max_rel_error", std::to_string(worst));
}

TEST(Ferrari, NearDoubleRoots) {
  // Roots 1 and 1 + 2^-k with exact coefficients.
  for (int k : {6, 10, 14, 20, 24}) {
    const double g = std::ldexp(1.0, -k);
    const auto q = testing::from_roots("near double", 1, {-2, 1, 1 + g, 3}, {}, TianhengCase::DeltaNegative);
    ASSERT_TRUE(q.p.exact);
    double r[4];
    ASSERT_EQ(solve(q, r), 4) << k;
    const double err = testing::max_rel_error(r, q.want);
    std::printf("ferrari: gap 2^-%d max relative error %.3g\n", k, err);
    EXPECT_LT(err, 1e-13 / g) << "gap 2^-" << k;
  }
}

TEST(Ferrari, SmallRootsBesideLargeOnesLoseRelativeAccuracy) {
  // A documented weakness of closed forms (both quartic solvers): every root is
  // formed as (y - b)/(4a), so a root much smaller than the largest one keeps
  // only an absolute accuracy of about eps times the largest root. For a ray
  // tracer this is the t ~ 0 hit of a ray leaving a surface.
  const auto q = testing::from_roots("wide", 1, {1e-6, 1, 1e3, 1e4}, {}, TianhengCase::DeltaNegative);
  double r[4];
  ASSERT_EQ(solve(q, r), 4);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r[i], q.want[i], 1e-11 * 1e4) << i;
  const double rel_small = std::fabs(r[0] - q.want[0]) / q.want[0];
  std::printf("ferrari: root 1e-6 next to 1e4: relative error %.3g\n", rel_small);
  EXPECT_GT(rel_small, 1e-6);  // the weakness is real: far from double accuracy
}

}  // namespace
}  // namespace toroid
