// SPDX-License-Identifier: Apache-2.0
// Unit-radius cylinder around the y axis (RTC chapter 13), optionally
// truncated to minimum < y < maximum and closed with caps.
#pragma once

#include "toroid/shapes/primitive.h"

namespace toroid {

class Cylinder : public Primitive<Cylinder> {
 public:
  // Changing these after the cylinder joins a group: call bounds_changed().
  double minimum = -BoundingBox::kInf;
  double maximum = BoundingBox::kInf;
  bool closed = false;

  BoundingBox bounds() const override { return {point(-1, minimum, -1), point(1, maximum, 1)}; }
  bool closed_surface() const override { return closed && minimum > -BoundingBox::kInf && maximum < BoundingBox::kInf; }
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
