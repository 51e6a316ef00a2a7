// SPDX-License-Identifier: Apache-2.0
// spheres.feature
#include "toroid/shapes/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/approx.h"
#include "support/material_eq.h"
#include "toroid/math/transform.h"

namespace toroid {
namespace {

Intersections intersect(const Shape& s, const Ray& r) {
  Intersections xs;
  s.intersect(r, xs);
  return xs;
}

TEST(Spheres, ARayIntersectsASphereAtTwoPoints) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  const Sphere s;
  const Intersections xs = intersect(s, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_APPROX(xs[0].t, 4.0);
  EXPECT_APPROX(xs[1].t, 6.0);
}

TEST(Spheres, ARayIntersectsASphereAtATangent) {
  const Ray r{point(0, 1, -5), vector(0, 0, 1)};
  const Sphere s;
  const Intersections xs = intersect(s, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_APPROX(xs[0].t, 5.0);
  EXPECT_APPROX(xs[1].t, 5.0);
}

TEST(Spheres, ARayMissesASphere) {
  const Ray r{point(0, 2, -5), vector(0, 0, 1)};
  const Sphere s;
  EXPECT_EQ(intersect(s, r).size(), 0u);
}

TEST(Spheres, ARayOriginatesInsideASphere) {
  const Ray r{point(0, 0, 0), vector(0, 0, 1)};
  const Sphere s;
  const Intersections xs = intersect(s, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_APPROX(xs[0].t, -1.0);
  EXPECT_APPROX(xs[1].t, 1.0);
}

TEST(Spheres, ASphereIsBehindARay) {
  const Ray r{point(0, 0, 5), vector(0, 0, 1)};
  const Sphere s;
  const Intersections xs = intersect(s, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_APPROX(xs[0].t, -6.0);
  EXPECT_APPROX(xs[1].t, -4.0);
}

TEST(Spheres, IntersectSetsTheObjectOnTheIntersection) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  const Sphere s;
  const Intersections xs = intersect(s, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_EQ(xs[0].object, &s);
  EXPECT_EQ(xs[1].object, &s);
}

TEST(Spheres, ASpheresDefaultTransformation) {
  const Sphere s;
  EXPECT_APPROX(s.transform(), Matrix4::identity());
}

TEST(Spheres, ChangingASpheresTransformation) {
  Sphere s;
  const Matrix4 t = translation(2, 3, 4);
  s.set_transform(t);
  EXPECT_APPROX(s.transform(), t);
}

TEST(Spheres, IntersectingAScaledSphereWithARay) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  Sphere s;
  s.set_transform(scaling(2, 2, 2));
  const Intersections xs = intersect(s, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_APPROX(xs[0].t, 3.0);
  EXPECT_APPROX(xs[1].t, 7.0);
}

TEST(Spheres, IntersectingATranslatedSphereWithARay) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  Sphere s;
  s.set_transform(translation(5, 0, 0));
  EXPECT_EQ(intersect(s, r).size(), 0u);
}

TEST(Spheres, TheNormalOnASphereAtAPointOnTheXAxis) {
  const Sphere s;
  EXPECT_APPROX(s.normal_at(point(1, 0, 0)), vector(1, 0, 0));
}

TEST(Spheres, TheNormalOnASphereAtAPointOnTheYAxis) {
  const Sphere s;
  EXPECT_APPROX(s.normal_at(point(0, 1, 0)), vector(0, 1, 0));
}

TEST(Spheres, TheNormalOnASphereAtAPointOnTheZAxis) {
  const Sphere s;
  EXPECT_APPROX(s.normal_at(point(0, 0, 1)), vector(0, 0, 1));
}

TEST(Spheres, TheNormalOnASphereAtANonaxialPoint) {
  const Sphere s;
  const double k = std::sqrt(3.0) / 3;
  EXPECT_APPROX(s.normal_at(point(k, k, k)), vector(k, k, k));
}

TEST(Spheres, TheNormalIsANormalizedVector) {
  const Sphere s;
  const double k = std::sqrt(3.0) / 3;
  const Tuple n = s.normal_at(point(k, k, k));
  EXPECT_APPROX(n, normalize(n));
}

TEST(Spheres, ComputingTheNormalOnATranslatedSphere) {
  Sphere s;
  s.set_transform(translation(0, 1, 0));
  EXPECT_APPROX(s.normal_at(point(0, 1.70711, -0.70711)), vector(0, 0.70711, -0.70711));
}

TEST(Spheres, ComputingTheNormalOnATransformedSphere) {
  Sphere s;
  const Matrix4 m = scaling(1, 0.5, 1) * rotation_z(std::numbers::pi / 5);
  s.set_transform(m);
  const double k = std::sqrt(2.0) / 2;
  EXPECT_APPROX(s.normal_at(point(0, k, -k)), vector(0, 0.97014, -0.24254));
}

TEST(Spheres, ASphereHasADefaultMaterial) {
  const Sphere s;
  const Material m = s.material();
  EXPECT_MATERIAL_EQ(m, Material{});
}

TEST(Spheres, ASphereMayBeAssignedAMaterial) {
  Sphere s;
  Material m;
  m.ambient = 1;
  s.set_material(m);
  EXPECT_MATERIAL_EQ(s.material(), m);
  EXPECT_EQ(s.material().ambient, 1.0);
}

TEST(Spheres, AHelperForProducingASphereWithAGlassyMaterial) {
  const auto s = glass_sphere();
  EXPECT_APPROX(s->transform(), Matrix4::identity());
  EXPECT_EQ(s->material().transparency, 1.0);
  EXPECT_EQ(s->material().refractive_index, 1.5);
}

}  // namespace
}  // namespace toroid
