// SPDX-License-Identifier: Apache-2.0
// Intersections of a ray with shapes, and the hit (RTC chapters 5 and 6).
#pragma once

#include <vector>

namespace toroid {

class Shape;

struct Intersection {
  double t = 0;
  const Shape* object = nullptr;
  // Barycentric coordinates, used by smooth triangles (RTC chapter 15).
  double u = 0, v = 0;
};

// Shapes append to this; the world sorts it once per ray.
using Intersections = std::vector<Intersection>;

// The visible intersection: the lowest non-negative t, or nullptr.
// Works on unsorted lists.
const Intersection* hit(const Intersections& xs);

// Sorts by t, ascending.
void sort_intersections(Intersections& xs);

}  // namespace toroid
