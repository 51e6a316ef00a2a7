#include "toroid/shapes/torus.h"

#include "toroid/shapes/torus_intersect.h"

namespace toroid {

BoundingBox Torus::bounds() const {
  const double e = major_ + minor_;
  return {point(-e, -e, -minor_), point(e, e, minor_)};
}

void Torus::local_intersect(const Ray& ray, Intersections& xs) const {
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  double t[4];
  const int n = intersect_torus(major_, minor_, o, d, t, solver_);
  for (int i = 0; i < n; ++i) xs.push_back({t[i], this});
}

Tuple Torus::local_normal_at(const Tuple& p, const Intersection&) const {
  const double q[3] = {p.x, p.y, p.z};
  double n[3];
  torus_normal(major_, minor_, q, n);
  return vector(n[0], n[1], n[2]);
}

}  // namespace toroid
