// SPDX-License-Identifier: Apache-2.0
// Ray–torus intersection: the one place where the torus is solved. The Torus
// shape, the `toroid intersect` command, the benchmarks and the accuracy
// harness all call these functions, and so can another renderer
// (target toroid::torus, which needs nothing but the standard library).
//
// The torus is in object space, ring in the xy-plane, axis z, centred at the
// origin: (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2. Any major > 0 and
// minor > 0 is allowed: minor >= major gives horn and spindle tori, whose
// whole quartic surface (the spindle's inner "lemon" included) is intersected.
// Tori and rays of any size are solved alike (they are scaled, exactly, by
// powers of two). Each root puts o + t d within a few ulps of
// |o| + |t d| + major + minor of the surface for minor / major from 2^-30
// (kTorusAspectLimit) to 2 (kTorusFattestSpindle), the range the accuracy
// families measure; the fuzzer checks the same bound on fatter spindles too.
// Thinner tubes are solved too, but a pair of roots across a tube thinner
// than about 1e-10 major can be taken for a near-tangent pair and returned as
// the point between them (the rounding of h is then above the near-tangent
// threshold).
#pragma once

#include "toroid/math/device.h"
#include "toroid/torus/solver.h"

namespace toroid {

// The range of minor / major over which the roots' accuracy holds: from
// 1 / kTorusAspectLimit to kTorusFattestSpindle (the spindles it is tested on).
inline constexpr double kTorusAspectLimit = 0x1p30;
inline constexpr double kTorusFattestSpindle = 2;

// Every real root t of |o + t d| on the torus (negative ones too), ascending,
// with multiplicity where the quartic has a multiple root: a tangent point is
// listed twice, and so is a horn torus's centre. The exceptions are the
// fourfold roots, listed twice, not four times: where the ray lies in the
// plane of the tube's top or bottom circle and touches that circle (the
// quartic is then (t - t0)^4), and a horn torus's centre seen along its axis.
// `direction` need not be of unit length. Returns the count (0..4) written
// to t.
TOROID_HD int intersect_torus(double major, double minor, const double origin[3], const double direction[3],
                              double t[4], TorusSolver solver = TorusSolver::Default);

// The nearest root in the open interval (t_min, t_max), as a renderer needs
// it; same accuracy as intersect_torus, with an early exit. Returns false and
// leaves *t unchanged when there is none. It is intersect_torus's first root
// in the interval, bit for bit, except where t_min lies inside the tube (a
// ray refracted into it): that root is found from t_min, within the
// solver's accuracy of the list's, and whether there is one is the list's
// answer. With t_min a root this returned (or intersect_torus listed), it is
// the next root: the roots of a ray can be walked one call at a time.
TOROID_HD bool intersect_torus_nearest(double major, double minor, const double origin[3], const double direction[3],
                                       double t_min, double t_max, double* t,
                                       TorusSolver solver = TorusSolver::Default);

// Whether some root lies in the open interval (t_min, t_max): the answer of
// intersect_torus_nearest, for shadow rays, which need no root's position
// (a root found on a stretch of the ray inside the interval is not refined).
TOROID_HD bool torus_blocks(double major, double minor, const double origin[3], const double direction[3], double t_min,
                            double t_max, TorusSolver solver = TorusSolver::Default);

// The quartic a t^4 + b t^3 + c t^2 + d t + e of the seed paper, formed
// directly from the inputs (coeffs[0] = a ... coeffs[4] = e). The closed-form
// solvers use it; the default solver does not (see docs/torus.md).
TOROID_HD void torus_quartic_coefficients(double major, double minor, const double origin[3], const double direction[3],
                                          double coeffs[5]);

}  // namespace toroid
