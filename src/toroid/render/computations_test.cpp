// SPDX-License-Identifier: Apache-2.0
// intersections.feature: prepare_computations and schlick.
#include "toroid/render/computations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

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
  Material a_material = a->material();
  a_material.refractive_index = 1.5;
  a->set_material(a_material);
  const auto b = glass_sphere();
  b->set_transform(translation(0, 0, -0.25));
  Material b_material = b->material();
  b_material.refractive_index = 2.0;
  b->set_material(b_material);
  const auto c = glass_sphere();
  c->set_transform(translation(0, 0, 0.25));
  Material c_material = c->material();
  c_material.refractive_index = 2.5;
  c->set_material(c_material);
  const Ray r{point(0, 0, -4), vector(0, 0, 1)};
  const Intersections xs{{2, a.get()},    {2.75, b.get()}, {3.25, c.get()},
                         {4.75, b.get()}, {5.25, c.get()}, {6, a.get()}};
  struct Example {
    int index;
    double n1, n2;
  };
  const Example examples[] = {{0, 1.0, 1.5}, {1, 1.5, 2.0}, {2, 2.0, 2.5}, {3, 2.5, 2.5}, {4, 2.5, 1.5}, {5, 1.5, 1.0}};
  for (const Example& e : examples) {
    SCOPED_TRACE(::testing::Message() << "index " << e.index);
    const Computations comps = prepare_computations(xs[e.index], r, xs);
    EXPECT_EQ(comps.n1, e.n1);
    EXPECT_EQ(comps.n2, e.n2);
  }
}

// The book's containers algorithm as its pseudo-code reads, for the test
// below: a list, append or remove, stop at the hit.
std::pair<double, double> book_n1_n2(const Intersection& hit, const Intersections& xs) {
  std::vector<const Shape*> containers;
  double n1 = 1, n2 = 1;
  for (const Intersection& x : xs) {
    const bool is_hit = x.t == hit.t && x.object == hit.object;
    if (is_hit) n1 = containers.empty() ? 1.0 : containers.back()->material().refractive_index;
    const auto found = std::find(containers.begin(), containers.end(), x.object);
    if (found != containers.end())
      containers.erase(found);
    else
      containers.push_back(x.object);
    if (is_hit) {
      n2 = containers.empty() ? 1.0 : containers.back()->material().refractive_index;
      break;
    }
  }
  return {n1, n2};
}

TEST(Intersections, N1AndN2AlongAChainOfOverlappingGlassSpheresLongerThanTheShortList) {
  // Twelve spheres along z, each overlapping the next (as b and c above):
  // 24 intersections, more than the containers' short list holds, and
  // spheres left while a later one is still inside.
  std::vector<std::shared_ptr<Sphere>> spheres;
  Intersections xs;
  for (int i = 0; i < 12; ++i) {
    auto s = glass_sphere();
    s->set_transform(translation(0, 0, 0.5 * i));
    Material m = s->material();
    m.refractive_index = 1.1 + 0.1 * i;
    s->set_material(m);
    spheres.push_back(s);
  }
  const Ray r{point(0, 0, -4), vector(0, 0, 1)};
  for (const auto& s : spheres) s->intersect(r, xs);
  sort_intersections(xs);
  ASSERT_EQ(xs.size(), 24u);
  int left_mid_list = 0;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    SCOPED_TRACE(::testing::Message() << "index " << k);
    const Computations comps = prepare_computations(xs[k], r, xs);
    const auto [n1, n2] = book_n1_n2(xs[k], xs);
    EXPECT_EQ(comps.n1, n1);
    EXPECT_EQ(comps.n2, n2);
    left_mid_list += n1 == n2;  // left a sphere that was not the innermost
  }
  EXPECT_GT(left_mid_list, 5);
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

// --- surface_bias: scale-aware over_point / under_point offsets ------------

// The offset of a hit straight down onto the top of `shape` from 5 of its
// own sizes above (the top is at `top`, the size is `size`).
double bias_from_above(const Shape& shape, double top, double size) {
  const Ray r{point(0, top + 5 * size, 0), vector(0, -1, 0)};
  return surface_bias({5 * size, &shape}, r);
}

TEST(SurfaceBias, ScalesWithTheObject) {
  Sphere unit;
  const double b1 = bias_from_above(unit, 1, 1);
  EXPECT_GT(b1, kEpsilon / 2);  // the book's over_point.z < -EPSILON/2
  EXPECT_LT(b1, 1e-4);
  for (const double s : {1e-9, 1e-3, 1e4, 1e9}) {
    Sphere scaled;
    scaled.set_transform(scaling(s, s, s));
    EXPECT_NEAR(bias_from_above(scaled, s, s) / s, b1, 1e-9 * b1) << "scale " << s;
  }
}

TEST(SurfaceBias, FollowsTheTransformsOfEveryParentGroup) {
  Sphere alone;
  const double b1 = bias_from_above(alone, 1, 1);
  auto outer = std::make_shared<Group>();
  auto inner = std::make_shared<Group>();
  auto sphere = std::make_shared<Sphere>();
  outer->set_transform(scaling(1e-3, 1e-3, 1e-3));
  inner->set_transform(scaling(0.5, 0.5, 0.5));
  inner->add_child(sphere);
  outer->add_child(inner);
  EXPECT_NEAR(bias_from_above(*sphere, 5e-4, 5e-4), 5e-4 * b1, 1e-9 * b1);
}

TEST(SurfaceBias, FollowsTheThinnestSideNotTheLargest) {
  // A torus's tube, a wall made of a flattened sphere.
  const Torus thin(1, 1e-6);
  EXPECT_LT(bias_from_above(thin, 1e-6, 1), 1e-6 * 1e-4);
  Sphere wall;
  wall.set_transform(scaling(10, 0.01, 10));
  EXPECT_LT(bias_from_above(wall, 0.01, 1), 0.01 * 1e-4);
}

TEST(SurfaceBias, ExceedsTheRoundingOfFarCoordinates) {
  // A plane has no thickness: only the hit point's magnitude counts. At
  // 1e12 neighbouring doubles are 1.2e-4 apart.
  Plane far_plane;
  far_plane.set_transform(translation(0, 1e12, 0));
  const double b = bias_from_above(far_plane, 1e12, 1);
  EXPECT_GE(b, 8 * (std::nextafter(1e12, 2e12) - 1e12));
  EXPECT_LT(b, 0.01);
  // ... and near the origin it is far below anything visible.
  EXPECT_LT(bias_from_above(Plane(), 0, 1), 1e-12);
}

// A top-level shape reads its own inverse; below a group the world-to-object
// matrix is the product. An identity group changes nothing, bit for bit.
TEST(SurfaceBias, IsTheSameAtTheTopLevelAndBelowAnIdentityGroup) {
  for (const Matrix4& m :
       {scaling(2, 0.5, 3), rotation_x(0.7) * shearing(0.2, 0, 0.1, 0, 0, 0.3), translation(1, 2, 3)}) {
    Sphere alone;
    alone.set_transform(m);
    auto group = std::make_shared<Group>();
    auto child = std::make_shared<Sphere>();
    child->set_transform(m);
    group->add_child(child);
    EXPECT_EQ(bias_from_above(alone, 1, 1), bias_from_above(*child, 1, 1));
  }
}

// Spheres and cubes answer half_thickness without building their box: the
// same as the box gives.
TEST(SurfaceBias, SpheresAndCubesKnowTheirHalfThicknessAsTheirBoxSays) {
  const Sphere sphere;
  const Cube cube;
  EXPECT_EQ(sphere.half_thickness(), sphere.Shape::half_thickness());
  EXPECT_EQ(cube.half_thickness(), cube.Shape::half_thickness());
}

}  // namespace
}  // namespace toroid
