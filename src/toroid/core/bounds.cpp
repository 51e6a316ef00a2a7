// SPDX-License-Identifier: Apache-2.0
#include "toroid/core/bounds.h"

#include <algorithm>
#include <cmath>

namespace toroid {

void BoundingBox::add_point(const Tuple& p) {
  min = point(std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z));
  max = point(std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z));
}

void BoundingBox::merge(const BoundingBox& other) {
  if (other.empty()) return;
  add_point(other.min);
  add_point(other.max);
}

bool BoundingBox::contains_point(const Tuple& p) const {
  return min.x <= p.x && p.x <= max.x && min.y <= p.y && p.y <= max.y && min.z <= p.z && p.z <= max.z;
}

bool BoundingBox::contains_box(const BoundingBox& other) const {
  return contains_point(other.min) && contains_point(other.max);
}

std::pair<BoundingBox, BoundingBox> BoundingBox::split() const {
  const double dx = max.x - min.x;
  const double dy = max.y - min.y;
  const double dz = max.z - min.z;
  const double greatest = std::max({dx, dy, dz});
  double x0 = min.x, y0 = min.y, z0 = min.z;
  double x1 = max.x, y1 = max.y, z1 = max.z;
  if (greatest == dx) {
    x0 = x1 = x0 + dx / 2;
  } else if (greatest == dy) {
    y0 = y1 = y0 + dy / 2;
  } else {
    z0 = z1 = z0 + dz / 2;
  }
  return {BoundingBox{min, point(x1, y1, z1)}, BoundingBox{point(x0, y0, z0), max}};
}

BoundingBox padded_box(const double centre[3], const double half[3]) {
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    const double pad = 1e-9 * (std::abs(centre[i]) + half[i]);
    lo[i] = centre[i] - half[i] - pad;
    hi[i] = centre[i] + half[i] + pad;
  }
  return {point(lo[0], lo[1], lo[2]), point(hi[0], hi[1], hi[2])};
}

BoundingBox transform(const BoundingBox& b, const Matrix4& m) {
  if (b.empty()) return b;
  const double lo[3] = {b.min.x, b.min.y, b.min.z};
  const double hi[3] = {b.max.x, b.max.y, b.max.z};
  double rmin[3], rmax[3];
  for (int i = 0; i < 3; ++i) {
    rmin[i] = rmax[i] = m(i, 3);
    for (int j = 0; j < 3; ++j) {
      const double a = m(i, j);
      if (a == 0) continue;  // this axis does not feed that one; skip 0 * inf
      const double p = a * lo[j];
      const double q = a * hi[j];
      rmin[i] += std::min(p, q);
      rmax[i] += std::max(p, q);
    }
  }
  return {point(rmin[0], rmin[1], rmin[2]), point(rmax[0], rmax[1], rmax[2])};
}

}  // namespace toroid
