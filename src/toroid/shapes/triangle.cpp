// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/triangle.h"

#include <algorithm>
#include <cmath>

namespace toroid {

namespace {
// Rays closer than this to parallel (as the cosine of the angle between the
// ray and the plane's normal) miss. Relative, so that small triangles from
// finely tessellated meshes are not lost as the book's absolute EPSILON would.
constexpr double kParallelCosine = 1e-12;
}  // namespace

Triangle::Triangle(const Tuple& p1, const Tuple& p2, const Tuple& p3)
    : p1_(p1), p2_(p2), p3_(p3), e1_(p2 - p1), e2_(p3 - p1) {
  const Tuple n = cross(e2_, e1_);
  area2_ = magnitude(n);
  normal_ = area2_ > 0 ? n / area2_ : vector(0, 0, 0);
}

BoundingBox Triangle::bounds() const {
  BoundingBox b;
  b.add_point(p1_);
  b.add_point(p2_);
  b.add_point(p3_);
  return b;
}

int Triangle::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  const Tuple dir_cross_e2 = cross(ray.direction, e2_);
  const double det = dot(e1_, dir_cross_e2);
  const Tuple& d = ray.direction;
  const double dmax = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
  if (!(std::abs(det) > kParallelCosine * area2_ * dmax)) return 0;  // parallel or degenerate
  const double f = 1.0 / det;
  const Tuple p1_to_origin = ray.origin - p1_;
  const double u = f * dot(p1_to_origin, dir_cross_e2);
  if (u < 0 || u > 1) return 0;
  const Tuple origin_cross_e1 = cross(p1_to_origin, e1_);
  const double v = f * dot(d, origin_cross_e1);
  if (v < 0 || u + v > 1) return 0;
  hits[0] = {f * dot(e2_, origin_cross_e1), this, u, v};
  return 1;
}

Tuple Triangle::local_normal_at(const Tuple&, const Intersection&) const { return normal_; }

}  // namespace toroid
