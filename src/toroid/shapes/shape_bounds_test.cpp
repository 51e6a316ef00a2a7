// SPDX-License-Identifier: Apache-2.0
// Bonus chapter "Bounding boxes and hierarchies", community transcriptions:
// bounding_boxes.CraigTreptow-rayz.feature, bounds.ShadeShiner-...feature and
// bounds.bedis-elacheche.feature, each distinct scenario once. The group
// scenarios are in group_test.cpp.
#include "toroid/core/bounds.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/approx.h"
#include "support/recording_shape.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/cone.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/cylinder.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/triangle.h"

namespace toroid {
namespace {

constexpr double kInf = BoundingBox::kInf;

// gtest's EXPECT_APPROX on points with infinite components would compute
// inf - inf; compare component by component instead.
::testing::AssertionResult SameCorner(const char* a_expr, const char* b_expr, const Tuple& a, const Tuple& b) {
  auto same = [](double x, double y) { return x == y || std::abs(x - y) < kEpsilon; };
  if (same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z) && a.w == b.w) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a_expr << " = " << a << "\n  expected " << b_expr << " = " << b;
}
#define EXPECT_CORNER(a, b) EXPECT_PRED_FORMAT2(SameCorner, a, b)

TEST(BoundingBoxes, CreatingAnEmptyBoundingBox) {
  const BoundingBox box;
  EXPECT_CORNER(box.min, point(kInf, kInf, kInf));
  EXPECT_CORNER(box.max, point(-kInf, -kInf, -kInf));
  EXPECT_TRUE(box.empty());
}

TEST(BoundingBoxes, CreatingABoundingBoxWithVolume) {
  const BoundingBox box{point(-1, -2, -3), point(3, 2, 1)};
  EXPECT_APPROX(box.min, point(-1, -2, -3));
  EXPECT_APPROX(box.max, point(3, 2, 1));
  EXPECT_FALSE(box.empty());
}

TEST(BoundingBoxes, AddingPointsToAnEmptyBoundingBox) {
  BoundingBox box;
  box.add_point(point(-5, 2, 0));
  box.add_point(point(7, 0, -3));
  EXPECT_APPROX(box.min, point(-5, 0, -3));
  EXPECT_APPROX(box.max, point(7, 2, 0));
}

TEST(BoundingBoxes, ASphereHasABoundingBox) {
  const BoundingBox box = Sphere().bounds();
  EXPECT_APPROX(box.min, point(-1, -1, -1));
  EXPECT_APPROX(box.max, point(1, 1, 1));
}

TEST(BoundingBoxes, ACubeHasABoundingBox) {
  const BoundingBox box = Cube().bounds();
  EXPECT_APPROX(box.min, point(-1, -1, -1));
  EXPECT_APPROX(box.max, point(1, 1, 1));
}

TEST(BoundingBoxes, AnUnboundedCylinderHasABoundingBox) {
  const BoundingBox box = Cylinder().bounds();
  EXPECT_CORNER(box.min, point(-1, -kInf, -1));
  EXPECT_CORNER(box.max, point(1, kInf, 1));
}

TEST(BoundingBoxes, ABoundedCylinderHasABoundingBox) {
  Cylinder shape;
  shape.minimum = -5;
  shape.maximum = 3;
  const BoundingBox box = shape.bounds();
  EXPECT_APPROX(box.min, point(-1, -5, -1));
  EXPECT_APPROX(box.max, point(1, 3, 1));
}

TEST(BoundingBoxes, AnUnboundedConeHasABoundingBox) {
  const BoundingBox box = Cone().bounds();
  EXPECT_CORNER(box.min, point(-kInf, -kInf, -kInf));
  EXPECT_CORNER(box.max, point(kInf, kInf, kInf));
}

TEST(BoundingBoxes, ABoundedConeHasABoundingBox) {
  Cone shape;
  shape.minimum = -5;
  shape.maximum = 3;
  const BoundingBox box = shape.bounds();
  EXPECT_APPROX(box.min, point(-5, -5, -5));
  EXPECT_APPROX(box.max, point(5, 3, 5));
}

TEST(BoundingBoxes, ATriangleHasABoundingBox) {
  const Triangle shape(point(-3, 7, 2), point(6, 2, -4), point(2, -1, -1));
  const BoundingBox box = shape.bounds();
  EXPECT_APPROX(box.min, point(-3, -1, -4));
  EXPECT_APPROX(box.max, point(6, 7, 2));
}

TEST(BoundingBoxes, TestShapeHasArbitraryBounds) {
  const BoundingBox box = testing::RecordingShape().bounds();
  EXPECT_APPROX(box.min, point(-1, -1, -1));
  EXPECT_APPROX(box.max, point(1, 1, 1));
}

TEST(BoundingBoxes, AddingOneBoundingBoxToAnother) {
  BoundingBox box1{point(-5, -2, 0), point(7, 4, 4)};
  const BoundingBox box2{point(8, -7, -2), point(14, 2, 8)};
  box1.merge(box2);
  EXPECT_APPROX(box1.min, point(-5, -7, -2));
  EXPECT_APPROX(box1.max, point(14, 4, 8));
}

TEST(BoundingBoxes, CheckingToSeeIfABoxContainsAGivenPoint) {
  const BoundingBox box{point(5, -2, 0), point(11, 4, 7)};
  const std::pair<Tuple, bool> examples[] = {
      {point(5, -2, 0), true},  {point(11, 4, 7), true},  {point(8, 1, 3), true},
      {point(3, 0, 3), false},  {point(8, -4, 3), false}, {point(8, 1, -1), false},
      {point(13, 1, 3), false}, {point(8, 5, 3), false},  {point(8, 1, 8), false},
  };
  for (const auto& [p, result] : examples) EXPECT_EQ(box.contains_point(p), result) << p;
}

TEST(BoundingBoxes, CheckingToSeeIfABoxContainsAGivenBox) {
  const BoundingBox box{point(5, -2, 0), point(11, 4, 7)};
  const std::pair<BoundingBox, bool> examples[] = {
      {{point(5, -2, 0), point(11, 4, 7)}, true},
      {{point(6, -1, 1), point(10, 3, 6)}, true},
      {{point(4, -3, -1), point(10, 3, 6)}, false},
      {{point(6, -1, 1), point(12, 5, 8)}, false},
  };
  for (const auto& [b, result] : examples) EXPECT_EQ(box.contains_box(b), result) << b.min << " " << b.max;
}

TEST(BoundingBoxes, TransformingABoundingBox) {
  const BoundingBox box{point(-1, -1, -1), point(1, 1, 1)};
  const Matrix4 matrix = rotation_x(std::numbers::pi / 4) * rotation_y(std::numbers::pi / 4);
  const BoundingBox box2 = transform(box, matrix);
  EXPECT_APPROX(box2.min, point(-1.41421, -1.70710, -1.70710));
  EXPECT_APPROX(box2.max, point(1.41421, 1.70710, 1.70710));
}

// From Craig Treptow's transcription (a single ray along +x).
TEST(BoundingBoxes, IntersectingARayWithABoundingBoxAtTheOrigin) {
  const BoundingBox box{point(-1, -1, -1), point(1, 1, 1)};
  EXPECT_TRUE(box.intersects({point(-5, 0, 0), normalize(vector(1, 0, 0))}));
}

struct RayExample {
  Tuple origin, direction;
  bool result;
};

void expect_box_hits(const BoundingBox& box, const RayExample& e) {
  EXPECT_EQ(box.intersects({e.origin, normalize(e.direction)}), e.result) << e.origin << " " << e.direction;
}

TEST(BoundingBoxes, IntersectingARayWithABoundingBoxAtTheOriginExamples) {
  const BoundingBox box{point(-1, -1, -1), point(1, 1, 1)};
  const RayExample examples[] = {
      {point(5, 0.5, 0), vector(-1, 0, 0), true}, {point(-5, 0.5, 0), vector(1, 0, 0), true},
      {point(0.5, 5, 0), vector(0, -1, 0), true}, {point(0.5, -5, 0), vector(0, 1, 0), true},
      {point(0.5, 0, 5), vector(0, 0, -1), true}, {point(0.5, 0, -5), vector(0, 0, 1), true},
      {point(0, 0.5, 0), vector(0, 0, 1), true},  {point(-2, 0, 0), vector(2, 4, 6), false},
      {point(0, -2, 0), vector(6, 2, 4), false},  {point(0, 0, -2), vector(4, 6, 2), false},
      {point(2, 0, 2), vector(0, 0, -1), false},  {point(0, 2, 2), vector(0, -1, 0), false},
      {point(2, 2, 0), vector(-1, 0, 0), false},
  };
  for (const RayExample& e : examples) expect_box_hits(box, e);
}

TEST(BoundingBoxes, IntersectingARayWithANonCubicBoundingBox) {
  const BoundingBox box{point(5, -2, 0), point(11, 4, 7)};
  const RayExample examples[] = {
      {point(15, 1, 2), vector(-1, 0, 0), true},  {point(-5, -1, 4), vector(1, 0, 0), true},
      {point(7, 6, 5), vector(0, -1, 0), true},   {point(9, -5, 6), vector(0, 1, 0), true},
      {point(8, 2, 12), vector(0, 0, -1), true},  {point(6, 0, -5), vector(0, 0, 1), true},
      {point(8, 1, 3.5), vector(0, 0, 1), true},  {point(9, -1, -8), vector(2, 4, 6), false},
      {point(8, 3, -4), vector(6, 2, 4), false},  {point(9, -1, -2), vector(4, 6, 2), false},
      {point(4, 0, 9), vector(0, 0, -1), false},  {point(8, 6, -1), vector(0, -1, 0), false},
      {point(12, 5, 4), vector(-1, 0, 0), false},
  };
  for (const RayExample& e : examples) expect_box_hits(box, e);
}

void expect_split(const BoundingBox& box, const BoundingBox& left, const BoundingBox& right) {
  const auto [l, r] = box.split();
  EXPECT_APPROX(l.min, left.min);
  EXPECT_APPROX(l.max, left.max);
  EXPECT_APPROX(r.min, right.min);
  EXPECT_APPROX(r.max, right.max);
}

TEST(BoundingBoxes, SplittingAPerfectCube) {
  expect_split({point(-1, -4, -5), point(9, 6, 5)}, {point(-1, -4, -5), point(4, 6, 5)},
               {point(4, -4, -5), point(9, 6, 5)});
}

TEST(BoundingBoxes, SplittingAnXWideBox) {
  expect_split({point(-1, -2, -3), point(9, 5.5, 3)}, {point(-1, -2, -3), point(4, 5.5, 3)},
               {point(4, -2, -3), point(9, 5.5, 3)});
}

TEST(BoundingBoxes, SplittingAYWideBox) {
  expect_split({point(-1, -2, -3), point(5, 8, 3)}, {point(-1, -2, -3), point(5, 3, 3)},
               {point(-1, 3, -3), point(5, 8, 3)});
}

TEST(BoundingBoxes, SplittingAZWideBox) {
  expect_split({point(-1, -2, -3), point(5, 3, 7)}, {point(-1, -2, -3), point(5, 3, 2)},
               {point(-1, -2, 2), point(5, 3, 7)});
}

// Not in the features: the robustness the renderer relies on.
TEST(BoundingBoxes, AnEmptyBoxIsNeverHit) {
  const BoundingBox box;
  EXPECT_FALSE(box.intersects({point(0, 0, 0), vector(0, 0, 1)}));
  EXPECT_FALSE(box.intersects({point(0, 0, 0), vector(0, -0.0, 1)}));
}

TEST(BoundingBoxes, InfiniteBoxesAndAxisParallelRaysAreHandledWithoutNaN) {
  // A plane-like slab: infinite in x and z, flat in y.
  const BoundingBox slab{point(-kInf, 0, -kInf), point(kInf, 0, kInf)};
  EXPECT_TRUE(slab.intersects({point(0, 5, 0), vector(0, -1, 0)}));
  EXPECT_FALSE(slab.intersects({point(0, 5, 0), vector(0, 1, 0)}));   // pointing away
  EXPECT_FALSE(slab.intersects({point(0, 5, 0), vector(1, 0, 0)}));   // parallel, above
  EXPECT_TRUE(slab.intersects({point(0, 0, 0), vector(1, 0, 0)}));    // parallel, in the plane
  EXPECT_FALSE(slab.intersects({point(3, 2, 0), vector(0, 0, -1)}));  // parallel, above
  // Transforming infinite extents: rotation mixes infinite axes, no NaN.
  const BoundingBox turned = transform(slab, rotation_y(std::numbers::pi / 4) * translation(0, 2, 0));
  EXPECT_CORNER(turned.min, point(-kInf, 2, -kInf));
  EXPECT_CORNER(turned.max, point(kInf, 2, kInf));
  // An empty box stays empty.
  EXPECT_TRUE(transform(BoundingBox{}, rotation_x(1)).empty());
}

TEST(BoundingBoxes, ABoxBehindTheRayIsMissed) {
  const BoundingBox box{point(-1, -1, -1), point(1, 1, 1)};
  EXPECT_FALSE(box.intersects({point(0, 0, 5), vector(0, 0, 1)}));
}

}  // namespace
}  // namespace toroid
