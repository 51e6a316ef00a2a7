// SPDX-License-Identifier: Apache-2.0
// Root finding on a bracket where the function is monotone.
#pragma once

#include <cmath>

#include "toroid/math/device.h"

namespace toroid {

// Root of a monotone function on [lo, hi] whose values at the ends have
// opposite signs, from the first guess x0 (inside). Newton, guarded by
// bisection; `f` returns (value, derivative). Stops when a step is below `tol`,
// or leaves x unchanged (x is then an end of the bracket, and the root to
// x's resolution: bisecting would only lead back to it).
template <typename F>
TOROID_HD double solve_monotone(const F& f, double lo, double hi, bool lo_negative, double x0, double tol) {
  double x = x0;
  for (int it = 0; it < 100; ++it) {
    const auto [v, dv] = f(x);
    if (v == 0) return x;
    if ((v < 0) == lo_negative)
      lo = x;
    else
      hi = x;
    double next = x - v / dv;
    if (next == x) return x;
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);  // also catches NaN
    const double step = std::abs(next - x);
    x = next;
    if (step <= tol || hi - lo <= tol) break;
  }
  return x;
}

}  // namespace toroid
