// SPDX-License-Identifier: Apache-2.0
// Textbook Ferrari: normalise, depress, take the dominant (largest) real root
// of the resolvent cubic, split into two quadratics. No polishing: the
// method's own numerical weaknesses are left visible (docs/torus.md).
#include <algorithm>
#include <cmath>

#include "toroid/roots/polynomial.h"

namespace toroid {

TOROID_HD int solve_quartic_ferrari(double a, double b, double c, double d, double e, double roots[4]) {
  if (a == 0) return solve_cubic(b, c, d, e, roots);
  // Monic x^4 + B x^3 + C x^2 + D x + E, depressed by x = y - B/4 to
  // y^4 + p y^2 + q y + r.
  const double B = b / a, C = c / a, D = d / a, E = e / a;
  const double B4 = B / 4, B2 = B4 * B4;  // B/4 and B^2/16
  const double p = C - 6 * B2;
  const double q = D - 2 * B4 * C + 8 * B2 * B4;
  const double r = E - B4 * D + B2 * C - 3 * B2 * B2;

  // Completing the square: (y^2 + p/2 + m)^2 = 2m y^2 - q y + m^2 + p m + p^2/4 - r,
  // and the right side is a perfect square 2m (y - q/(4m))^2 when m solves the
  // resolvent m^3 + p m^2 + (p^2/4 - r) m - q^2/8 = 0.
  double ms[3];
  const int nm = solve_cubic(1, p, p * p / 4 - r, -q * q / 8, ms);
  const double m = ms[nm - 1];  // dominant root; > 0 whenever q != 0

  int n = 0;
  double y[4];
  if (m <= 0) {
    // Only when q == 0: the biquadratic y^4 + p y^2 + r = 0.
    double z[2];
    const int nz = solve_quadratic(1, p, r, z);
    for (int i = 0; i < nz; ++i) {
      if (z[i] < 0) continue;
      const double s = std::sqrt(z[i]);
      y[n++] = -s;
      y[n++] = s;
    }
  } else {
    // y^2 + p/2 + m = +-s (y - q/(4m)), s = sqrt(2m):
    //   y^2 - s y + (p/2 + m + q/(2s)) = 0  and  y^2 + s y + (p/2 + m - q/(2s)) = 0.
    const double s = std::sqrt(2 * m);
    const double h = p / 2 + m, k = q / (2 * s);
    n += solve_quadratic(1, -s, h + k, y + n);
    n += solve_quadratic(1, s, h - k, y + n);
  }
  for (int i = 0; i < n; ++i) roots[i] = y[i] - B4;
  std::sort(roots, roots + n);
  return n;
}

}  // namespace toroid
