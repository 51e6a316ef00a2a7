// SPDX-License-Identifier: Apache-2.0
// planes.feature
#include "toroid/shapes/plane.h"

#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <memory>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/group.h"

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

namespace toroid {
namespace {

// The normal through the transforms, as Shape::normal_at computes it for
// every shape: what Plane::normal_at must give, bit for bit.
Tuple normal_through_transforms(const Plane& p, const Tuple& world_point) {
  return p.normal_to_world(p.local_normal_at(p.world_to_object(world_point), {}));
}

void expect_same_bits(const Tuple& a, const Tuple& b) {
  EXPECT_EQ(std::memcmp(&a, &b, sizeof(Tuple)), 0) << a << " vs " << b;
}

TEST(PlaneNormals, AtTheTopLevelTheKeptNormalIsTheOneThroughTheTransforms) {
  Plane p;
  expect_same_bits(p.normal_at(point(3, 0, -2)), vector(0, 1, 0));
  // A transform that rounds: the kept normal follows every set_transform.
  p.set_transform(rotation_y(0.31415) * rotation_z(1.5708) * scaling(2, 0.3, 5));
  for (const Tuple& at : {point(0, 0, 0), point(1e6, -3, 7), point(-0.1, 0.2, 0.3)})
    expect_same_bits(p.normal_at(at), normal_through_transforms(p, at));
  const Tuple before = p.normal_at(point(0, 0, 0));
  p.set_transform(rotation_x(1.5708) * translation(0, 0, 5));
  expect_same_bits(p.normal_at(point(0, 0, 0)), normal_through_transforms(p, point(0, 0, 0)));
  EXPECT_FALSE(approx_equal(p.normal_at(point(0, 0, 0)), before));
}

TEST(PlaneNormals, InsideAGroupTheParentsTransformsCountEvenWhenTheyChangeLater) {
  auto g = std::make_shared<Group>();
  auto p = std::make_shared<Plane>();
  p->set_transform(rotation_z(0.5));
  g->add_child(p);
  g->set_transform(rotation_x(1.0));
  expect_same_bits(p->normal_at(point(1, 2, 3)), normal_through_transforms(*p, point(1, 2, 3)));
  EXPECT_FALSE(approx_equal(p->normal_at(point(1, 2, 3)), p->normal_to_parent(vector(0, 1, 0))));
}

}  // namespace
}  // namespace toroid
