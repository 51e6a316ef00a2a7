#include "toroid/shapes/primitive.h"

namespace toroid {

void Primitive::local_intersect(const Ray& local_ray, Intersections& xs) const {
  Intersection hits[kMaxHits];
  const int n = local_hits(local_ray, hits);
  xs.insert(xs.end(), hits, hits + n);
}

bool Primitive::local_intersect_nearest(const Ray& local_ray, double t_max, Intersection& hit) const {
  Intersection hits[kMaxHits];
  const int n = local_hits(local_ray, hits);
  bool found = false;
  for (int i = 0; i < n; ++i)
    if (hits[i].t >= 0 && hits[i].t < t_max) {
      hit = hits[i];
      t_max = hits[i].t;
      found = true;
    }
  return found;
}

bool Primitive::local_blocks(const Ray& local_ray, double t_max) const {
  Intersection hits[kMaxHits];
  const int n = local_hits(local_ray, hits);
  for (int i = 0; i < n; ++i)
    if (hits[i].t >= 0 && hits[i].t < t_max) return true;
  return false;
}

}  // namespace toroid
