#include "toroid/shapes/torus.h"

#include <limits>

#include "toroid/shapes/torus_intersect.h"

namespace toroid {

BoundingBox Torus::bounds() const {
  const double e = major_ + minor_;
  return {point(-e, -e, -minor_), point(e, e, minor_)};
}

AnnularCylinder Torus::washer() const { return {major_ - minor_, major_ + minor_, minor_}; }

int Torus::local_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!washer().may_meet(ray.origin, ray.direction, -kInf, kInf)) return 0;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  double t[4];
  const int n = intersect_torus(major_, minor_, o, d, t, solver_);
  for (int i = 0; i < n; ++i) hits[i] = {t[i], this};
  return n;
}

bool Torus::nearest_root(const Ray& ray, double t_max, double& t) const {
  // The query's interval is open: just below 0 admits t = 0, as hit() does.
  constexpr double kBelowZero = -std::numeric_limits<double>::denorm_min();
  // Most rays that reach a torus's box miss the torus, or meet it beyond
  // t_max (a nearer hit, the light): the washer turns them away cheaply.
  if (!washer().may_meet(ray.origin, ray.direction, kBelowZero, t_max)) return false;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  return intersect_torus_nearest(major_, minor_, o, d, kBelowZero, t_max, &t, solver_);
}

bool Torus::local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
  double t;
  if (!nearest_root(ray, t_max, t)) return false;
  hit = {t, this};
  return true;
}

bool Torus::local_blocks(const Ray& ray, double t_max) const {
  double t;
  return nearest_root(ray, t_max, t);
}

Tuple Torus::local_normal_at(const Tuple& p, const Intersection&) const {
  const double q[3] = {p.x, p.y, p.z};
  double n[3];
  torus_normal(major_, minor_, q, n);
  return vector(n[0], n[1], n[2]);
}

}  // namespace toroid
