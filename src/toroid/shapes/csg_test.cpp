// SPDX-License-Identifier: Apache-2.0
// csg.feature, plus smoke tests of CSG over operands whose intersections
// arrive unsorted (groups) and of the bonus chapter's CSG bounds.
#include "toroid/shapes/csg.h"

#include <gtest/gtest.h>

#include "support/approx.h"
#include "support/csg_operands.h"
#include "support/recording_shape.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/sphere.h"

namespace toroid {
namespace {

using testing::local_intersections_of;
using testing::sphere_with;

TEST(Csg, CsgIsCreatedWithAnOperationAndTwoShapes) {
  auto s1 = std::make_shared<Sphere>();
  auto s2 = std::make_shared<Cube>();
  const Csg c(CsgOp::Union, s1, s2);
  EXPECT_EQ(c.operation(), CsgOp::Union);
  EXPECT_EQ(c.left(), s1);
  EXPECT_EQ(c.right(), s2);
  EXPECT_EQ(s1->parent, &c);
  EXPECT_EQ(s2->parent, &c);
}

TEST(Csg, EvaluatingTheRuleForACsgOperation) {
  struct Example {
    CsgOp op;
    bool lhit, inl, inr, result;
  };
  constexpr auto U = CsgOp::Union;
  constexpr auto I = CsgOp::Intersection;
  constexpr auto D = CsgOp::Difference;
  const Example examples[] = {
      {U, true, true, true, false},    {U, true, true, false, true},   {U, true, false, true, false},
      {U, true, false, false, true},   {U, false, true, true, false},  {U, false, true, false, false},
      {U, false, false, true, true},   {U, false, false, false, true}, {I, true, true, true, true},
      {I, true, true, false, false},   {I, true, false, true, true},   {I, true, false, false, false},
      {I, false, true, true, true},    {I, false, true, false, true},  {I, false, false, true, false},
      {I, false, false, false, false}, {D, true, true, true, false},   {D, true, true, false, true},
      {D, true, false, true, false},   {D, true, false, false, true},  {D, false, true, true, true},
      {D, false, true, false, true},   {D, false, false, true, false}, {D, false, false, false, false},
  };
  for (const Example& e : examples)
    EXPECT_EQ(intersection_allowed(e.op, e.lhit, e.inl, e.inr), e.result)
        << "op " << static_cast<int>(e.op) << " lhit " << e.lhit << " inl " << e.inl << " inr " << e.inr;
}

TEST(Csg, FilteringAListOfIntersections) {
  testing::expect_filtering_a_list_of_intersections(
      [](CsgOp op, std::shared_ptr<Shape> s1, std::shared_ptr<Shape> s2) { return std::make_shared<Csg>(op, s1, s2); });
}

TEST(Csg, ARayMissesACsgObject) {
  const Csg c(CsgOp::Union, std::make_shared<Sphere>(), std::make_shared<Cube>());
  EXPECT_TRUE(local_intersections_of(c, {point(0, 2, -5), vector(0, 0, 1)}).empty());
}

TEST(Csg, ARayHitsACsgObject) {
  auto s1 = std::make_shared<Sphere>();
  auto s2 = sphere_with(translation(0, 0, 0.5));
  const Csg c(CsgOp::Union, s1, s2);
  const Intersections xs = local_intersections_of(c, {point(0, 0, -5), vector(0, 0, 1)});
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0].t, 4, kEpsilon);
  EXPECT_EQ(xs[0].object, s1.get());
  EXPECT_NEAR(xs[1].t, 6.5, kEpsilon);
  EXPECT_EQ(xs[1].object, s2.get());
}

// --- not in csg.feature --------------------------------------------------

// The bonus chapter's CSG scenarios (absent from the community feature files).
TEST(Csg, ACsgShapeHasABoundingBoxThatContainsItsChildren) {
  auto left = std::make_shared<Sphere>();
  auto right = sphere_with(translation(2, 3, 4));
  const Csg shape(CsgOp::Difference, left, right);
  EXPECT_APPROX(shape.bounds().min, point(-1, -1, -1));
  EXPECT_APPROX(shape.bounds().max, point(3, 4, 5));
}

TEST(Csg, IntersectingRayCsgDoesntTestChildrenIfBoxIsMissed) {
  auto left = std::make_shared<testing::RecordingShape>();
  auto right = std::make_shared<testing::RecordingShape>();
  const Csg shape(CsgOp::Difference, left, right);
  Intersections xs;
  shape.intersect({point(0, 0, -5), vector(0, 1, 0)}, xs);
  EXPECT_FALSE(left->saved_ray.has_value());
  EXPECT_FALSE(right->saved_ray.has_value());
}

TEST(Csg, IntersectingRayCsgTestsChildrenIfBoxIsHit) {
  auto left = std::make_shared<testing::RecordingShape>();
  auto right = std::make_shared<testing::RecordingShape>();
  const Csg shape(CsgOp::Difference, left, right);
  Intersections xs;
  shape.intersect({point(0, 0, -5), vector(0, 0, 1)}, xs);
  EXPECT_TRUE(left->saved_ray.has_value());
  EXPECT_TRUE(right->saved_ray.has_value());
}

TEST(Csg, SubdividingACsgShapeSubdividesItsChildren) {
  std::shared_ptr<Shape> s1 = sphere_with(translation(-1.5, 0, 0));
  std::shared_ptr<Shape> s2 = sphere_with(translation(1.5, 0, 0));
  auto left = std::make_shared<Group>();
  left->add_child(s1);
  left->add_child(s2);
  std::shared_ptr<Shape> s3 = sphere_with(translation(0, 0, -1.5));
  std::shared_ptr<Shape> s4 = sphere_with(translation(0, 0, 1.5));
  auto right = std::make_shared<Group>();
  right->add_child(s3);
  right->add_child(s4);
  Csg shape(CsgOp::Difference, left, right);
  shape.divide(1);
  ASSERT_EQ(left->size(), 2u);
  EXPECT_EQ(dynamic_cast<const Group&>(*left->children()[0]).children(), ShapeList{s1});
  EXPECT_EQ(dynamic_cast<const Group&>(*left->children()[1]).children(), ShapeList{s2});
  ASSERT_EQ(right->size(), 2u);
  EXPECT_EQ(dynamic_cast<const Group&>(*right->children()[0]).children(), ShapeList{s3});
  EXPECT_EQ(dynamic_cast<const Group&>(*right->children()[1]).children(), ShapeList{s4});
}

// Smoke tests: the operands are groups whose children were added far side
// first, so each operand reports its intersections out of order; CSG must
// sort them before filtering.
std::shared_ptr<Group> reversed_pair(double z_far, double z_near) {
  auto g = std::make_shared<Group>();
  g->add_child(sphere_with(translation(0, 0, z_far)));
  g->add_child(sphere_with(translation(0, 0, z_near)));
  return g;
}

TEST(Csg, SmokeDifferenceOfGroupsWithUnsortedIntersections) {
  // Left: unit spheres at z = 0 and z = 6 (surfaces -1..1 and 5..7 along z).
  // Right: unit spheres at z = 0.5 and z = 6.5 carve the back of each.
  const Csg c(CsgOp::Difference, reversed_pair(6, 0), reversed_pair(6.5, 0.5));
  Intersections xs;
  c.intersect({point(0, 0, -5), vector(0, 0, 1)}, xs);
  ASSERT_EQ(xs.size(), 4u);
  const double expected[] = {4, 4.5, 10, 10.5};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(xs[i].t, expected[i], kEpsilon) << i;
  // Entering surfaces come from the left operand, exits from the right one.
  EXPECT_TRUE(c.left()->includes(xs[0].object));
  EXPECT_TRUE(c.right()->includes(xs[1].object));
  EXPECT_TRUE(c.left()->includes(xs[2].object));
  EXPECT_TRUE(c.right()->includes(xs[3].object));
}

TEST(Csg, SmokeIntersectionAndUnionOfGroups) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  {
    const Csg c(CsgOp::Intersection, reversed_pair(6, 0), reversed_pair(6.5, 0.5));
    Intersections xs;
    c.intersect(r, xs);
    ASSERT_EQ(xs.size(), 4u);
    const double expected[] = {4.5, 6, 10.5, 12};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(xs[i].t, expected[i], kEpsilon) << i;
  }
  {
    const Csg c(CsgOp::Union, reversed_pair(6, 0), reversed_pair(6.5, 0.5));
    Intersections xs;
    c.intersect(r, xs);
    ASSERT_EQ(xs.size(), 4u);
    const double expected[] = {4, 6.5, 10, 12.5};
    for (std::size_t i = 0; i < 4; ++i) EXPECT_NEAR(xs[i].t, expected[i], kEpsilon) << i;
  }
}

TEST(Csg, SmokeCsgLeavesEarlierIntersectionsAlone) {
  Group world;
  auto before = sphere_with(translation(0, 0, 20));
  world.add_child(before);
  world.add_child(
      std::make_shared<Csg>(CsgOp::Difference, std::make_shared<Sphere>(), sphere_with(translation(0, 0, 0.5))));
  Intersections xs;
  world.intersect({point(0, 0, -5), vector(0, 0, 1)}, xs);
  ASSERT_EQ(xs.size(), 4u);
  // The sphere's two intersections come first, untouched by the CSG's sort
  // and filter, which only see what the CSG appended.
  EXPECT_NEAR(xs[0].t, 24, kEpsilon);
  EXPECT_NEAR(xs[1].t, 26, kEpsilon);
  EXPECT_NEAR(xs[2].t, 4, kEpsilon);
  EXPECT_NEAR(xs[3].t, 4.5, kEpsilon);
}

TEST(Csg, SmokeNestedCsg) {
  // (sphere - cube scaled to a slab) inside a union with a far sphere.
  auto slab = std::make_shared<Cube>();
  slab->set_transform(scaling(2, 2, 0.25));
  auto inner = std::make_shared<Csg>(CsgOp::Difference, std::make_shared<Sphere>(), slab);
  const Csg outer(CsgOp::Union, inner, sphere_with(translation(0, 0, 3)));
  Intersections xs;
  outer.intersect({point(0, 0, -5), vector(0, 0, 1)}, xs);
  ASSERT_EQ(xs.size(), 6u);
  const double expected[] = {4, 4.75, 5.25, 6, 7, 9};
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(xs[i].t, expected[i], kEpsilon) << i;
}

}  // namespace
}  // namespace toroid
