// SPDX-License-Identifier: Apache-2.0
// Axis-aligned cube from -1 to 1 on every axis (RTC chapter 12).
#pragma once

#include "toroid/shapes/primitive.h"

namespace toroid {

class Cube : public Primitive<Cube> {
 public:
  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  // Half of bounds()'s side, without building the box: asked at every hit.
  double half_thickness() const override { return 1.0; }
  bool closed_surface() const override { return true; }
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
