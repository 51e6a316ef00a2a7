// SPDX-License-Identifier: Apache-2.0
// Double-napped cone x^2 + z^2 = y^2 around the y axis (RTC chapter 13),
// optionally truncated to minimum < y < maximum and closed with caps.
#pragma once

#include "toroid/shapes/primitive.h"

namespace toroid {

class Cone : public Primitive<Cone> {
 public:
  // Changing these after the cone joins a group: call bounds_changed().
  double minimum = -BoundingBox::kInf;
  double maximum = BoundingBox::kInf;
  bool closed = false;

  BoundingBox bounds() const override;
  bool closed_surface() const override { return closed && minimum > -BoundingBox::kInf && maximum < BoundingBox::kInf; }
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const;
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

}  // namespace toroid
