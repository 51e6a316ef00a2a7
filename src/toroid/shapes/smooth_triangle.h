// SPDX-License-Identifier: Apache-2.0
// Triangle with a normal at each vertex, interpolated across the face with
// the hit's barycentric u/v (RTC chapter 15).
#pragma once

#include "toroid/shapes/triangle.h"

namespace toroid {

class SmoothTriangle : public Triangle {
 public:
  SmoothTriangle(const Tuple& p1, const Tuple& p2, const Tuple& p3, const Tuple& n1, const Tuple& n2, const Tuple& n3)
      : Triangle(p1, p2, p3), n1_(n1), n2_(n2), n3_(n3) {}

  const Tuple& n1() const { return n1_; }
  const Tuple& n2() const { return n2_; }
  const Tuple& n3() const { return n3_; }

  // n2 * u + n3 * v + n1 * (1 - u - v), from hit.u and hit.v.
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;

 private:
  Tuple n1_, n2_, n3_;
};

}  // namespace toroid
