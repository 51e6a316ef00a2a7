// SPDX-License-Identifier: Apache-2.0
// intersections.feature: intersections and the hit (the scenarios about
// prepare_computations and schlick are in computations_test.cpp).
#include "toroid/core/intersection.h"

#include <gtest/gtest.h>

#include "support/approx.h"
#include "toroid/shapes/sphere.h"

namespace toroid {
namespace {

TEST(Intersections, AnIntersectionEncapsulatesTAndObject) {
  const Sphere s;
  const Intersection i{3.5, &s};
  EXPECT_EQ(i.t, 3.5);
  EXPECT_EQ(i.object, &s);
}

TEST(Intersections, AggregatingIntersections) {
  const Sphere s;
  const Intersection i1{1, &s};
  const Intersection i2{2, &s};
  const Intersections xs{i1, i2};
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_EQ(xs[0].t, 1.0);
  EXPECT_EQ(xs[1].t, 2.0);
}

TEST(Intersections, TheHitWhenAllIntersectionsHavePositiveT) {
  const Sphere s;
  const Intersection i1{1, &s};
  const Intersection i2{2, &s};
  const Intersections xs{i2, i1};
  const Intersection* i = hit(xs);
  ASSERT_NE(i, nullptr);
  EXPECT_EQ(i, &xs[1]);
  EXPECT_EQ(i->t, i1.t);
}

TEST(Intersections, TheHitWhenSomeIntersectionsHaveNegativeT) {
  const Sphere s;
  const Intersection i1{-1, &s};
  const Intersection i2{1, &s};
  const Intersections xs{i2, i1};
  const Intersection* i = hit(xs);
  ASSERT_NE(i, nullptr);
  EXPECT_EQ(i, &xs[0]);
  EXPECT_EQ(i->t, i2.t);
}

TEST(Intersections, TheHitWhenAllIntersectionsHaveNegativeT) {
  const Sphere s;
  const Intersection i1{-2, &s};
  const Intersection i2{-1, &s};
  const Intersections xs{i2, i1};
  EXPECT_EQ(hit(xs), nullptr);
}

TEST(Intersections, TheHitIsAlwaysTheLowestNonnegativeIntersection) {
  const Sphere s;
  const Intersection i1{5, &s};
  const Intersection i2{7, &s};
  const Intersection i3{-3, &s};
  const Intersection i4{2, &s};
  const Intersections xs{i1, i2, i3, i4};
  const Intersection* i = hit(xs);
  ASSERT_NE(i, nullptr);
  EXPECT_EQ(i, &xs[3]);
  EXPECT_EQ(i->t, i4.t);
}

}  // namespace
}  // namespace toroid

// The one intersections.feature scenario that needs a triangle.
#include "toroid/shapes/triangle.h"

namespace toroid {
namespace {

TEST(Intersections, AnIntersectionCanEncapsulateUAndV) {
  const Triangle s(point(0, 1, 0), point(-1, 0, 0), point(1, 0, 0));
  const Intersection i{3.5, &s, 0.2, 0.4};
  EXPECT_EQ(i.u, 0.2);
  EXPECT_EQ(i.v, 0.4);
  EXPECT_EQ(i.t, 3.5);
  EXPECT_EQ(i.object, &s);
}

}  // namespace
}  // namespace toroid
