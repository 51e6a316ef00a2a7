// SPDX-License-Identifier: Apache-2.0
// A bounding volume for ring shapes: the solid annular cylinder (a thick
// washer) r_in <= sqrt(x^2 + y^2) <= r_out, |z| <= half_height, axis z. A
// torus fits in the one with r_in = R - r, r_out = R + r, half height r;
// unlike its box, the washer rejects the rays through the hole, and the test
// costs a few dozen flops where the ray-torus solver costs hundreds of ns.
#pragma once

#include "toroid/math/tuple.h"

namespace toroid {

struct AnnularCylinder {
  double r_in;  // <= 0: no hole
  double r_out;
  double half_height;

  // Whether the segment origin + t direction, t_min < t < t_max, may meet
  // the solid. Conservative: the washer is grown by a relative margin far
  // above rounding (and by the rounding of a distant origin), so a segment
  // that meets it is never rejected; one that misses it by less than the
  // margin may be accepted.
  bool may_meet(const Tuple& origin, const Tuple& direction, double t_min, double t_max) const;
};

}  // namespace toroid
