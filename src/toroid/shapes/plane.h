// The xz plane, y = 0 in object space (RTC chapter 9).
#pragma once

#include "toroid/shapes/shape.h"

namespace toroid {

class Plane : public Shape {
 public:
  // Infinite in x and z, flat in y.
  BoundingBox bounds() const override {
    return {point(-BoundingBox::kInf, 0, -BoundingBox::kInf), point(BoundingBox::kInf, 0, BoundingBox::kInf)};
  }
  void local_intersect(const Ray& ray, Intersections& xs) const override;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
