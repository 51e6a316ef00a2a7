// SPDX-License-Identifier: Apache-2.0
// smooth-triangles.feature: the scenario that goes through prepare_computations.
#include <gtest/gtest.h>

#include "support/approx.h"
#include "support/smooth_triangle_background.h"
#include "toroid/render/computations.h"

namespace toroid {
namespace {

TEST_F(SmoothTriangles, PreparingTheNormalOnASmoothTriangle) {
  const Intersection i{1, &tri, 0.45, 0.25};
  const Ray r{point(-0.2, 0.3, -2), vector(0, 0, 1)};
  const Intersections xs{i};
  const Computations comps = prepare_computations(i, r, xs);
  EXPECT_APPROX(comps.normalv, vector(-0.5547, 0.83205, 0));
}

}  // namespace
}  // namespace toroid
