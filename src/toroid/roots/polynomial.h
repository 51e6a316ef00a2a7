// SPDX-License-Identifier: Apache-2.0
// Real roots of polynomials up to degree four. Every solver writes the real
// roots it finds in ascending order and returns their count.
#pragma once

#include "toroid/math/device.h"

namespace toroid {

// a x^2 + b x + c = 0 (a may be 0).
TOROID_HD int solve_quadratic(double a, double b, double c, double roots[2]);
// a x^3 + b x^2 + c x + d = 0 (a != 0).
TOROID_HD int solve_cubic(double a, double b, double c, double d, double roots[3]);
// a x^4 + b x^3 + c x^2 + d x + e = 0 (a != 0), Ferrari's method.
TOROID_HD int solve_quartic_ferrari(double a, double b, double c, double d, double e, double roots[4]);
// a x^4 + b x^3 + c x^2 + d x + e = 0 (a != 0), the seed paper's closed form.
TOROID_HD int solve_quartic_tianheng(double a, double b, double c, double d, double e, double roots[4]);

}  // namespace toroid
