// Axis-aligned cube from -1 to 1 on every axis (RTC chapter 12).
#pragma once

#include "toroid/shapes/shape.h"

namespace toroid {

class Cube : public Shape {
 public:
  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  void local_intersect(const Ray& ray, Intersections& xs) const override;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
