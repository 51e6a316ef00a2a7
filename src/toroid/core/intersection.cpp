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
  // A ray's list is short: an insertion sort, which is what std::sort does
  // below 17 elements (stable, so the same order of equal t), without its
  // set-up.
  constexpr std::size_t kShort = 16;
  if (xs.size() > kShort) {
    std::sort(xs.begin(), xs.end(), [](const Intersection& a, const Intersection& b) { return a.t < b.t; });
    return;
  }
  for (std::size_t i = 1; i < xs.size(); ++i) {
    const Intersection x = xs[i];
    std::size_t j = i;
    for (; j > 0 && x.t < xs[j - 1].t; --j) xs[j] = xs[j - 1];
    xs[j] = x;
  }
}

}  // namespace toroid
