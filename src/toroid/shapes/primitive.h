// A shape with a surface of its own and at most four intersections along
// any ray (sphere, plane, cube, cylinder, cone, triangle, torus). It lists
// them once, into a fixed array, and the renderer's queries (nearest hit,
// shadow test) read them from there instead of from a growing list.
#pragma once

#include "toroid/shapes/shape.h"

namespace toroid {

class Primitive : public Shape {
 public:
  static constexpr int kMaxHits = 4;

  void local_intersect(const Ray& local_ray, Intersections& xs) const final;
  bool local_intersect_nearest(const Ray& local_ray, double t_max, Intersection& hit) const override;
  bool local_blocks(const Ray& local_ray, double t_max) const override;

  // Writes every intersection along the ray (any t, the order
  // local_intersect lists them in) and returns how many (0..kMaxHits).
  virtual int local_hits(const Ray& local_ray, Intersection hits[kMaxHits]) const = 0;
};

}  // namespace toroid
