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

// a * b - p for p = a * b rounded, which is a double: one fused
// multiply-add where the target has one. Elsewhere (x86-64 below -mfma)
// std::fma is a call into the C library, and a call makes the caller save
// every floating-point register it holds; Dekker's split gives the same
// exact value with plain products, where they neither overflow nor lose bits
// below the smallest normal (else the call).
TOROID_HD inline double product_error(double a, double b, double p) {
#if defined(__FMA__) || defined(__CUDA_ARCH__) || defined(__aarch64__)
  return std::fma(a, b, -p);
#else
  if (!(std::abs(a) < 0x1p995 && std::abs(b) < 0x1p995 && std::abs(p) < 0x1p995 && std::abs(p) > 0x1p-900))
    return std::fma(a, b, -p);  // also a zero factor: p = 0
  constexpr double kSplit = 0x1p27 + 1;
  const double ca = kSplit * a, cb = kSplit * b;
  const double a_hi = ca - (ca - a), a_lo = a - a_hi;
  const double b_hi = cb - (cb - b), b_lo = b - b_hi;
  return ((a_hi * b_hi - p) + a_hi * b_lo + a_lo * b_hi) + a_lo * b_lo;
#endif
}

// a + t * b, exactly up to ~2^-106 relative.
TOROID_HD inline DoubleDouble add_scaled(double a, double t, double b) {
  const double p = t * b;
  const double p_err = product_error(t, b, p);
  const DoubleDouble s = two_sum(a, p);
  const double lo = s.lo + p_err;
  const double hi = s.hi + lo;
  return {hi, lo - (hi - s.hi)};
}

TOROID_HD inline DoubleDouble two_prod(double a, double b) {
  const double p = a * b;
  return {p, product_error(a, b, p)};
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
