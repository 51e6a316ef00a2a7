// SPDX-License-Identifier: Apache-2.0
// The seed paper's closed-form quartic solver (after Fan Shengjin and
// Shen Tianheng): its discriminant quantities and case table, exposed so that
// tests can check which branch a polynomial takes. The solver itself is
// solve_quartic_tianheng in quartic.h; docs/torus.md derives every formula.
#pragma once

#include "toroid/math/device.h"

namespace toroid {

// The quantities of a x^4 + b x^3 + c x^2 + d x + e. With y = 4 a x + b the
// quartic becomes (y^2 - D)^2 = 4 (2 E y + F), and v = (y_1 + y_j)^2 / 4
// (j = 2, 3, 4) are the roots of the resolvent v^3 - D v^2 + F v - E^2 = 0,
// whose Shengjin discriminants are A, B, C and Delta.
//   D = 3b^2 - 8ac
//   E = -b^3 + 4abc - 8a^2 d
//   F = 3b^4 + 16a^2 c^2 - 16ab^2 c + 16a^2 bd - 64a^3 e
//   A = D^2 - 3F,  B = DF - 9E^2,  C = F^2 - 3DE^2,  Delta = B^2 - 4AC
// Floating-point zero tests are relative: X counts as zero when
// |X| <= kTianhengTolerance * DBL_EPSILON * m_X, where m_X is the sum of the
// magnitudes of the terms that cancel in X's own formula (m_D = 3b^2 + 8|ac|,
// ..., m_A = D^2 + 3|F|, ..., m_Delta = B^2 + 4|AC|). The errors that A, B, C
// and Delta inherit from D, E, F are deliberately left out: the formulas of
// cases 5 and 6 are continuous across Delta = 0, and a wider test would snap
// merely close roots onto the double-root formulas (measured: errors of 3e-4
// on a cluster of three roots 0.01 apart, against 4e-8 with this test).
struct TianhengQuantities {
  double D, E, F, A, B, C, Delta;
  double mD, mE, mF, mA, mB, mC, mDelta;

  TOROID_HD bool D_zero() const;
  TOROID_HD bool E_zero() const;
  TOROID_HD bool F_zero() const;
  TOROID_HD bool A_zero() const;
  TOROID_HD bool B_zero() const;
  TOROID_HD bool C_zero() const;
  TOROID_HD bool Delta_zero() const;
};

// Multiplier of DBL_EPSILON * m_X in the zero tests (see above).
inline constexpr double kTianhengTolerance = 16;

TOROID_HD TianhengQuantities tianheng_quantities(double a, double b, double c, double d, double e);

// The paper's case table, in the order it is tested.
enum class TianhengCase {
  QuadrupleRoot = 1,   // 1. D = E = F = 0: x = -b/(4a) four times
  TripleRoot = 2,      // 2. A = B = C = 0 (DEF != 0): one simple, one triple root
  TwoDoubleRoots = 3,  // 3. E = F = 0, D != 0: two double roots, real iff D > 0
  OneDoubleRoot = 4,   // 4. Delta = 0, ABC != 0: a real double root and two more
  DeltaPositive = 5,   // 5. Delta > 0: two simple real roots and a complex pair
  DeltaNegative = 6,   // 6. Delta < 0: four simple real roots (D > 0, F > 0) or none
};

TOROID_HD TianhengCase classify_tianheng(double a, double b, double c, double d, double e);
TOROID_HD TianhengCase classify_tianheng(const TianhengQuantities& q);

}  // namespace toroid
