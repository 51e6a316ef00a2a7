// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/plane.h"

#include <cmath>

namespace toroid {

int Plane::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  double t;
  if (!hit_at(ray.origin.y, ray.direction.y, t)) return 0;
  hits[0] = {t, this};
  return 1;
}

Tuple Plane::local_normal_at(const Tuple&, const Intersection&) const { return vector(0, 1, 0); }

Tuple Plane::normal_at(const Tuple& world_point, const Intersection& hit) const {
  return parent == nullptr ? world_normal_ : Shape::normal_at(world_point, hit);
}

void Plane::transform_changed() { world_normal_ = normal_to_parent(local_normal_at(point(0, 0, 0), {})); }

}  // namespace toroid
