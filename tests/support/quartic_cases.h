// SPDX-License-Identifier: Apache-2.0
// Quartics shared by the Ferrari and Tianheng tests: one or more for every
// branch of the Tianheng case table, and a seeded random sweep. Reference
// roots are chosen exactly (dyadic roots give exact double coefficients) or
// refined with MPFR (tests/support/mp_poly.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "support/mp_poly.h"
#include "toroid/roots/tianheng.h"

namespace toroid::testing {

struct QuarticCase {
  std::string name;
  Poly p;                      // a, b, c, d, e
  std::vector<double> want;    // real roots with multiplicity, ascending
  TianhengCase tianheng_case;  // the branch the paper's table assigns
  bool multiple = false;       // has a multiple root (ill-conditioned)
};

inline QuarticCase from_roots(std::string name, double lead, std::vector<double> real, std::vector<ComplexPair> pairs,
                              TianhengCase tc, bool multiple = false) {
  QuarticCase q{std::move(name), poly_from_roots(lead, real, pairs), {}, tc, multiple};
  q.want = reference_roots(q.p, real);
  return q;
}

// Coefficients given directly; real roots refined from the guesses.
inline QuarticCase from_coeffs(std::string name, std::vector<double> c, std::vector<double> guesses, TianhengCase tc) {
  QuarticCase q{std::move(name), Poly{std::move(c), false}, {}, tc, false};
  q.want = reference_roots(q.p, guesses);
  return q;
}

inline std::vector<QuarticCase> branch_cases() {
  using TC = TianhengCase;
  return {
      // 1. D = E = F = 0
      from_roots("quadruple 3", 2, {3, 3, 3, 3}, {}, TC::QuadrupleRoot, true),
      from_roots("quadruple -0.5", -1, {-0.5, -0.5, -0.5, -0.5}, {}, TC::QuadrupleRoot, true),
      from_roots("quadruple 0", 1, {0, 0, 0, 0}, {}, TC::QuadrupleRoot, true),
      // 2. A = B = C = 0, DEF != 0
      from_roots("triple 1 simple 5", 1, {1, 1, 1, 5}, {}, TC::TripleRoot, true),
      from_roots("triple 4 simple -2", 3, {-2, 4, 4, 4}, {}, TC::TripleRoot, true),
      from_roots("triple 0.5 simple -1.5", -0.25, {-1.5, 0.5, 0.5, 0.5}, {}, TC::TripleRoot, true),
      // 3. E = F = 0, D != 0
      from_roots("double 1 double 3", 1, {1, 1, 3, 3}, {}, TC::TwoDoubleRoots, true),
      from_roots("double -2 double 5", -0.5, {-2, -2, 5, 5}, {}, TC::TwoDoubleRoots, true),
      from_roots("double pair 1+-2i", 1, {}, {{1, 2}, {1, 2}}, TC::TwoDoubleRoots, true),
      // 4. Delta = 0, ABC != 0
      from_roots("double 1 simple 2 4", 1, {1, 1, 2, 4}, {}, TC::OneDoubleRoot, true),
      from_roots("double 0.5 simple -3 6", -2, {-3, 0.5, 0.5, 6}, {}, TC::OneDoubleRoot, true),
      from_roots("double 2 between -1 3", 1, {-1, 2, 2, 3}, {}, TC::OneDoubleRoot, true),
      from_roots("double 0 simple +-1 (E = 0)", 1, {-1, 0, 0, 1}, {}, TC::OneDoubleRoot, true),
      from_roots("double 1 pair +-i", 1, {1, 1}, {{0, 1}}, TC::OneDoubleRoot, true),
      from_roots("double -2 pair 3+-0.5i", 4, {-2, -2}, {{3, 0.5}}, TC::OneDoubleRoot, true),
      // 5. Delta > 0
      from_roots("1 2 pair +-i", 1, {1, 2}, {{0, 1}}, TC::DeltaPositive),
      from_roots("-1 3 pair 1+-i", -2, {-1, 3}, {{1, 1}}, TC::DeltaPositive),
      from_roots("-7 0.25 pair -2+-3i", 0.5, {-7, 0.25}, {{-2, 3}}, TC::DeltaPositive),
      from_coeffs("x^4 + x^2 - 6 (E = 0)", {1, 0, 1, 0, -6}, {-std::sqrt(2.0), std::sqrt(2.0)}, TC::DeltaPositive),
      // 6. Delta < 0
      from_roots("1 2 3 5", 1, {1, 2, 3, 5}, {}, TC::DeltaNegative),
      from_roots("-4 -1 0.5 8", 0.25, {-4, -1, 0.5, 8}, {}, TC::DeltaNegative),
      from_roots("+-1 +-2 (E = 0)", 1, {-2, -1, 1, 2}, {}, TC::DeltaNegative),
      from_roots("pairs -1+-i 2+-i", 1, {}, {{-1, 1}, {2, 1}}, TC::DeltaNegative),
      from_roots("pairs +-i +-2i (E = 0, D < 0)", 1, {}, {{0, 1}, {0, 2}}, TC::DeltaNegative),
      from_coeffs("x^4 + x^2 + 1 (E = 0, F < 0)", {1, 0, 1, 0, 1}, {}, TC::DeltaNegative),
      from_roots("pairs -3+-0.5i 2+-0.25i", -1, {}, {{-3, 0.5}, {2, 0.25}}, TC::DeltaNegative),
  };
}

// Random quartics with full-precision (rounded) coefficients: real roots in
// [-8, 8] at least `gap` apart, complex pairs with |im| in [0.5, 4]. kind
// 0: four real roots, 1: two real and a pair, 2: two pairs.
inline std::vector<QuarticCase> random_cases(int count, unsigned seed, double gap = 0.5) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(-8, 8), im(0.5, 4), lead(0.5, 4);
  std::vector<QuarticCase> out;
  while (static_cast<int>(out.size()) < count) {
    const int kind = static_cast<int>(out.size() % 3);
    const int nreal = 4 - 2 * kind;
    std::vector<double> real;
    while (static_cast<int>(real.size()) < nreal) {
      const double x = pos(rng);
      bool ok = true;
      for (double r : real) ok = ok && std::fabs(r - x) >= gap;
      if (ok) real.push_back(x);
    }
    std::vector<ComplexPair> pairs;
    for (int k = 0; k < kind; ++k) pairs.push_back({pos(rng), im(rng)});
    const double a = (rng() & 1 ? 1 : -1) * lead(rng);
    out.push_back(from_roots("random " + std::to_string(out.size()), a, real, pairs, TianhengCase::DeltaNegative));
  }
  return out;
}

// The random sweep both closed forms run: every case's roots must match the
// MPFR reference within `tol`; returns the largest relative error seen, or
// the first mismatch as a failure.
template <typename Solve>
::testing::AssertionResult random_sweep(Solve solve, double tol, double* worst) {
  *worst = 0;
  for (const QuarticCase& q : random_cases(600, 20190101)) {
    double r[4];
    const int n = solve(q, r);
    ::testing::AssertionResult match = RootsMatch(r, n, q.want, tol);
    if (!match) return match << " (" << q.name << ")";
    if (n) *worst = std::max(*worst, max_rel_error(r, q.want));
  }
  return ::testing::AssertionSuccess();
}

}  // namespace toroid::testing
