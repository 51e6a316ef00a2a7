// SPDX-License-Identifier: Apache-2.0
// The xz plane, y = 0 in object space (RTC chapter 9).
#pragma once

#include <cmath>

#include "toroid/shapes/primitive.h"

namespace toroid {

class Plane : public Primitive<Plane> {
 public:
  // Infinite in x and z, flat in y.
  BoundingBox bounds() const override {
    return {point(-BoundingBox::kInf, 0, -BoundingBox::kInf), point(BoundingBox::kInf, 0, BoundingBox::kInf)};
  }
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  // No finite, non-zero side (Shape::half_thickness's answer, without
  // building the box at every hit).
  double half_thickness() const override { return 0; }

  // Where a ray meets y = 0, given only the y of its object-space origin and
  // direction. Parallel or coplanar rays miss (a coplanar ray would see only
  // the edge). find_hits and the world index's plane test (which computes
  // just these two numbers from the inverse transform) share it.
  static bool hit_at(double origin_y, double direction_y, double& t) {
    if (std::abs(direction_y) < kEpsilon) return false;
    t = -origin_y / direction_y;
    return true;
  }
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
  // The same at every point: a plane at the top level answers with the
  // normal that Shape::normal_at computes, kept from set_transform (the same
  // operations on the same numbers, so the same bits; a tenth of a room's
  // shading otherwise). One inside a group asks its parents each time,
  // since their transforms may change after it joins them.
  Tuple normal_at(const Tuple& world_point, const Intersection& hit = {}) const override;

 protected:
  void transform_changed() override;

 private:
  Tuple world_normal_ = vector(0, 1, 0);  // normal_to_parent(local normal): the world's at the top level
};

}  // namespace toroid
