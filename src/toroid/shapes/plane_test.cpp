// planes.feature
#include "toroid/shapes/plane.h"

#include <gtest/gtest.h>

#include <limits>

#include "support/approx.h"

namespace toroid {
namespace {

Intersections local_intersect(const Shape& s, const Ray& r) {
  Intersections xs;
  s.local_intersect(r, xs);
  return xs;
}

TEST(Planes, TheNormalOfAPlaneIsConstantEverywhere) {
  const Plane p;
  const Tuple n1 = p.local_normal_at(point(0, 0, 0), {});
  const Tuple n2 = p.local_normal_at(point(10, 0, -10), {});
  const Tuple n3 = p.local_normal_at(point(-5, 0, 150), {});
  EXPECT_APPROX(n1, vector(0, 1, 0));
  EXPECT_APPROX(n2, vector(0, 1, 0));
  EXPECT_APPROX(n3, vector(0, 1, 0));
}

TEST(Planes, IntersectWithARayParallelToThePlane) {
  const Plane p;
  const Ray r{point(0, 10, 0), vector(0, 0, 1)};
  EXPECT_TRUE(local_intersect(p, r).empty());
}

TEST(Planes, IntersectWithACoplanarRay) {
  const Plane p;
  const Ray r{point(0, 0, 0), vector(0, 0, 1)};
  EXPECT_TRUE(local_intersect(p, r).empty());
}

TEST(Planes, ARayIntersectingAPlaneFromAbove) {
  const Plane p;
  const Ray r{point(0, 1, 0), vector(0, -1, 0)};
  const Intersections xs = local_intersect(p, r);
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_APPROX(xs[0].t, 1.0);
  EXPECT_EQ(xs[0].object, &p);
}

TEST(Planes, ARayIntersectingAPlaneFromBelow) {
  const Plane p;
  const Ray r{point(0, -1, 0), vector(0, 1, 0)};
  const Intersections xs = local_intersect(p, r);
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_APPROX(xs[0].t, 1.0);
  EXPECT_EQ(xs[0].object, &p);
}

}  // namespace
}  // namespace toroid

namespace toroid {
namespace {

// bonus bounding_boxes.feature
TEST(BoundingBoxes, APlaneHasABoundingBox) {
  const Plane shape;
  const BoundingBox box = shape.bounds();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(box.min.x, -inf);
  EXPECT_EQ(box.min.y, 0);
  EXPECT_EQ(box.min.z, -inf);
  EXPECT_EQ(box.max.x, inf);
  EXPECT_EQ(box.max.y, 0);
  EXPECT_EQ(box.max.z, inf);
}

}  // namespace
}  // namespace toroid
