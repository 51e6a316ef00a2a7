// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/cone.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "toroid/shapes/caps.h"

namespace toroid {

BoundingBox Cone::bounds() const {
  const double limit = std::max(std::abs(minimum), std::abs(maximum));
  return {point(-limit, minimum, -limit), point(limit, maximum, limit)};
}

int Cone::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  int n = 0;
  const Tuple& o = ray.origin;
  const Tuple& d = ray.direction;
  const double a = d.x * d.x - d.y * d.y + d.z * d.z;
  const double b = 2 * (o.x * d.x - o.y * d.y + o.z * d.z);
  const double c = o.x * o.x - o.y * o.y + o.z * o.z;
  auto add_if_within = [&](double t) {
    const double y = o.y + t * d.y;
    if (minimum < y && y < maximum) hits[n++] = {t, this};
  };
  if (std::abs(a) < kEpsilon) {
    // Parallel to one half: a single intersection with the other half.
    if (std::abs(b) >= kEpsilon) add_if_within(-c / (2 * b));
  } else {
    const double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      double t0 = q / a;
      double t1 = q != 0 ? c / q : t0;
      if (t0 > t1) std::swap(t0, t1);
      add_if_within(t0);
      add_if_within(t1);
    }
  }
  if (!closed || std::abs(d.y) < kEpsilon) return n;
  const double tlo = (minimum - o.y) / d.y;
  if (detail::within_cap(ray, tlo, std::abs(minimum))) hits[n++] = {tlo, this};
  const double thi = (maximum - o.y) / d.y;
  if (detail::within_cap(ray, thi, std::abs(maximum))) hits[n++] = {thi, this};
  return n;
}

Tuple Cone::local_normal_at(const Tuple& p, const Intersection&) const {
  const double dist = p.x * p.x + p.z * p.z;
  if (dist < maximum * maximum && p.y >= maximum - kEpsilon) return vector(0, 1, 0);
  if (dist < minimum * minimum && p.y <= minimum + kEpsilon) return vector(0, -1, 0);
  double y = std::sqrt(dist);
  if (p.y > 0) y = -y;
  return vector(p.x, y, p.z);
}

}  // namespace toroid
