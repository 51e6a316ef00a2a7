// The xz plane, y = 0 in object space (RTC chapter 9).
#pragma once

#include "toroid/shapes/primitive.h"

namespace toroid {

class Plane : public Primitive<Plane> {
 public:
  // Infinite in x and z, flat in y.
  BoundingBox bounds() const override {
    return {point(-BoundingBox::kInf, 0, -BoundingBox::kInf), point(BoundingBox::kInf, 0, BoundingBox::kInf)};
  }
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
