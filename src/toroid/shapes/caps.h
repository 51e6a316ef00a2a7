// SPDX-License-Identifier: Apache-2.0
// End caps shared by the cylinder and the cone (RTC chapter 13).
#pragma once

#include "toroid/core/ray.h"

namespace toroid::detail {

// Whether the ray at t lies within `radius` of the y axis.
inline bool within_cap(const Ray& ray, double t, double radius) {
  const double x = ray.origin.x + t * ray.direction.x;
  const double z = ray.origin.z + t * ray.direction.z;
  return x * x + z * z <= radius * radius;
}

}  // namespace toroid::detail
