// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/shape.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toroid {

void Shape::set_transform(const Matrix4& m) {
  inverse_ = Affine::from(inverse(m));
  transform_changed();
  bounds_changed();
}

Tuple Shape::world_to_object(const Tuple& world_point) const {
  const Tuple p = parent ? parent->world_to_object(world_point) : world_point;
  return inverse_.times_point(p);
}

Tuple Shape::normal_to_world(const Tuple& object_normal) const {
  const Tuple n = normal_to_parent(object_normal);
  return parent ? parent->normal_to_world(n) : n;
}

Tuple Shape::normal_at(const Tuple& world_point, const Intersection& hit) const {
  return normal_to_world(local_normal_at(world_to_object(world_point), hit));
}

BoundingBox Shape::parent_space_bounds() const { return ::toroid::transform(bounds(), transform()); }

double Shape::parent_space_half_thickness() const { return half_in_parent_space(half_thickness()); }

double Shape::half_thickness() const {
  const BoundingBox box = bounds();
  double half = std::numeric_limits<double>::infinity();
  for (const double side : {box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z})
    if (side > 0 && std::isfinite(side)) half = std::min(half, side / 2);
  return std::isfinite(half) ? half : 0.0;
}

namespace {
// local_intersect's list for the default queries. One per thread; the
// defaults never re-enter each other while it is in use (local_intersect
// only calls intersect below it).
Intersections& scratch() {
  thread_local Intersections xs;
  xs.clear();
  return xs;
}
}  // namespace

bool Shape::local_intersect_nearest(const Ray& local_ray, double t_max, Intersection& hit) const {
  Intersections& xs = scratch();
  local_intersect(local_ray, xs);
  const Intersection* best = nullptr;
  for (const Intersection& x : xs)
    if (x.t >= 0 && x.t < t_max && (best == nullptr || x.t < best->t)) best = &x;
  if (best == nullptr) return false;
  hit = *best;
  return true;
}

bool Shape::local_blocks(const Ray& local_ray, double t_max) const {
  Intersections& xs = scratch();
  local_intersect(local_ray, xs);
  for (const Intersection& x : xs)
    if (x.t >= 0 && x.t < t_max && x.object->casts_shadow) return true;
  return false;
}

}  // namespace toroid
