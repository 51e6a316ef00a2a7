// SPDX-License-Identifier: Apache-2.0
// solve_quartic_tianheng: every branch of the paper's case table is taken
// (classify_tianheng) and its roots match the exact or MPFR reference.
#include "toroid/roots/tianheng.h"

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

// Simple roots of the branch polynomials: a few hundred ulps at most.
constexpr double kTolSimple = 1e-13;
// Multiple roots of exactly degenerate polynomials (the branch formulas then
// see exact D, E, F and give the roots almost exactly).
constexpr double kTolMultiple = 1e-12;
// Random sweep, roots >= 0.5 apart in [-8, 8], rounded coefficients:
// measured max 1e-11 (a heavy tail: most roots are within 1e-14).
constexpr double kTolSweep = 1e-10;

int solve(const QuarticCase& q, double r[4]) {
  const auto& c = q.p.c;
  return solve_quartic_tianheng(c[0], c[1], c[2], c[3], c[4], r);
}

TianhengQuantities quantities(const QuarticCase& q) {
  const auto& c = q.p.c;
  return tianheng_quantities(c[0], c[1], c[2], c[3], c[4]);
}

// Runs every shared branch polynomial of one case: branch taken, roots right.
void check_branch(TianhengCase which) {
  int seen = 0;
  for (const QuarticCase& q : testing::branch_cases()) {
    if (q.tianheng_case != which) continue;
    ++seen;
    SCOPED_TRACE(q.name);
    EXPECT_EQ(classify_tianheng(quantities(q)), which);
    double r[4];
    const int n = solve(q, r);
    EXPECT_TRUE(RootsMatch(r, n, q.want, q.multiple ? kTolMultiple : kTolSimple));
  }
  EXPECT_GE(seen, 3);
}

TEST(Tianheng, Quantities) {
  // (x-1)(x-2)(x-3)(x-5) = x^4 - 11x^3 + 41x^2 - 61x + 30, by hand:
  const auto t = tianheng_quantities(1, -11, 41, -61, 30);
  EXPECT_EQ(t.D, 3 * 121 - 8 * 41);                                            // 35
  EXPECT_EQ(t.E, 1331 + 4 * -11 * 41 + 8 * 61);                                // 15
  EXPECT_EQ(t.F, 3 * 14641 + 16 * 1681 - 16 * 121 * 41 + 16 * 671 - 64 * 30);  // 259
  EXPECT_EQ(t.A, t.D * t.D - 3 * t.F);
  EXPECT_EQ(t.B, t.D * t.F - 9 * t.E * t.E);
  EXPECT_EQ(t.C, t.F * t.F - 3 * t.D * t.E * t.E);
  EXPECT_EQ(t.Delta, t.B * t.B - 4 * t.A * t.C);
  // The resolvent v^3 - D v^2 + F v - E^2 has the roots (y1 + yj)^2 / 4 with
  // y = 4x + b = 4x - 11: y = -7, -3, 1, 9, so v = 25, 9, 1.
  for (double v : {25.0, 9.0, 1.0}) EXPECT_EQ(((v - t.D) * v + t.F) * v - t.E * t.E, 0) << v;
}

TEST(Tianheng, Case1QuadrupleRoot) { check_branch(TianhengCase::QuadrupleRoot); }

TEST(Tianheng, Case2TripleRoot) {
  check_branch(TianhengCase::TripleRoot);
  // The branch formulas need D, E, F nonzero; for (x-1)^3 (x-5) they are.
  const auto t = tianheng_quantities(1, -8, 18, -16, 5);
  EXPECT_FALSE(t.D_zero() || t.E_zero() || t.F_zero());
  EXPECT_TRUE(t.A_zero() && t.B_zero() && t.C_zero());
}

TEST(Tianheng, Case3TwoDoubleRoots) {
  check_branch(TianhengCase::TwoDoubleRoots);
  double r[4];
  // (x^2 - 2x + 5)^2: D < 0, no real roots.
  const auto p = testing::poly_from_roots(1, {}, {{1, 2}, {1, 2}});
  EXPECT_LT(tianheng_quantities(p.c[0], p.c[1], p.c[2], p.c[3], p.c[4]).D, 0);
  EXPECT_EQ(solve_quartic_tianheng(p.c[0], p.c[1], p.c[2], p.c[3], p.c[4], r), 0);
}

TEST(Tianheng, Case4OneDoubleRoot) {
  check_branch(TianhengCase::OneDoubleRoot);
  // AB > 0 gives four real roots, AB < 0 only the double root.
  const auto four = tianheng_quantities(1, -8, 21, -22, 8);  // (x-1)^2 (x-2)(x-4)
  EXPECT_GT(four.A * four.B, 0);
  const auto two = tianheng_quantities(1, -2, 2, -2, 1);  // (x-1)^2 (x^2+1)
  EXPECT_LT(two.A * two.B, 0);
  EXPECT_EQ(classify_tianheng(two), TianhengCase::OneDoubleRoot);
}

TEST(Tianheng, Case5DeltaPositive) { check_branch(TianhengCase::DeltaPositive); }

TEST(Tianheng, Case6DeltaNegative) {
  check_branch(TianhengCase::DeltaNegative);
  // Each sub-branch: four real with E != 0, four real with E = 0, none.
  struct Sub {
    testing::Poly p;
    bool e_zero;
    int count;
  };
  using testing::poly_from_roots;
  for (const Sub& s : {Sub{poly_from_roots(1, {1, 2, 3, 5}), false, 4},
                       // E = 0: x = (-b +- sqrt(D +- 2 sqrt F)) / 4a
                       Sub{poly_from_roots(1, {-2, -1, 1, 2}), true, 4},
                       Sub{poly_from_roots(1, {}, {{0, 1}, {0, 2}}), true, 0},  // D < 0
                       Sub{{{1, 0, 1, 0, 1}, true}, true, 0},                   // F < 0: no real roots
                       Sub{poly_from_roots(1, {}, {{-1, 1}, {2, 1}}), true, 0},
                       Sub{poly_from_roots(-1, {}, {{-3, 0.5}, {2, 0.25}}), false, 0},
                       Sub{poly_from_roots(2, {}, {{-1, 2}, {0.5, 3}}), false, 0}}) {
    const auto& c = s.p.c;
    const auto t = tianheng_quantities(c[0], c[1], c[2], c[3], c[4]);
    ASSERT_EQ(classify_tianheng(t), TianhengCase::DeltaNegative);
    EXPECT_EQ(t.E_zero(), s.e_zero);
    EXPECT_EQ(s.count == 4, t.D > 0 && t.F > 0);
    double r[4];
    EXPECT_EQ(solve_quartic_tianheng(c[0], c[1], c[2], c[3], c[4], r), s.count);
  }
}

TEST(Tianheng, ZeroTestsAreRelative) {
  // The same polynomial scaled by 2^-40 and by 2^40 (exactly) takes the same branch.
  for (const QuarticCase& q : testing::branch_cases()) {
    const auto& c = q.p.c;
    for (double s : {std::ldexp(1.0, -40), std::ldexp(1.0, 40)}) {
      EXPECT_EQ(classify_tianheng(s * c[0], s * c[1], s * c[2], s * c[3], s * c[4]), q.tianheng_case) << q.name;
    }
  }
  // Roots symmetric about a centre that is not a dyadic number: the rounded
  // coefficients make E rounding noise instead of 0, and the zero test still
  // recognises it.
  int noisy = 0;
  for (double centre : {0.1, 0.2, 0.7, 1.3, 2.9, 5.1}) {
    const auto p = testing::poly_from_roots(1, {centre - 0.75, centre - 0.25, centre + 0.25, centre + 0.75});
    const auto t = tianheng_quantities(p.c[0], p.c[1], p.c[2], p.c[3], p.c[4]);
    noisy += t.E != 0;
    EXPECT_TRUE(t.E_zero()) << centre;
  }
  EXPECT_GT(noisy, 0);
}

TEST(Tianheng, HugeAndTinyCoefficientsAreScaledExactly) {
  // Delta is of degree 12 in the coefficients: without the power-of-two
  // normalisation it overflows for coefficients beyond about 2^85.
  for (const QuarticCase& q : testing::branch_cases()) {
    for (int k : {-300, -90, 90, 300}) {
      double c[5];
      for (int i = 0; i < 5; ++i) c[i] = std::ldexp(q.p.c[i], k);
      double r[4];
      const int n = solve_quartic_tianheng(c[0], c[1], c[2], c[3], c[4], r);
      EXPECT_TRUE(RootsMatch(r, n, q.want, q.multiple ? kTolMultiple : kTolSimple)) << q.name << " 2^" << k;
    }
  }
}

TEST(Tianheng, RandomSweepAgainstMpfr) {
  double worst = 0;
  ASSERT_TRUE(testing::random_sweep(solve, kTolSweep, &worst));
  std::printf("tianheng random sweep: max relative error %.3g\n", worst);
  RecordProperty("max_rel_error", std::to_string(worst));
}

TEST(Tianheng, NearDoubleRootsLoseDigits) {
  // Roots 1 and 1 + 2^-k with exact coefficients: accuracy falls off roughly
  // as eps / gap (a known weakness of the closed form, documented in
  // docs/torus.md); the pair still counts as two real roots.
  for (int k : {6, 10, 14, 20, 24}) {
    const double g = std::ldexp(1.0, -k);
    const auto q = testing::from_roots("near double", 1, {-2, 1, 1 + g, 3}, {}, TianhengCase::DeltaNegative);
    ASSERT_TRUE(q.p.exact);
    double r[4];
    const int n = solve(q, r);
    ASSERT_EQ(n, 4);
    const double err = testing::max_rel_error(r, q.want);
    std::printf("tianheng: gap 2^-%d max relative error %.3g\n", k, err);
    EXPECT_LT(err, 1e-13 / g) << "gap 2^-" << k;
  }
}

}  // namespace
}  // namespace toroid
