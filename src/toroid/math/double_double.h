// SPDX-License-Identifier: Apache-2.0
// Double-double arithmetic: a value as an unevaluated sum hi + lo of two
// doubles, about 106 bits. Built on the error-free transformations TwoSum
// (Knuth) and TwoProduct (one fused multiply-add). The torus solver uses it
// to move a ray's origin exactly and to decide the sign of near-tangent
// roots.
#pragma once

#include <cmath>

#include "toroid/math/device.h"

namespace toroid {

struct DoubleDouble {
  double hi, lo;
};

TOROID_HD inline DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}

// a + t * b, exactly up to ~2^-106 relative.
TOROID_HD inline DoubleDouble add_scaled(double a, double t, double b) {
  const double p = t * b;
  const double p_err = std::fma(t, b, -p);
  const DoubleDouble s = two_sum(a, p);
  const double lo = s.lo + p_err;
  const double hi = s.hi + lo;
  return {hi, lo - (hi - s.hi)};
}

TOROID_HD inline DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

TOROID_HD inline DoubleDouble dd_add(DoubleDouble a, DoubleDouble b) {
  const DoubleDouble s = two_sum(a.hi, b.hi);
  const double lo = s.lo + a.lo + b.lo;
  const double hi = s.hi + lo;
  return {hi, lo - (hi - s.hi)};
}

TOROID_HD inline DoubleDouble dd_mul(DoubleDouble a, DoubleDouble b) {
  DoubleDouble p = two_prod(a.hi, b.hi);
  p.lo += a.hi * b.lo + a.lo * b.hi;
  const double hi = p.hi + p.lo;
  return {hi, p.lo - (hi - p.hi)};
}

TOROID_HD inline DoubleDouble dd_sqrt(DoubleDouble a) {
  if (a.hi <= 0) return {0, 0};
  const double s = std::sqrt(a.hi);
  const DoubleDouble s2 = two_prod(s, s);
  const double corr = ((a.hi - s2.hi) - s2.lo + a.lo) / (2 * s);
  const double hi = s + corr;
  return {hi, corr - (hi - s)};
}

}  // namespace toroid
