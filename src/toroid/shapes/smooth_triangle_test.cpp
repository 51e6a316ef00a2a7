// SPDX-License-Identifier: Apache-2.0
// smooth-triangles.feature
#include "toroid/shapes/smooth_triangle.h"

#include <gtest/gtest.h>

#include "support/approx.h"
#include "support/smooth_triangle_background.h"

namespace toroid {
namespace {

TEST_F(SmoothTriangles, ConstructingASmoothTriangle) {
  EXPECT_APPROX(tri.p1(), p1);
  EXPECT_APPROX(tri.p2(), p2);
  EXPECT_APPROX(tri.p3(), p3);
  EXPECT_APPROX(tri.n1(), n1);
  EXPECT_APPROX(tri.n2(), n2);
  EXPECT_APPROX(tri.n3(), n3);
}

TEST_F(SmoothTriangles, AnIntersectionWithASmoothTriangleStoresUV) {
  Intersections xs;
  tri.local_intersect({point(-0.2, 0.3, -2), vector(0, 0, 1)}, xs);
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_NEAR(xs[0].u, 0.45, kEpsilon);
  EXPECT_NEAR(xs[0].v, 0.25, kEpsilon);
}

TEST_F(SmoothTriangles, ASmoothTriangleUsesUVToInterpolateTheNormal) {
  const Intersection i{1, &tri, 0.45, 0.25};
  EXPECT_APPROX(tri.normal_at(point(0, 0, 0), i), vector(-0.5547, 0.83205, 0));
}

}  // namespace
}  // namespace toroid
