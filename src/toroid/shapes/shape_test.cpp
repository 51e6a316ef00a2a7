// SPDX-License-Identifier: Apache-2.0
// shapes.feature (the scenarios that need no group; those that do are ported
// with groups).
#include "toroid/shapes/shape.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "support/approx.h"
#include "support/material_eq.h"
#include "toroid/math/transform.h"

namespace toroid {
namespace {

// The book's test_shape(): records the object-space ray it is intersected with.
class TestShape : public Shape {
 public:
  mutable Ray saved_ray{};

  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  void local_intersect(const Ray& ray, Intersections&) const override { saved_ray = ray; }
  Tuple local_normal_at(const Tuple& p, const Intersection&) const override { return vector(p.x, p.y, p.z); }
};

TEST(Shapes, TheDefaultTransformation) {
  const TestShape s;
  EXPECT_APPROX(s.transform(), Matrix4::identity());
}

TEST(Shapes, AssigningATransformation) {
  TestShape s;
  s.set_transform(translation(2, 3, 4));
  EXPECT_APPROX(s.transform(), translation(2, 3, 4));
}

TEST(Shapes, TheDefaultMaterial) {
  const TestShape s;
  const Material m = s.material();
  EXPECT_MATERIAL_EQ(m, Material{});
}

TEST(Shapes, AssigningAMaterial) {
  TestShape s;
  Material m;
  m.ambient = 1;
  s.set_material(m);
  EXPECT_MATERIAL_EQ(s.material(), m);
  EXPECT_EQ(s.material().ambient, 1.0);
}

// Memory: the material is a pointer to a block, shared where it can be.
TEST(Shapes, ShapesWithoutAMaterialShareTheDefault) {
  const TestShape a, b;
  EXPECT_EQ(&a.material(), &b.material());
  EXPECT_MATERIAL_EQ(a.material(), Material{});
}

TEST(Shapes, AssigningAMaterialGivesTheShapeItsOwnCopy) {
  TestShape a, b;
  Material m;
  m.ambient = 1;
  a.set_material(m);
  b.set_material(m);
  EXPECT_NE(&a.material(), &b.material());
  EXPECT_NE(&a.material(), &m);
  m.ambient = 0.5;  // the copy keeps the value it was given
  EXPECT_EQ(a.material().ambient, 1.0);
  TestShape fresh;
  EXPECT_MATERIAL_EQ(fresh.material(), Material{});  // the default is untouched
}

TEST(Shapes, SharingAMaterial) {
  Material m;
  m.diffuse = 0.3;
  const SharedMaterial shared(m);
  TestShape a, b;
  a.set_material(shared);
  b.set_material(shared);
  EXPECT_EQ(&a.material(), shared.get());
  EXPECT_EQ(&b.material(), shared.get());
  Material other;
  other.diffuse = 0.6;
  a.set_material(other);  // b keeps the shared block
  EXPECT_EQ(a.material().diffuse, 0.6);
  EXPECT_EQ(b.material().diffuse, 0.3);
  EXPECT_EQ(&b.material(), shared.get());
}

TEST(Shapes, IntersectingAScaledShapeWithARay) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  TestShape s;
  s.set_transform(scaling(2, 2, 2));
  Intersections xs;
  s.intersect(r, xs);
  EXPECT_APPROX(s.saved_ray.origin, point(0, 0, -2.5));
  EXPECT_APPROX(s.saved_ray.direction, vector(0, 0, 0.5));
}

TEST(Shapes, IntersectingATranslatedShapeWithARay) {
  const Ray r{point(0, 0, -5), vector(0, 0, 1)};
  TestShape s;
  s.set_transform(translation(5, 0, 0));
  Intersections xs;
  s.intersect(r, xs);
  EXPECT_APPROX(s.saved_ray.origin, point(-5, 0, -5));
  EXPECT_APPROX(s.saved_ray.direction, vector(0, 0, 1));
}

TEST(Shapes, ComputingTheNormalOnATranslatedShape) {
  TestShape s;
  s.set_transform(translation(0, 1, 0));
  EXPECT_APPROX(s.normal_at(point(0, 1.70711, -0.70711)), vector(0, 0.70711, -0.70711));
}

TEST(Shapes, ComputingTheNormalOnATransformedShape) {
  TestShape s;
  const Matrix4 m = scaling(1, 0.5, 1) * rotation_z(std::numbers::pi / 5);
  s.set_transform(m);
  const double k = std::sqrt(2.0) / 2;
  EXPECT_APPROX(s.normal_at(point(0, k, -k)), vector(0, 0.97014, -0.24254));
}

TEST(Shapes, AShapeHasAParentAttribute) {
  const TestShape s;
  EXPECT_EQ(s.parent, nullptr);
}

}  // namespace
}  // namespace toroid
