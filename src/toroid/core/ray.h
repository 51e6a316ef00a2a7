// SPDX-License-Identifier: Apache-2.0
// A ray origin + t * direction. The direction is not assumed to be of unit
// length: transforming a ray into object space scales it, and t stays valid.
#pragma once

#include "toroid/math/matrix.h"

namespace toroid {

struct Ray {
  Tuple origin;
  Tuple direction;

  constexpr Tuple position(double t) const { return origin + direction * t; }
};

constexpr Ray transform(const Ray& r, const Matrix4& m) { return {m * r.origin, m * r.direction}; }

}  // namespace toroid
