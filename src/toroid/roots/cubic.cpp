// SPDX-License-Identifier: Apache-2.0
// Real roots of a x^3 + b x^2 + c x + d = 0: Cardano with cube roots when
// there is one real root, the trigonometric form when there are three, one
// guarded Newton step per root on the original polynomial.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numbers>

#include "toroid/roots/polynomial.h"

namespace toroid {

namespace {

// One Newton step on x^3 + B x^2 + C x + D, kept only when it lowers |f|.
TOROID_HD double polish(double x, double B, double C, double D) {
  const double f = ((x + B) * x + C) * x + D;
  const double df = (3 * x + 2 * B) * x + C;
  if (f == 0 || df == 0) return x;
  const double x1 = x - f / df;
  const double f1 = ((x1 + B) * x1 + C) * x1 + D;
  return std::isfinite(x1) && std::fabs(f1) < std::fabs(f) ? x1 : x;
}

}  // namespace

TOROID_HD int solve_cubic(double a, double b, double c, double d, double roots[3]) {
  if (a == 0) return solve_quadratic(b, c, d, roots);
  // Monic x^3 + B x^2 + C x + D, depressed by x = t - B/3 to t^3 + p t + q.
  const double B = b / a, C = c / a, D = d / a;
  const double B3 = B / 3;
  const double p = C - B * B3;
  const double q = (2 * B3 * B3 - C) * B3 + D;
  const double hq = q / 2, tp = p / 3;
  const double disc = hq * hq + tp * tp * tp;

  // disc == 0 (a multiple root) is tested against a first-order bound on the
  // rounding error of disc: p and q carry errors relative to the magnitudes
  // of the terms that cancel in them (mp, mq), which disc inherits through
  // d(disc) = hq dq + p^2/9 dp, plus its own rounding.
  const double mp = std::fabs(C) + std::fabs(B * B3);
  const double mq = std::fabs(B3) * (2 * B3 * B3 + std::fabs(C)) + std::fabs(D);
  const double mdisc = hq * hq + std::fabs(tp * tp * tp) + std::fabs(hq) * mq + tp * tp * mp;
  constexpr double kTol = 8 * DBL_EPSILON;

  int n = 0;
  if (std::fabs(disc) <= kTol * mdisc) {
    // Multiple root: t = 2u and the double root t = -u, u = cbrt(-q/2)
    // (u = 0 gives the triple root).
    const double u = std::cbrt(-hq);
    roots[0] = 2 * u - B3;
    roots[1] = roots[2] = -u - B3;
    n = 3;
  } else if (disc > 0) {
    // One real root t = u - p/(3u); u takes the sign that avoids cancellation.
    const double u = std::cbrt(-hq - std::copysign(std::sqrt(disc), hq));
    roots[0] = u - tp / u - B3;
    n = 1;
  } else {
    // Three real roots: t = 2 r cos(phi/3 - 2 pi k/3), r = sqrt(-p/3), cos(phi) = -q/(2 r^3).
    const double r = std::sqrt(-tp);
    const double cos_phi = std::clamp(-hq / (r * r * r), -1.0, 1.0);
    const double phi = std::acos(cos_phi);
    for (int k = 0; k < 3; ++k) roots[k] = 2 * r * std::cos((phi - 2 * std::numbers::pi * k) / 3) - B3;
    n = 3;
  }
  for (int i = 0; i < n; ++i) roots[i] = polish(roots[i], B, C, D);
  std::sort(roots, roots + n);
  return n;
}

}  // namespace toroid
