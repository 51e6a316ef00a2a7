// SPDX-License-Identifier: Apache-2.0
// triangles.feature
#include "toroid/shapes/triangle.h"

#include <gtest/gtest.h>

#include "support/approx.h"

namespace toroid {
namespace {

Triangle book_triangle() { return Triangle(point(0, 1, 0), point(-1, 0, 0), point(1, 0, 0)); }

Intersections local_intersect(const Shape& s, const Ray& r) {
  Intersections xs;
  s.local_intersect(r, xs);
  return xs;
}

TEST(Triangles, ConstructingATriangle) {
  const Tuple p1 = point(0, 1, 0);
  const Tuple p2 = point(-1, 0, 0);
  const Tuple p3 = point(1, 0, 0);
  const Triangle t(p1, p2, p3);
  EXPECT_APPROX(t.p1(), p1);
  EXPECT_APPROX(t.p2(), p2);
  EXPECT_APPROX(t.p3(), p3);
  EXPECT_APPROX(t.e1(), vector(-1, -1, 0));
  EXPECT_APPROX(t.e2(), vector(1, -1, 0));
  EXPECT_APPROX(t.normal(), vector(0, 0, -1));
}

TEST(Triangles, IntersectingARayParallelToTheTriangle) {
  EXPECT_TRUE(local_intersect(book_triangle(), {point(0, -1, -2), vector(0, 1, 0)}).empty());
}

TEST(Triangles, ARayMissesTheP1P3Edge) {
  EXPECT_TRUE(local_intersect(book_triangle(), {point(1, 1, -2), vector(0, 0, 1)}).empty());
}

TEST(Triangles, ARayMissesTheP1P2Edge) {
  EXPECT_TRUE(local_intersect(book_triangle(), {point(-1, 1, -2), vector(0, 0, 1)}).empty());
}

TEST(Triangles, ARayMissesTheP2P3Edge) {
  EXPECT_TRUE(local_intersect(book_triangle(), {point(0, -1, -2), vector(0, 0, 1)}).empty());
}

TEST(Triangles, ARayStrikesATriangle) {
  const Triangle t = book_triangle();
  const Intersections xs = local_intersect(t, {point(0, 0.5, -2), vector(0, 0, 1)});
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_NEAR(xs[0].t, 2, kEpsilon);
  EXPECT_EQ(xs[0].object, &t);
}

TEST(Triangles, FindingTheNormalOnATriangle) {
  const Triangle t = book_triangle();
  EXPECT_APPROX(t.local_normal_at(point(0, 0.5, 0), {}), t.normal());
  EXPECT_APPROX(t.local_normal_at(point(-0.5, 0.75, 0), {}), t.normal());
  EXPECT_APPROX(t.local_normal_at(point(0.5, 0.25, 0), {}), t.normal());
}

// Not in the book: its absolute EPSILON on the determinant loses small
// triangles; the relative test keeps them.
TEST(Triangles, ATinyTriangleIsStillHit) {
  const Triangle t(point(0, 1e-4, 0), point(-1e-4, 0, 0), point(1e-4, 0, 0));
  const Intersections xs = local_intersect(t, {point(0, 0.5e-4, -2), vector(0, 0, 1)});
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_NEAR(xs[0].t, 2, kEpsilon);
}

}  // namespace
}  // namespace toroid
