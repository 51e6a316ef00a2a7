// SPDX-License-Identifier: Apache-2.0
// Helpers for the Torus shape's scenarios (shapes/torus_test.cpp and
// render/torus_shading_test.cpp).
#pragma once

#include <cmath>
#include <memory>

#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"
#include "toroid/shapes/torus.h"

namespace toroid {

// Every intersection of the shape with the ray, ascending.
inline Intersections intersect_sorted(const Shape& s, const Ray& r) {
  Intersections xs;
  s.intersect(r, xs);
  sort_intersections(xs);
  return xs;
}

// The torus R = 1, r = 0.25, cut to RiTorus's sweep (theta-max, phi-min, phi-max).
inline std::shared_ptr<Torus> partial_torus(double theta_max, double phi_min = -M_PI, double phi_max = M_PI) {
  auto t = std::make_shared<Torus>(1, 0.25);
  t->set_sweep({theta_max, phi_min, phi_max});
  return t;
}

}  // namespace toroid
