// SPDX-License-Identifier: Apache-2.0
// groups.feature; the group scenarios of shapes.feature (suite Shapes); the
// bonus chapter's group scenarios from bounding_boxes.CraigTreptow-rayz.feature
// and groups_with_bvh.ShadeShiner-...feature, each distinct scenario once.
#include "toroid/shapes/group.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "support/approx.h"
#include "support/recording_shape.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/cylinder.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/triangle.h"

namespace toroid {
namespace {

using testing::RecordingShape;

// The book prints these expectations to four decimals.
constexpr double kBookDigits = 1e-4;

std::shared_ptr<Sphere> sphere_with(const Matrix4& transform) {
  auto s = std::make_shared<Sphere>();
  s->set_transform(transform);
  return s;
}

std::shared_ptr<Group> group_of(const ShapeList& children) {
  auto g = std::make_shared<Group>();
  for (const auto& c : children) g->add_child(c);
  return g;
}

// "x is a group of [children]".
void expect_group_of(const std::shared_ptr<Shape>& shape, const ShapeList& children) {
  const auto* g = dynamic_cast<const Group*>(shape.get());
  ASSERT_NE(g, nullptr) << "not a group";
  EXPECT_EQ(g->children(), children);
}

Intersections intersect_sorted(const Shape& s, const Ray& r, bool local) {
  Intersections xs;
  if (local) {
    s.local_intersect(r, xs);
  } else {
    s.intersect(r, xs);
  }
  sort_intersections(xs);
  return xs;
}

// --- groups.feature -------------------------------------------------------

TEST(Groups, CreatingANewGroup) {
  const Group g;
  EXPECT_APPROX(g.transform(), Matrix4::identity());
  EXPECT_TRUE(g.empty());
}

TEST(Groups, AddingAChildToAGroup) {
  Group g;
  auto s = std::make_shared<RecordingShape>();
  g.add_child(s);
  EXPECT_FALSE(g.empty());
  EXPECT_TRUE(g.includes(s.get()));
  EXPECT_EQ(s->parent, &g);
}

TEST(Groups, IntersectingARayWithAnEmptyGroup) {
  const Group g;
  EXPECT_TRUE(intersect_sorted(g, {point(0, 0, 0), vector(0, 0, 1)}, true).empty());
}

TEST(Groups, IntersectingARayWithANonemptyGroup) {
  Group g;
  auto s1 = std::make_shared<Sphere>();
  auto s2 = sphere_with(translation(0, 0, -3));
  auto s3 = sphere_with(translation(5, 0, 0));
  g.add_child(s1);
  g.add_child(s2);
  g.add_child(s3);
  const Intersections xs = intersect_sorted(g, {point(0, 0, -5), vector(0, 0, 1)}, true);
  ASSERT_EQ(xs.size(), 4u);
  EXPECT_EQ(xs[0].object, s2.get());
  EXPECT_EQ(xs[1].object, s2.get());
  EXPECT_EQ(xs[2].object, s1.get());
  EXPECT_EQ(xs[3].object, s1.get());
}

TEST(Groups, IntersectingATransformedGroup) {
  Group g;
  g.set_transform(scaling(2, 2, 2));
  g.add_child(sphere_with(translation(5, 0, 0)));
  EXPECT_EQ(intersect_sorted(g, {point(10, 0, -10), vector(0, 0, 1)}, false).size(), 2u);
}

// --- bonus chapter: bounding boxes and the BVH ------------------------------

TEST(Groups, AGroupHasABoundingBoxThatContainsItsChildren) {
  auto s = sphere_with(translation(2, 5, -3) * scaling(2, 2, 2));
  auto c = std::make_shared<Cylinder>();
  c->minimum = -2;
  c->maximum = 2;
  c->set_transform(translation(-4, -1, 4) * scaling(0.5, 1, 0.5));
  Group shape;
  shape.add_child(s);
  shape.add_child(c);
  const BoundingBox box = shape.bounds();
  EXPECT_APPROX(box.min, point(-4.5, -3, -5));
  EXPECT_APPROX(box.max, point(4, 7, 4.5));
}

TEST(Groups, IntersectingRayGroupDoesntTestChildrenIfBoxIsMissed) {
  auto child = std::make_shared<RecordingShape>();
  Group shape;
  shape.add_child(child);
  Intersections xs;
  shape.intersect({point(0, 0, -5), vector(0, 1, 0)}, xs);
  EXPECT_FALSE(child->saved_ray.has_value());
}

TEST(Groups, IntersectingRayGroupTestsChildrenIfBoxIsHit) {
  auto child = std::make_shared<RecordingShape>();
  Group shape;
  shape.add_child(child);
  Intersections xs;
  shape.intersect({point(0, 0, -5), vector(0, 0, 1)}, xs);
  EXPECT_TRUE(child->saved_ray.has_value());
}

TEST(Groups, PartitioningAGroupsChildren) {
  std::shared_ptr<Shape> s1 = sphere_with(translation(-2, 0, 0));
  std::shared_ptr<Shape> s2 = sphere_with(translation(2, 0, 0));
  std::shared_ptr<Shape> s3 = std::make_shared<Sphere>();
  auto g = group_of({s1, s2, s3});
  const auto [left, right] = g->partition_children();
  EXPECT_EQ(g->children(), ShapeList{s3});
  EXPECT_EQ(left, ShapeList{s1});
  EXPECT_EQ(right, ShapeList{s2});
}

TEST(Groups, CreatingASubGroupFromAListOfChildren) {
  std::shared_ptr<Shape> s1 = std::make_shared<Sphere>();
  std::shared_ptr<Shape> s2 = std::make_shared<Sphere>();
  Group g;
  g.make_subgroup({s1, s2});
  ASSERT_EQ(g.size(), 1u);
  expect_group_of(g.children()[0], {s1, s2});
  EXPECT_EQ(s1->parent, g.children()[0].get());
}

TEST(Groups, SubdividingAGroupPartitionsItsChildren) {
  std::shared_ptr<Shape> s1 = sphere_with(translation(-2, -2, 0));
  std::shared_ptr<Shape> s2 = sphere_with(translation(-2, 2, 0));
  std::shared_ptr<Shape> s3 = sphere_with(scaling(4, 4, 4));
  auto g = group_of({s1, s2, s3});
  g->divide(1);
  ASSERT_EQ(g->size(), 2u);
  EXPECT_EQ(g->children()[0], s3);
  const auto* subgroup = dynamic_cast<const Group*>(g->children()[1].get());
  ASSERT_NE(subgroup, nullptr);
  ASSERT_EQ(subgroup->size(), 2u);
  expect_group_of(subgroup->children()[0], {s1});
  expect_group_of(subgroup->children()[1], {s2});
}

TEST(Groups, SubdividingAGroupWithTooFewChildren) {
  std::shared_ptr<Shape> s1 = sphere_with(translation(-2, 0, 0));
  std::shared_ptr<Shape> s2 = sphere_with(translation(2, 1, 0));
  std::shared_ptr<Shape> s3 = sphere_with(translation(2, -1, 0));
  auto subgroup = group_of({s1, s2, s3});
  std::shared_ptr<Shape> s4 = std::make_shared<Sphere>();
  auto g = group_of({subgroup, s4});
  g->divide(3);
  ASSERT_EQ(g->size(), 2u);
  EXPECT_EQ(g->children()[0], subgroup);
  EXPECT_EQ(g->children()[1], s4);
  ASSERT_EQ(subgroup->size(), 2u);
  expect_group_of(subgroup->children()[0], {s1});
  expect_group_of(subgroup->children()[1], {s2, s3});
}

// --- not in the features: the cached bounds and the BVH's robustness --------

TEST(Groups, BoundsFollowChildrenChangedAfterAdding) {
  auto inner = std::make_shared<Group>();
  Group outer;
  outer.add_child(inner);
  EXPECT_TRUE(outer.bounds().empty());
  auto s = std::make_shared<Sphere>();
  inner->add_child(s);  // a grandchild arrives after the child was added
  EXPECT_APPROX(outer.bounds().max, point(1, 1, 1));
  s->set_transform(translation(10, 0, 0));  // a grandchild moves
  EXPECT_APPROX(outer.bounds().min, point(9, -1, -1));
  EXPECT_APPROX(outer.bounds().max, point(11, 1, 1));
  Intersections xs;
  outer.intersect({point(10, 0, -5), vector(0, 0, 1)}, xs);
  EXPECT_EQ(xs.size(), 2u);
}

TEST(Groups, DividingCoincidentChildrenTerminates) {
  ShapeList same;
  // Degenerate triangles: every box is the same single point, so no split
  // can separate them (the book's divide would recurse forever).
  for (int i = 0; i < 10; ++i)
    same.push_back(std::make_shared<Triangle>(point(1, 1, 1), point(1, 1, 1), point(1, 1, 1)));
  auto g = group_of(same);
  g->divide(2);
  EXPECT_EQ(g->size(), 10u);
}

TEST(Groups, DividingChildrenThatAllStraddleTheSplitTerminates) {
  // Long spheres stacked in y: the box is widest in x, the split is at x = 0,
  // and every child crosses it, so neither half takes any (a lathed mesh's
  // ring of triangles around its axis does this).
  ShapeList straddling;
  for (int i = 0; i < 10; ++i) straddling.push_back(sphere_with(translation(0, 2.0 * i, 0) * scaling(20, 1, 1)));
  auto g = group_of(straddling);
  g->divide(2);
  EXPECT_EQ(g->children(), straddling);
}

TEST(Groups, DividingKeepsEveryIntersection) {
  Group flat;
  auto bvh = std::make_shared<Group>();
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      const Matrix4 m = translation(3.0 * i, 3.0 * j, 0.05 * (i + j));
      flat.add_child(sphere_with(m));
      bvh->add_child(sphere_with(m));
    }
  bvh->divide(2);
  EXPECT_LT(bvh->size(), 64u);
  EXPECT_APPROX(bvh->bounds().min, flat.bounds().min);
  EXPECT_APPROX(bvh->bounds().max, flat.bounds().max);
  for (int i = 0; i < 8; ++i) {
    const Ray r{point(3.0 * i + 0.5, -5, 0), vector(0, 1, 0)};
    const Intersections a = intersect_sorted(flat, r, false);
    const Intersections b = intersect_sorted(*bvh, r, false);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.size(), 16u);
    for (std::size_t k = 0; k < a.size(); ++k) EXPECT_NEAR(a[k].t, b[k].t, kEpsilon);
  }
}

// Found by fuzzing the OBJ loader: copies of one triangle all straddle every
// split, and dividing them used to recurse until the stack overflowed.
TEST(Groups, DividingChildrenThatAllStraddleTheSplitEnds) {
  Group g;
  for (int i = 0; i < 6; ++i) g.add_child(std::make_shared<Triangle>(point(-1, 0, 0), point(1, 0, 0), point(0, 1, 0)));
  g.divide(4);
  EXPECT_EQ(g.size(), 6u);  // nothing separates them: they stay together
}

TEST(Groups, AGroupHasNoNormalOfItsOwn) {
  const Group g;
  EXPECT_THROW(g.local_normal_at(point(0, 0, 0), {}), std::logic_error);
}

// --- shapes.feature: the scenarios about shapes inside groups ---------------

TEST(Shapes, ConvertingAPointFromWorldToObjectSpace) {
  auto g1 = std::make_shared<Group>();
  g1->set_transform(rotation_y(std::numbers::pi / 2));
  auto g2 = std::make_shared<Group>();
  g2->set_transform(scaling(2, 2, 2));
  g1->add_child(g2);
  auto s = sphere_with(translation(5, 0, 0));
  g2->add_child(s);
  EXPECT_APPROX(s->world_to_object(point(-2, 0, -10)), point(0, 0, -1));
}

TEST(Shapes, ConvertingANormalFromObjectToWorldSpace) {
  auto g1 = std::make_shared<Group>();
  g1->set_transform(rotation_y(std::numbers::pi / 2));
  auto g2 = std::make_shared<Group>();
  g2->set_transform(scaling(1, 2, 3));
  g1->add_child(g2);
  auto s = sphere_with(translation(5, 0, 0));
  g2->add_child(s);
  const double k = std::sqrt(3.0) / 3;
  const Tuple n = s->normal_to_world(vector(k, k, k));
  EXPECT_TRUE(approx_equal(n, vector(0.2857, 0.4286, -0.8571), kBookDigits)) << n;
}

TEST(Shapes, FindingTheNormalOnAChildObject) {
  auto g1 = std::make_shared<Group>();
  g1->set_transform(rotation_y(std::numbers::pi / 2));
  auto g2 = std::make_shared<Group>();
  g2->set_transform(scaling(1, 2, 3));
  g1->add_child(g2);
  auto s = sphere_with(translation(5, 0, 0));
  g2->add_child(s);
  const Tuple n = s->normal_at(point(1.7321, 1.1547, -5.5774));
  EXPECT_TRUE(approx_equal(n, vector(0.2857, 0.4286, -0.8571), kBookDigits)) << n;
}

}  // namespace
}  // namespace toroid
