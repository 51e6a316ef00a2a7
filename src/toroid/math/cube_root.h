// SPDX-License-Identifier: Apache-2.0
// The real cube root from bit operations, +, * and / alone, for the torus
// solver's convexity cut. The C library's cbrt is not correctly rounded, and
// glibc's and CUDA's round differently, so a solver that called it would
// give the GPU other bits than the CPU; this one is the same sequence of
// correctly rounded operations on every compiler and device (built with
// -ffp-contract=off, or nvcc --fmad=false). Within 1 ulp of the exact cube
// root (cube_root_test.cpp checks it against MPFR).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

#include "toroid/math/device.h"

namespace toroid {

// The seed of cube_root for a positive normal a: the exponent and mantissa
// bits divided by 3 approximate log2(a)/3; the constant re-biases the
// exponent and centres the error of the mantissa's linear interpolation
// (under 3.2% either way).
constexpr std::uint64_t kCubeRootSeedBias = 0x2A9F7893782DA1CEull;

TOROID_HD inline double cube_root_seed(double a) {
  return std::bit_cast<double>(std::bit_cast<std::uint64_t>(a) / 3 + kCubeRootSeedBias);
}

// cube_root's iteration from the seed y, for a in [2^-900, 2^900]: over any
// type with +, * and /, so that the SIMD batch runs it on vectors with the
// scalar operations (a + a is 2a, and (y2 + y2) + y2 rounds as 3 y2 does).
// Halley's iteration y <- y (y^3 + 2a) / (2y^3 + a) cubes the relative
// error: 3.2e-2 -> 3e-5 -> 3e-14; one Newton step on the residual then
// leaves the rounding alone.
template <class T>
TOROID_HD inline T cube_root_refine(T a, T y) {
  for (int k = 0; k < 2; ++k) {
    const T y3 = y * y * y;
    y = y * ((y3 + (a + a)) / ((y3 + y3) + a));
  }
  const T y2 = y * y;
  return y + (a - y2 * y) / ((y2 + y2) + y2);
}

// The real cube root of x, within 1 ulp.
TOROID_HD inline double cube_root(double x) {
  if (x == 0 || !std::isfinite(x)) return x + x;  // +-0, +-inf, NaN
  double a = std::abs(x);
  // Magnitudes far from 1 are brought nearer by 2^+-900 (a cube, so the
  // root goes back by 2^-+300 exactly): the seed's bit trick needs a normal
  // exponent, and the iteration's 2a and y^3 must not overflow.
  double unscale = 1;
  if (a < 0x1p-900) a *= 0x1p900, unscale = 0x1p-300;
  if (a > 0x1p900) a *= 0x1p-900, unscale = 0x1p300;
  const double y = cube_root_refine(a, cube_root_seed(a));
  return std::copysign(y * unscale, x);
}

}  // namespace toroid
