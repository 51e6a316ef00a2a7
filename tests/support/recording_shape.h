// SPDX-License-Identifier: Apache-2.0
// The book's test_shape(): a shape that records the last ray it was asked to
// intersect (in its object space) and has the bounds of a unit cube.
#pragma once

#include <optional>

#include "toroid/shapes/shape.h"

namespace toroid::testing {

class RecordingShape : public Shape {
 public:
  mutable std::optional<Ray> saved_ray;

  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  void local_intersect(const Ray& ray, Intersections&) const override { saved_ray = ray; }
  Tuple local_normal_at(const Tuple& p, const Intersection&) const override { return vector(p.x, p.y, p.z); }
};

}  // namespace toroid::testing
