#include "toroid/shapes/plane.h"

#include <cmath>

namespace toroid {

void Plane::local_intersect(const Ray& ray, Intersections& xs) const {
  // Parallel or coplanar rays miss: a coplanar ray would see only the edge.
  if (std::abs(ray.direction.y) < kEpsilon) return;
  xs.push_back({-ray.origin.y / ray.direction.y, this});
}

Tuple Plane::local_normal_at(const Tuple&, const Intersection&) const { return vector(0, 1, 0); }

}  // namespace toroid
