// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/cylinder.h"

#include <cmath>
#include <utility>

#include "toroid/shapes/caps.h"

namespace toroid {

int Cylinder::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  int n = 0;
  const double a = ray.direction.x * ray.direction.x + ray.direction.z * ray.direction.z;
  // A ray parallel to the y axis can only meet the caps.
  if (std::abs(a) >= kEpsilon) {
    const double b = 2 * (ray.origin.x * ray.direction.x + ray.origin.z * ray.direction.z);
    const double c = ray.origin.x * ray.origin.x + ray.origin.z * ray.origin.z - 1;
    const double disc = b * b - 4 * a * c;
    if (disc < 0) return n;  // misses the infinite cylinder, so the caps too
    // Stable form: no cancellation between -b and sqrt(disc).
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double t0 = q / a;
    double t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    const double y0 = ray.origin.y + t0 * ray.direction.y;
    if (minimum < y0 && y0 < maximum) hits[n++] = {t0, this};
    const double y1 = ray.origin.y + t1 * ray.direction.y;
    if (minimum < y1 && y1 < maximum) hits[n++] = {t1, this};
  }
  if (!closed || std::abs(ray.direction.y) < kEpsilon) return n;
  const double tlo = (minimum - ray.origin.y) / ray.direction.y;
  if (detail::within_cap(ray, tlo, 1)) hits[n++] = {tlo, this};
  const double thi = (maximum - ray.origin.y) / ray.direction.y;
  if (detail::within_cap(ray, thi, 1)) hits[n++] = {thi, this};
  return n;
}

Tuple Cylinder::local_normal_at(const Tuple& p, const Intersection&) const {
  const double dist = p.x * p.x + p.z * p.z;
  if (dist < 1 && p.y >= maximum - kEpsilon) return vector(0, 1, 0);
  if (dist < 1 && p.y <= minimum + kEpsilon) return vector(0, -1, 0);
  return vector(p.x, 0, p.z);
}

}  // namespace toroid
