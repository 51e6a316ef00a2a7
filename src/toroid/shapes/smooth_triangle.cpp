// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/smooth_triangle.h"

namespace toroid {

Tuple SmoothTriangle::local_normal_at(const Tuple&, const Intersection& hit) const {
  return n2_ * hit.u + n3_ * hit.v + n1_ * (1 - hit.u - hit.v);
}

}  // namespace toroid
