// SPDX-License-Identifier: Apache-2.0
#include "toroid/torus/checked.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace

TOROID_HD bool torus_radii_valid(double major, double minor) {
  return std::isfinite(major) && std::isfinite(minor) && major > 0 && minor > 0;
}

TOROID_HD bool torus_ray_valid(const double origin[3], const double direction[3]) {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(origin[i]) || !std::isfinite(direction[i])) return false;
  return direction[0] != 0 || direction[1] != 0 || direction[2] != 0;
}

TOROID_HD int intersect_torus_checked(double major, double minor, const double origin[3], const double direction[3],
                                      double t[4]) {
  if (!torus_radii_valid(major, minor)) return -1;
  if (!torus_ray_valid(origin, direction)) return 0;
  return intersect_torus(major, minor, origin, direction, t);
}

TOROID_HD int intersect_torus_nearest_checked(double major, double minor, const double origin[3],
                                              const double direction[3], double t_min, double t_max, double* t) {
  if (!torus_radii_valid(major, minor)) return -1;
  if (!torus_ray_valid(origin, direction) || std::isnan(t_min) || std::isnan(t_max)) return 0;
  return intersect_torus_nearest(major, minor, origin, direction, t_min, t_max, t) ? 1 : 0;
}

TOROID_HD void torus_unit_normal(double major, double minor, const double p[3], double n[3]) {
  if (!torus_radii_valid(major, minor) || !std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
    n[0] = n[1] = n[2] = kNaN;
    return;
  }
  double m[3];
  torus_normal(major, minor, p, m);
  const double longest = std::max({std::abs(m[0]), std::abs(m[1]), std::abs(m[2])});
  if (!(longest > 0) || !std::isfinite(longest)) {
    n[0] = n[1] = n[2] = kNaN;
    return;
  }
  const int e = std::ilogb(longest);
  for (int i = 0; i < 3; ++i) m[i] = std::scalbn(m[i], -e);
  const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  for (int i = 0; i < 3; ++i) n[i] = m[i] / length;
}

TOROID_HD int intersect_torus_row(double major, double minor, const double origin[3], const double direction[3],
                                  double row[4]) {
  const int count = intersect_torus_checked(major, minor, origin, direction, row);
  for (int k = std::max(count, 0); k < 4; ++k) row[k] = kNaN;
  return count;
}

}  // namespace toroid
