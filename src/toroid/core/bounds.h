// SPDX-License-Identifier: Apache-2.0
// Axis-aligned bounding boxes (RTC bonus chapter "Bounding boxes and hierarchies").
#pragma once

#include <limits>
#include <utility>

#include "toroid/core/ray.h"
#include "toroid/math/matrix.h"

namespace toroid {

// An axis-aligned box; the default one is empty (min = +inf, max = -inf) and
// infinite extents are allowed (planes, open cylinders and cones).
struct BoundingBox {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  Tuple min = point(kInf, kInf, kInf);
  Tuple max = point(-kInf, -kInf, -kInf);

  // True when the box holds no point at all (min > max on some axis).
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }

  // Grows the box to hold `p`.
  void add_point(const Tuple& p);
  // Grows the box to hold `other` ("adding one bounding box to another").
  void merge(const BoundingBox& other);

  // Inclusive: points on the faces are contained.
  bool contains_point(const Tuple& p) const;
  bool contains_box(const BoundingBox& other) const;

  // Whether the ray meets the box at some 0 <= t <= t_max (slab test).
  // Handles infinite extents and zero direction components without NaN
  // trouble: a slab that a parallel ray grazes exactly is treated as crossed.
  inline bool intersects(const Ray& r, double t_max = kInf) const;

  // The bonus chapter's split: halves the box across its largest extent
  // (ties prefer x, then y); returns {left, right}.
  std::pair<BoundingBox, BoundingBox> split() const;
};

// The box that holds the eight corners of `b` transformed by `m` (an affine
// matrix). Computed per axis (Arvo's method), which gives the same box as
// transforming the corners but never forms 0 * infinity; an empty box stays empty.
BoundingBox transform(const BoundingBox& b, const Matrix4& m);

// The box centre[i] +- half[i] on each axis, outwards by 1e-9 (|centre[i]| +
// half[i]): far more than the rounding of the box and of a shape's own test,
// for a shape whose box must hold every hit it reports, a grazing one
// included (groups and CSG cull by the box).
BoundingBox padded_box(const double centre[3], const double half[3]);

namespace detail {
// One slab of the ray/box test. `inv` is 1 / direction (+-inf for a zero
// component). A NaN bound (0 * inf: the origin lies on a slab plane of a
// parallel ray) leaves the interval as it was, because comparisons with NaN fail.
inline void clip_slab(double lo, double hi, double origin, double inv, double& tmin, double& tmax) {
  double t0 = (lo - origin) * inv;
  double t1 = (hi - origin) * inv;
  if (inv < 0) std::swap(t0, t1);
  tmin = t0 > tmin ? t0 : tmin;
  tmax = t1 < tmax ? t1 : tmax;
}
}  // namespace detail

inline bool BoundingBox::intersects(const Ray& r, double t_max) const {
  double tmin = -kInf;
  double tmax = kInf;
  detail::clip_slab(min.x, max.x, r.origin.x, 1.0 / r.direction.x, tmin, tmax);
  detail::clip_slab(min.y, max.y, r.origin.y, 1.0 / r.direction.y, tmin, tmax);
  detail::clip_slab(min.z, max.z, r.origin.z, 1.0 / r.direction.z, tmin, tmax);
  return tmin <= tmax && tmax >= 0 && tmin <= t_max;
}

}  // namespace toroid
