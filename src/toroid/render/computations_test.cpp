// intersections.feature: prepare_computations and schlick.
#include "toroid/render/computations.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"

namespace toroid {
namespace {

const double kHalfSqrt2 = std::sqrt(2.0) / 2;

TEST(Intersections, PrecomputingTheStateOfAnIntersection) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  const Sphere shape;
  const Intersection i{4, &shape};
  const Computations comps = prepare_computations(i, r);
  EXPECT_EQ(comps.t, i.t);
  EXPECT_EQ(comps.object, i.object);
  EXPECT_APPROX(comps.point, point(0, 0, -1));
  EXPECT_APPROX(comps.eyev, vector(0, 0, -1));
  EXPECT_APPROX(comps.normalv, vector(0, 0, -1));
}

TEST(Intersections, PrecomputingTheReflectionVector) {
  const Plane shape;
  const Ray r{point(0, 1, -1), vector(0, -kHalfSqrt2, kHalfSqrt2)};
  const Intersection i{std::sqrt(2.0), &shape};
  const Computations comps = prepare_computations(i, r);
  EXPECT_APPROX(comps.reflectv, vector(0, kHalfSqrt2, kHalfSqrt2));
}

TEST(Intersections, TheHitWhenAnIntersectionOccursOnTheOutside) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  const Sphere shape;
  const Intersection i{4, &shape};
  const Computations comps = prepare_computations(i, r);
  EXPECT_FALSE(comps.inside);
}

TEST(Intersections, TheHitWhenAnIntersectionOccursOnTheInside) {
  const Ray r{point(0, 0, 0), vector(0, 0, 1)};
  const Sphere shape;
  const Intersection i{1, &shape};
  const Computations comps = prepare_computations(i, r);
  EXPECT_APPROX(comps.point, point(0, 0, 1));
  EXPECT_APPROX(comps.eyev, vector(0, 0, -1));
  EXPECT_TRUE(comps.inside);
  // normal would have been (0, 0, 1), but is inverted!
  EXPECT_APPROX(comps.normalv, vector(0, 0, -1));
}

TEST(Intersections, TheHitShouldOffsetThePoint) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  Sphere shape;
  shape.set_transform(translation(0, 0, 1));
  const Intersection i{5, &shape};
  const Computations comps = prepare_computations(i, r);
  EXPECT_LT(comps.over_point.z, -kEpsilon / 2);
  EXPECT_GT(comps.point.z, comps.over_point.z);
}

TEST(Intersections, TheUnderPointIsOffsetBelowTheSurface) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  const auto shape = glass_sphere();
  shape->set_transform(translation(0, 0, 1));
  const Intersection i{5, shape.get()};
  const Intersections xs{i};
  const Computations comps = prepare_computations(i, r, xs);
  EXPECT_GT(comps.under_point.z, kEpsilon / 2);
  EXPECT_LT(comps.point.z, comps.under_point.z);
}

TEST(Intersections, FindingN1AndN2AtVariousIntersections) {
  const auto a = glass_sphere();
  a->set_transform(scaling(2, 2, 2));
  a->material.refractive_index = 1.5;
  const auto b = glass_sphere();
  b->set_transform(translation(0, 0, -0.25));
  b->material.refractive_index = 2.0;
  const auto c = glass_sphere();
  c->set_transform(translation(0, 0, 0.25));
  c->material.refractive_index = 2.5;
  const Ray r{point(0, 0, -4), vector(0, 0, 1)};
  const Intersections xs{{2, a.get()},    {2.75, b.get()}, {3.25, c.get()},
                         {4.75, b.get()}, {5.25, c.get()}, {6, a.get()}};
  struct Example {
    int index;
    double n1, n2;
  };
  const Example examples[] = {{0, 1.0, 1.5}, {1, 1.5, 2.0}, {2, 2.0, 2.5},
                              {3, 2.5, 2.5}, {4, 2.5, 1.5}, {5, 1.5, 1.0}};
  for (const Example& e : examples) {
    SCOPED_TRACE(::testing::Message() << "index " << e.index);
    const Computations comps = prepare_computations(xs[e.index], r, xs);
    EXPECT_EQ(comps.n1, e.n1);
    EXPECT_EQ(comps.n2, e.n2);
  }
}

TEST(Intersections, TheSchlickApproximationUnderTotalInternalReflection) {
  const auto shape = glass_sphere();
  const Ray r{point(0, 0, kHalfSqrt2), vector(0, 1, 0)};
  const Intersections xs{{-kHalfSqrt2, shape.get()}, {kHalfSqrt2, shape.get()}};
  const Computations comps = prepare_computations(xs[1], r, xs);
  EXPECT_APPROX(schlick(comps), 1.0);
}

TEST(Intersections, TheSchlickApproximationWithAPerpendicularViewingAngle) {
  const auto shape = glass_sphere();
  const Ray r{point(0, 0, 0), vector(0, 1, 0)};
  const Intersections xs{{-1, shape.get()}, {1, shape.get()}};
  const Computations comps = prepare_computations(xs[1], r, xs);
  EXPECT_APPROX(schlick(comps), 0.04);
}

TEST(Intersections, TheSchlickApproximationWithSmallAngleAndN2GreaterThanN1) {
  const auto shape = glass_sphere();
  const Ray r{point(0, 0.99, -2), vector(0, 0, 1)};
  const Intersections xs{{1.8589, shape.get()}};
  const Computations comps = prepare_computations(xs[0], r, xs);
  EXPECT_APPROX(schlick(comps), 0.48873);
}

}  // namespace
}  // namespace toroid
