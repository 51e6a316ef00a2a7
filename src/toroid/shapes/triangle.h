// SPDX-License-Identifier: Apache-2.0
// Flat triangle (RTC chapter 15), intersected with Moller-Trumbore.
#pragma once

#include "toroid/shapes/primitive.h"

namespace toroid {

class Triangle : public Primitive<Triangle> {
 public:
  Triangle(const Tuple& p1, const Tuple& p2, const Tuple& p3);

  const Tuple& p1() const { return p1_; }
  const Tuple& p2() const { return p2_; }
  const Tuple& p3() const { return p3_; }
  const Tuple& e1() const { return e1_; }  // p2 - p1
  const Tuple& e2() const { return e2_; }  // p3 - p1
  const Tuple& normal() const { return normal_; }

  BoundingBox bounds() const override;
  // Records the barycentric u (weight of p2) and v (weight of p3) of the hit.
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;

 private:
  Tuple p1_, p2_, p3_, e1_, e2_, normal_;
  // |e1 x e2|: scales the parallel-ray test to the triangle's size.
  double area2_;
};

}  // namespace toroid
