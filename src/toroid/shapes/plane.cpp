#include "toroid/shapes/plane.h"

#include <cmath>

namespace toroid {

int Plane::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  // Parallel or coplanar rays miss: a coplanar ray would see only the edge.
  if (std::abs(ray.direction.y) < kEpsilon) return 0;
  hits[0] = {-ray.origin.y / ray.direction.y, this};
  return 1;
}

Tuple Plane::local_normal_at(const Tuple&, const Intersection&) const { return vector(0, 1, 0); }

}  // namespace toroid
