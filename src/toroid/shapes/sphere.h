// SPDX-License-Identifier: Apache-2.0
// Unit sphere at the origin (RTC chapter 5).
#pragma once

#include <cmath>
#include <memory>
#include <utility>

#include "toroid/shapes/primitive.h"

namespace toroid {

class Sphere : public Primitive<Sphere> {
 public:
  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  // Half of bounds()'s side, without building the box: asked at every hit.
  double half_thickness() const override { return 1.0; }
  bool closed_surface() const override { return true; }
  // Inline: the renderer's three queries each inline it, and the sphere's
  // arithmetic is cheaper than a call and the zeroing of an unread array.
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
    // The book's a, b and c, with dot products of xyz alone: the origin less
    // the centre (0, 0, 0) is the origin, and the w terms are 0 * 0 (b's + 0
    // is kept: it turns a sum of -0 into +0, and b's sign picks the root).
    const Tuple& o = ray.origin;
    const Tuple& d = ray.direction;
    const double a = d.x * d.x + d.y * d.y + d.z * d.z;
    const double b = 2 * (d.x * o.x + d.y * o.y + d.z * o.z + 0.0);
    const double c = o.x * o.x + o.y * o.y + o.z * o.z - 1;
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return 0;
    // Numerically stable form: no cancellation between -b and sqrt(disc).
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    hits[0] = {t0, this};
    hits[1] = {t1, this};
    return 2;
  }
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;
};

// A unit sphere of glass: transparency 1, refractive index 1.5 (RTC chapter 11).
std::shared_ptr<Sphere> glass_sphere();

}  // namespace toroid
