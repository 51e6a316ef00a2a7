// Ray–torus intersection: the one place where the torus is solved. The Torus
// shape, the `toroid intersect` command, the benchmarks and the accuracy
// harness all call these functions, and so can another renderer.
//
// The torus is in object space, ring in the xy-plane, axis z, centred at the
// origin: (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2. Any major > 0 and
// minor > 0 is allowed: minor >= major gives horn and spindle tori, whose
// whole quartic surface (the spindle's inner "lemon" included) is intersected.
#pragma once

#include "toroid/roots/quartic.h"

namespace toroid {

// Every real root t of |o + t d| on the torus (negative ones too), ascending,
// with multiplicity where the quartic has a multiple root. `direction` need
// not be of unit length. Returns the count (0..4) written to t.
int intersect_torus(double major, double minor, const double origin[3], const double direction[3],
                    double t[4], QuarticSolver solver = QuarticSolver::Default);

// The nearest root in the open interval (t_min, t_max), as a renderer needs
// it; same accuracy as intersect_torus, with an early exit. Returns false and
// leaves *t unchanged when there is none.
bool intersect_torus_nearest(double major, double minor, const double origin[3], const double direction[3],
                             double t_min, double t_max, double* t,
                             QuarticSolver solver = QuarticSolver::Default);

// Whether some root lies in the open interval (t_min, t_max): the answer of
// intersect_torus_nearest, for shadow rays, which need no root's position
// (a root found on a stretch of the ray inside the interval is not refined).
bool torus_blocks(double major, double minor, const double origin[3], const double direction[3], double t_min,
                  double t_max, QuarticSolver solver = QuarticSolver::Default);

// The quartic a t^4 + b t^3 + c t^2 + d t + e of the seed paper, formed
// directly from the inputs (coeffs[0] = a ... coeffs[4] = e). The closed-form
// solvers use it; the default solver does not (see docs/torus.md).
void torus_quartic_coefficients(double major, double minor, const double origin[3], const double direction[3],
                                double coeffs[5]);

// The seed's normal at a point on the surface (object space, not normalised):
// ((1 - R/rho) x, (1 - R/rho) y, z), with rho = sqrt(x^2 + y^2). On the
// spindle's inner part (closer to the far side of the centre circle) the
// nearest point of the circle is on the other side, and the normal uses
// (1 + R/rho). Finite everywhere, the axis points included.
void torus_normal(double major, double minor, const double p[3], double n[3]);

// Whether a point on the surface of a spindle torus (minor > major) lies on
// the inner "lemon" sheet (rho + R)^2 + z^2 = r^2, the part of the quartic's
// surface closer to the far side of the centre circle, rather than on the
// outer sheet (rho - R)^2 + z^2 = r^2: whichever factor the point satisfies
// best. Always false for ring and horn tori (minor <= major).
bool on_torus_lemon(double major, double minor, const double p[3]);

// RenderMan's surface parameters of a point on the surface (RiTorus):
// p = ((R + r cos phi) cos theta, (R + r cos phi) sin theta, r sin phi).
// theta in [0, 2 pi) is the angle around the z axis from +x towards +y; phi
// in [-pi, pi] the angle around the tube, 0 on the outer equator, pi/2 on top
// (+z), +-pi on the inner equator. On a spindle's lemon R + r cos phi < 0:
// the point lies across the axis from its tube centre, so theta is
// atan2(y, x) + pi there. On the axis itself theta is 0.
void torus_angles(double major, double minor, const double p[3], double* theta, double* phi);

}  // namespace toroid
