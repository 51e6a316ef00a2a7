// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/cube.h"

#include <cmath>

namespace toroid {

int Cube::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  // The cube is its own bounding box: the same slab test, keeping both ends.
  double tmin = -BoundingBox::kInf;
  double tmax = BoundingBox::kInf;
  detail::clip_slab(-1, 1, ray.origin.x, 1.0 / ray.direction.x, tmin, tmax);
  detail::clip_slab(-1, 1, ray.origin.y, 1.0 / ray.direction.y, tmin, tmax);
  detail::clip_slab(-1, 1, ray.origin.z, 1.0 / ray.direction.z, tmin, tmax);
  if (tmin > tmax || std::isinf(tmin) || std::isinf(tmax)) return 0;
  hits[0] = {tmin, this};
  hits[1] = {tmax, this};
  return 2;
}

Tuple Cube::local_normal_at(const Tuple& p, const Intersection&) const {
  const double ax = std::abs(p.x), ay = std::abs(p.y), az = std::abs(p.z);
  if (ax >= ay && ax >= az) return vector(p.x, 0, 0);
  if (ay >= az) return vector(0, p.y, 0);
  return vector(0, 0, p.z);
}

}  // namespace toroid
