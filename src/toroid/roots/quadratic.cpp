// SPDX-License-Identifier: Apache-2.0
// Real roots of a x^2 + b x + c = 0 without catastrophic cancellation.
#include <cmath>
#include <utility>

#include "toroid/roots/polynomial.h"

namespace toroid {

namespace {

// b^2 - 4ac with the rounding errors of both products recovered by fma
// (Kahan's trick), so a discriminant that is tiny next to b^2 keeps its sign.
TOROID_HD double discriminant(double a, double b, double c) {
  const double p = b * b;
  const double q = 4 * a * c;  // 4a is exact
  const double dp = std::fma(b, b, -p);
  const double dq = std::fma(4 * a, c, -q);
  return (p - q) + (dp - dq);
}

}  // namespace

TOROID_HD int solve_quadratic(double a, double b, double c, double roots[2]) {
  if (a == 0) {
    if (b == 0) return 0;  // constant: no roots (or every x when c == 0)
    roots[0] = -c / b;
    return 1;
  }
  const double disc = discriminant(a, b, c);
  if (disc < 0) return 0;
  if (disc == 0) {  // double root, reported twice
    roots[0] = roots[1] = -b / (2 * a);
    return 2;
  }
  // q has the sign of -b, so b and sqrt(disc) never cancel; q != 0 since disc > 0.
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  double r0 = q / a;
  double r1 = c / q;
  if (r0 > r1) std::swap(r0, r1);
  roots[0] = r0;
  roots[1] = r1;
  return 2;
}

}  // namespace toroid
