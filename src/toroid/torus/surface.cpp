// SPDX-License-Identifier: Apache-2.0
#include "toroid/torus/surface.h"

#include <cmath>
#include <numbers>

namespace toroid {

TOROID_HD void torus_normal(double R, double r, const double p[3], double n[3]) {
  const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  if (rho == 0) {
    // An apex of a horn or spindle torus: the surface is a cone there; take
    // the axis direction away from the centre (up at the horn's centre).
    n[0] = 0;
    n[1] = 0;
    n[2] = p[2] < 0 ? -1.0 : 1.0;
    return;
  }
  // On the spindle's inner part the nearest point of the centre circle is
  // the one across the axis: pick the factor the point satisfies best.
  const double k = on_torus_lemon(R, r, p) ? 1 + R / rho : 1 - R / rho;
  n[0] = k * p[0];
  n[1] = k * p[1];
  n[2] = p[2];
}

TOROID_HD bool on_torus_lemon(double R, double r, const double p[3]) {
  if (r <= R) return false;
  const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  const double a_out = rho - R, a_in = rho + R;
  const double h_out = std::abs((a_out - r) * (a_out + r) + p[2] * p[2]);
  const double h_in = std::abs((a_in - r) * (a_in + r) + p[2] * p[2]);
  return h_in < h_out;
}

TOROID_HD void torus_angles(double R, double r, const double p[3], double* theta, double* phi) {
  const double rho = std::sqrt(p[0] * p[0] + p[1] * p[1]);
  // Signed distance from the axis along the direction of the tube centre.
  const bool lemon = on_torus_lemon(R, r, p);
  const double rho_s = lemon ? -rho : rho;
  double th = std::atan2(p[1], p[0]);
  constexpr double kTwoPi = 2 * std::numbers::pi;
  if (lemon) th += std::numbers::pi;
  if (th < 0) th += kTwoPi;
  if (th >= kTwoPi) th -= kTwoPi;  // also catches -tiny + 2 pi rounding to 2 pi
  *theta = th;
  *phi = std::atan2(p[2], rho_s - R);
}

}  // namespace toroid
