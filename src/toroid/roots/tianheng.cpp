// SPDX-License-Identifier: Apache-2.0
// The seed paper's closed form for the quartic, with its full case table.
// Every formula is written for y = 4 a x + b, in which the quartic reads
//   (y^2 - D)^2 = 4 (2 E y + F),
// and with s_j = (y_1 + y_j)/2 (j = 2, 3, 4) the roots are
//   y_1 = s_2 + s_3 + s_4, y_2 = s_2 - s_3 - s_4, y_3 = s_3 - s_2 - s_4, y_4 = s_4 - s_2 - s_3,
// where v_j = s_j^2 solve v^3 - D v^2 + F v - E^2 = 0 and s_2 s_3 s_4 = E.
// docs/torus.md has the derivation and the corrections to the paper.
#include "toroid/roots/tianheng.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "toroid/roots/polynomial.h"

namespace toroid {

namespace {

TOROID_HD bool is_zero(double x, double m) { return std::fabs(x) <= kTianhengTolerance * DBL_EPSILON * m; }

TOROID_HD double sgn(double x) { return x > 0 ? 1.0 : (x < 0 ? -1.0 : 0.0); }

TOROID_HD double sqrt0(double x) { return std::sqrt(std::max(x, 0.0)); }  // rounding may push a square below 0

}  // namespace

TOROID_HD bool TianhengQuantities::D_zero() const { return is_zero(D, mD); }
TOROID_HD bool TianhengQuantities::E_zero() const { return is_zero(E, mE); }
TOROID_HD bool TianhengQuantities::F_zero() const { return is_zero(F, mF); }
TOROID_HD bool TianhengQuantities::A_zero() const { return is_zero(A, mA); }
TOROID_HD bool TianhengQuantities::B_zero() const { return is_zero(B, mB); }
TOROID_HD bool TianhengQuantities::C_zero() const { return is_zero(C, mC); }
TOROID_HD bool TianhengQuantities::Delta_zero() const { return is_zero(Delta, mDelta); }

TOROID_HD TianhengQuantities tianheng_quantities(double a, double b, double c, double d, double e) {
  TianhengQuantities q{};
  const double aa = a * a, bb = b * b;
  q.D = 3 * bb - 8 * a * c;
  q.E = -bb * b + 4 * a * b * c - 8 * aa * d;
  q.F = 3 * bb * bb + 16 * aa * c * c - 16 * a * bb * c + 16 * aa * b * d - 64 * aa * a * e;
  q.A = q.D * q.D - 3 * q.F;
  q.B = q.D * q.F - 9 * q.E * q.E;
  q.C = q.F * q.F - 3 * q.D * q.E * q.E;
  q.Delta = q.B * q.B - 4 * q.A * q.C;

  // Zero-test scales: the sum of the magnitudes of the terms that cancel in
  // each quantity's own formula (see tianheng.h for why the errors inherited
  // from D, E, F are deliberately not added).
  const double fa = std::fabs(a), fb = std::fabs(b), fc = std::fabs(c), fd = std::fabs(d), fe = std::fabs(e);
  const double D = std::fabs(q.D), E2 = q.E * q.E, F = std::fabs(q.F);
  q.mD = 3 * bb + 8 * fa * fc;
  q.mE = bb * fb + 4 * fa * fb * fc + 8 * aa * fd;
  q.mF = 3 * bb * bb + 16 * aa * c * c + 16 * fa * bb * fc + 16 * aa * fb * fd + 64 * aa * fa * fe;
  q.mA = D * D + 3 * F;
  q.mB = D * F + 9 * E2;
  q.mC = F * F + 3 * D * E2;
  q.mDelta = q.B * q.B + 4 * std::fabs(q.A * q.C);
  return q;
}

TOROID_HD TianhengCase classify_tianheng(const TianhengQuantities& q) {
  const bool D0 = q.D_zero(), E0 = q.E_zero(), F0 = q.F_zero();
  if (D0 && E0 && F0) return TianhengCase::QuadrupleRoot;
  if (q.A_zero() && q.B_zero() && q.C_zero()) return TianhengCase::TripleRoot;
  if (E0 && F0) return TianhengCase::TwoDoubleRoots;
  if (q.Delta_zero() && !q.A_zero() && !q.B_zero() && !q.C_zero()) return TianhengCase::OneDoubleRoot;
  return q.Delta > 0 ? TianhengCase::DeltaPositive : TianhengCase::DeltaNegative;
}

TOROID_HD TianhengCase classify_tianheng(double a, double b, double c, double d, double e) {
  return classify_tianheng(tianheng_quantities(a, b, c, d, e));
}

TOROID_HD int solve_quartic_tianheng(double a, double b, double c, double d, double e, double roots[4]) {
  if (a == 0) return solve_cubic(b, c, d, e, roots);
  // D..F, A..C and Delta are homogeneous of degrees 2..12 in the coefficients,
  // so Delta overflows once they pass about 2^85. Scaling every coefficient by
  // the same power of two is exact and changes neither the roots nor any
  // rounding, so do it first (the only departure from the paper's recipe).
  const double big = std::max({std::fabs(a), std::fabs(b), std::fabs(c), std::fabs(d), std::fabs(e)});
  const int k = std::ilogb(big);
  a = std::scalbn(a, -k), b = std::scalbn(b, -k), c = std::scalbn(c, -k), d = std::scalbn(d, -k),
  e = std::scalbn(e, -k);
  const TianhengQuantities q = tianheng_quantities(a, b, c, d, e);
  const double D = q.D, E = q.E, F = q.F, A = q.A, B = q.B, Delta = q.Delta;
  double y[4];
  int n = 0;
  switch (classify_tianheng(q)) {
    case TianhengCase::QuadrupleRoot:  // y^4 = 0
      y[0] = y[1] = y[2] = y[3] = 0;
      n = 4;
      break;
    case TianhengCase::TripleRoot: {
      // The resolvent has the triple root v = D/3 = F/D = 3E^2/F, so
      // s_2 = s_3 = s_4 = 3E/D: y = 9E/D once and y = -3E/D three times.
      y[0] = 9 * E / D;
      y[1] = y[2] = y[3] = -3 * E / D;
      n = 4;
      break;
    }
    case TianhengCase::TwoDoubleRoots:  // (y^2 - D)^2 = 0
      if (D > 0) {
        const double s = std::sqrt(D);
        y[0] = y[1] = -s;
        y[2] = y[3] = s;
        n = 4;
      }
      break;
    case TianhengCase::OneDoubleRoot: {
      // Resolvent roots v_1 = D - B/A, v_2 = v_3 = B/(2A); s_2 = 2AE/B.
      // Double root y = -2AE/B (always real); y = 2AE/B +- sqrt(2B/A) when AB > 0.
      const double s = 2 * A * E / B;
      y[n++] = -s;
      y[n++] = -s;
      if (A * B > 0) {
        const double w = std::sqrt(2 * B / A);
        y[n++] = s - w;
        y[n++] = s + w;
      }
      break;
    }
    case TianhengCase::DeltaPositive: {
      // One real resolvent root v_1 = (D + S)/3, S = cbrt(z1) + cbrt(z2), and a
      // complex pair with |v_2| = sqrt(z)/3, Re v_2 = (2D - S)/6:
      //   y = sgn(E) sqrt(v_1) +- 2 Re sqrt(v_2) = sgn(E) sqrt((D + S)/3) +- sqrt((2D - S + 2 sqrt(z))/3).
      const double sd = std::sqrt(Delta);
      const double z1 = A * D + 3 * (-B + sd) / 2;
      const double z2 = A * D + 3 * (-B - sd) / 2;
      const double S = std::cbrt(z1) + std::cbrt(z2);
      const double z = D * D - D * S + S * S - 3 * A;
      const double u = sgn(E) * sqrt0((D + S) / 3);
      const double w = sqrt0((2 * D - S + 2 * sqrt0(z)) / 3);
      y[n++] = u - w;
      y[n++] = u + w;
      break;
    }
    case TianhengCase::DeltaNegative: {
      // Three real resolvent roots: all >= 0 (four real roots) iff D > 0 and F > 0;
      // otherwise two of them are negative and the roots are two complex pairs.
      if (!(D > 0 && F > 0)) break;
      if (q.E_zero()) {
        // Biquadratic: y^2 = D +- 2 sqrt(F), both >= 0 here.
        const double r = 2 * std::sqrt(F);
        const double hi = std::sqrt(D + r), lo = sqrt0(D - r);
        y[0] = -hi;
        y[1] = -lo;
        y[2] = lo;
        y[3] = hi;
        n = 4;
        break;
      }
      const double sA = sqrt0(A);
      const double cos_theta = A > 0 ? std::clamp((3 * B - 2 * A * D) / (2 * A * sA), -1.0, 1.0) : 1.0;
      const double t = std::acos(cos_theta) / 3;
      const double ct = std::cos(t), st = std::sqrt(3.0) * std::sin(t);
      const double s1 = sqrt0((D - 2 * sA * ct) / 3);
      const double s2 = sqrt0((D + sA * (ct + st)) / 3);
      const double s3 = sqrt0((D + sA * (ct - st)) / 3);
      const double g = sgn(E) * s1;
      y[0] = g + (s2 + s3);
      y[1] = g - (s2 + s3);
      y[2] = -g + (s2 - s3);
      y[3] = -g - (s2 - s3);
      n = 4;
      break;
    }
  }
  for (int i = 0; i < n; ++i) roots[i] = (y[i] - b) / (4 * a);
  std::sort(roots, roots + n);
  return n;
}

}  // namespace toroid
