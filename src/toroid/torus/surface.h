// SPDX-License-Identifier: Apache-2.0
// The torus's surface at a point: normal, which sheet of a spindle torus,
// and the surface parameters. Same torus as intersect.h: ring in the
// xy-plane, axis z, centred at the origin,
// (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2.
#pragma once

#include "toroid/math/device.h"

namespace toroid {

// The seed's normal at a point on the surface (object space, not normalised):
// ((1 - R/rho) x, (1 - R/rho) y, z), with rho = sqrt(x^2 + y^2). On the
// spindle's inner part (closer to the far side of the centre circle) the
// nearest point of the circle is on the other side, and the normal uses
// (1 + R/rho). Finite everywhere, the axis points included.
TOROID_HD void torus_normal(double major, double minor, const double p[3], double n[3]);

// Whether a point on the surface of a spindle torus (minor > major) lies on
// the inner "lemon" sheet (rho + R)^2 + z^2 = r^2, the part of the quartic's
// surface closer to the far side of the centre circle, rather than on the
// outer sheet (rho - R)^2 + z^2 = r^2: whichever factor the point satisfies
// best. Always false for ring and horn tori (minor <= major).
TOROID_HD bool on_torus_lemon(double major, double minor, const double p[3]);

// RenderMan's surface parameters of a point on the surface (RiTorus):
// p = ((R + r cos phi) cos theta, (R + r cos phi) sin theta, r sin phi).
// theta in [0, 2 pi) is the angle around the z axis from +x towards +y; phi
// in [-pi, pi] the angle around the tube, 0 on the outer equator, pi/2 on top
// (+z), +-pi on the inner equator. On a spindle's lemon R + r cos phi < 0:
// the point lies across the axis from its tube centre, so theta is
// atan2(y, x) + pi there. On the axis itself theta is 0.
TOROID_HD void torus_angles(double major, double minor, const double p[3], double* theta, double* phi);

}  // namespace toroid
