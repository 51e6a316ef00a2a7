// SPDX-License-Identifier: Apache-2.0
// The hole test of a ring torus (minor < major), shared by the scalar solver
// (intersect.cpp) and the SIMD batch (batch_kernel.h) so that both reject
// the same rays. Internal: not installed.
//
// No point of the torus lies inside the cylinder rho < major - minor, and
// rho^2 is convex along a ray, so a chord whose two ends lie inside that
// cylinder holds no root: the ray passes through the hole. The ends' rho^2
// is compared with hole_limit, (major - minor)^2 less a margin of 2^-26 of
// it, which is far above the rounding of rho^2 at the ends (a few eps
// (major + minor)^2) wherever major - minor > 2^-16 (major + minor); for
// fatter tori, horn tori and spindles there is no test (the limit is -1).
#pragma once

#include "toroid/math/device.h"

namespace toroid {

TOROID_HD inline double hole_limit(double major, double minor) {
  const double hole = major - minor;
  return hole > 0x1p-16 * (major + minor) ? hole * hole * (1 - 0x1p-26) : -1.0;
}

}  // namespace toroid
