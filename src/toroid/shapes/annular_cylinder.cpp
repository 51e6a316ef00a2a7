// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/annular_cylinder.h"

#include <algorithm>
#include <cmath>

namespace toroid {
namespace {
// Relative growth of the washer: rounding in the test is ~1e-16 relative.
constexpr double kMargin = 1e-9;
}  // namespace

bool AnnularCylinder::may_meet(const Tuple& origin, const Tuple& direction, double t_min, double t_max) const {
  const Tuple& d = direction;
  const double dd = d.x * d.x + d.y * d.y + d.z * d.z;
  if (!(dd > 0)) return true;  // degenerate ray: let the exact test decide
  // Work from the line's point nearest the axis origin (p, at t_shift), so
  // that a distant origin does not cancel digits away; its own rounding is
  // covered by `slack`.
  const double t_shift = -(origin.x * d.x + origin.y * d.y + origin.z * d.z) / dd;
  const double px = origin.x + t_shift * d.x, py = origin.y + t_shift * d.y, pz = origin.z + t_shift * d.z;
  const double slack =
      kMargin * (r_out + half_height) +
      1e-15 * (std::abs(origin.x) + std::abs(origin.y) + std::abs(origin.z) + std::abs(t_shift) * std::sqrt(dd));
  double lo = t_min - t_shift, hi = t_max - t_shift;

  // The slab |z| <= half height.
  const double h = half_height + slack;
  if (d.z != 0) {
    double z0 = (-h - pz) / d.z, z1 = (h - pz) / d.z;
    if (z0 > z1) std::swap(z0, z1);
    lo = std::max(lo, z0);
    hi = std::min(hi, z1);
  } else if (std::abs(pz) > h) {
    return false;
  }
  if (!(lo <= hi)) return false;

  // rho^2(s) = a s^2 + 2 b s + c: inside the outer cylinder...
  const double a = d.x * d.x + d.y * d.y;
  const double b = px * d.x + py * d.y;
  const double c = px * px + py * py;
  const double ro = r_out + slack;
  if (a == 0) {
    if (c > ro * ro) return false;
  } else {
    const double disc = b * b - a * (c - ro * ro);
    if (disc < 0) return false;
    const double w = std::sqrt(disc);
    lo = std::max(lo, (-b - w) / a);
    hi = std::min(hi, (-b + w) / a);
    if (!(lo <= hi)) return false;
  }

  // ...and not wholly inside the hole.
  const double ri = r_in - slack;
  if (ri <= 0) return true;
  if (a == 0) return c >= ri * ri;
  const double disc = b * b - a * (c - ri * ri);
  if (disc <= 0) return true;
  const double w = std::sqrt(disc);
  return !((-b - w) / a < lo && hi < (-b + w) / a);
}

}  // namespace toroid
