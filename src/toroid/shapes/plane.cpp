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

}  // namespace toroid
