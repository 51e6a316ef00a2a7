// Unit sphere at the origin (RTC chapter 5).
#pragma once

#include "toroid/shapes/shape.h"

namespace toroid {

class Sphere : public Shape {
 public:
  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  void local_intersect(const Ray& ray, Intersections& xs) const override;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
