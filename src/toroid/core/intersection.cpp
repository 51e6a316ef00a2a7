// SPDX-License-Identifier: Apache-2.0
#include "toroid/core/intersection.h"

#include <algorithm>

namespace toroid {

const Intersection* hit(const Intersections& xs) {
  const Intersection* best = nullptr;
  for (const Intersection& x : xs)
    if (x.t >= 0 && (best == nullptr || x.t < best->t)) best = &x;
  return best;
}

void sort_intersections(Intersections& xs) {
  std::sort(xs.begin(), xs.end(), [](const Intersection& a, const Intersection& b) { return a.t < b.t; });
}

}  // namespace toroid
