// SPDX-License-Identifier: Apache-2.0
// The C API (toroid/torus_c.h): NULL pointers are answered here, everything
// else by the checked C++ calls of checked.h.
#include "toroid/torus_c.h"

#include <cstddef>
#include <limits>

#include "toroid/torus/checked.h"

extern "C" {

int toroid_torus_intersect(double major, double minor, const double origin[3], const double direction[3],
                           double t[4]) noexcept {
  if (origin == nullptr || direction == nullptr || t == nullptr) return -1;
  return toroid::intersect_torus_checked(major, minor, origin, direction, t);
}

int toroid_torus_nearest(double major, double minor, const double origin[3], const double direction[3], double t_min,
                         double t_max, double* t) noexcept {
  if (origin == nullptr || direction == nullptr || t == nullptr) return -1;
  return toroid::intersect_torus_nearest_checked(major, minor, origin, direction, t_min, t_max, t);
}

void toroid_torus_normal(double major, double minor, const double point[3], double normal[3]) noexcept {
  if (normal == nullptr) return;
  if (point == nullptr) {
    normal[0] = normal[1] = normal[2] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  toroid::torus_unit_normal(major, minor, point, normal);
}

void toroid_torus_intersect_batch(double major, double minor, size_t n, const double* origins, const double* directions,
                                  int* counts, double* roots) noexcept {
  if (n == 0) return;
  if (origins == nullptr || directions == nullptr || counts == nullptr || roots == nullptr) {
    for (std::size_t i = 0; counts != nullptr && i < n; ++i) counts[i] = -1;
    for (std::size_t i = 0; roots != nullptr && i < 4 * n; ++i) roots[i] = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  toroid::intersect_torus_batch(major, minor, n, origins, directions, counts, roots);
}

}  // extern "C"
