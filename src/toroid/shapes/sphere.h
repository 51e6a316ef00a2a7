// SPDX-License-Identifier: Apache-2.0
// Unit sphere at the origin (RTC chapter 5).
#pragma once

#include <memory>

#include "toroid/shapes/primitive.h"

namespace toroid {

class Sphere : public Primitive<Sphere> {
 public:
  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  // Half of bounds()'s side, without building the box: asked at every hit.
  double half_thickness() const override { return 1.0; }
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

// A unit sphere of glass: transparency 1, refractive index 1.5 (RTC chapter 11).
std::shared_ptr<Sphere> glass_sphere();

}  // namespace toroid
