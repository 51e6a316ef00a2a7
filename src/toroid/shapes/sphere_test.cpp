// SPDX-License-Identifier: Apache-2.0
// spheres.feature
#include "toroid/shapes/sphere.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/approx.h"
#include "support/material_eq.h"
#include "toroid/math/hash.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/group.h"

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

// A sphere under a similarity transform answers in its parent's space:
// the same surface as the book's way (the ray into object space, the unit
// sphere), up to rounding.

// The book's answers: the ray moved into object space by hand.
Intersections book_intersect(const Sphere& s, const Ray& r) {
  Intersections xs;
  s.local_intersect(transform(r, s.inverse_transform()), xs);
  return xs;
}

// A ray from a point around the sphere towards a point near it.
Ray random_ray(std::uint64_t& key, const Tuple& centre, double spread) {
  const auto coordinate = [&](double scale) { return (2 * unit_interval(key = splitmix64(key)) - 1) * scale; };
  const Tuple from = centre + vector(coordinate(3 * spread), coordinate(3 * spread), coordinate(3 * spread));
  const Tuple to = centre + vector(coordinate(spread), coordinate(spread), coordinate(spread));
  return {from, to - from};
}

TEST(SpheresUnderSimilarity, MeetRaysWhereTheBooksWayDoes) {
  Sphere s;
  s.set_transform(translation(3, -2, 7) * rotation_y(0.7) * rotation_x(-1.3) * scaling(2.5, 2.5, 2.5));
  ASSERT_TRUE(s.similarity());
  EXPECT_APPROX(s.centre(), point(3, -2, 7));
  EXPECT_APPROX(s.radius(), 2.5);
  std::uint64_t key = 12345;
  int hits = 0;
  for (int i = 0; i < 2000; ++i) {
    const Ray r = random_ray(key, point(3, -2, 7), 2.5);
    const Intersections book = book_intersect(s, r);
    Intersections xs;
    s.intersect(r, xs);
    ASSERT_EQ(xs.size(), book.size()) << i;
    for (std::size_t k = 0; k < xs.size(); ++k) {
      EXPECT_NEAR(xs[k].t, book[k].t, 1e-12 * (1 + std::abs(book[k].t))) << i;
      EXPECT_EQ(xs[k].object, &s);
    }
    if (xs.empty()) continue;
    ++hits;
    // The nearest hit from t = 0 and the shadow test agree with the list.
    const Intersection* first = hit(xs);
    Intersection nearest;
    const bool found = s.intersect_nearest(r, 1e300, nearest);
    ASSERT_EQ(found, first != nullptr) << i;
    if (found) {
      EXPECT_EQ(nearest.t, first->t) << i;
    }
    EXPECT_EQ(s.blocks(r, 1e300), found) << i;
    // The normal at the hit: the book's, to rounding, and of unit length.
    const Tuple p = r.position(xs[0].t);
    const Tuple n = s.normal_at(p);
    const Tuple book_n = s.normal_to_world(s.local_normal_at(s.world_to_object(p), xs[0]));
    EXPECT_NEAR(n.x, book_n.x, 1e-9) << i;
    EXPECT_NEAR(n.y, book_n.y, 1e-9) << i;
    EXPECT_NEAR(n.z, book_n.z, 1e-9) << i;
    EXPECT_NEAR(magnitude(n), 1.0, 1e-9) << i;
    EXPECT_EQ(n.w, 0.0);
  }
  EXPECT_GT(hits, 500);  // the rays do meet the sphere
}

// The nearest hit and the shadow test skip a sphere the ray leaves from
// outside before solving: from inside, on and outside the surface, in
// every direction, both still give what the full list gives, bit for bit.
TEST(Spheres, TheQueriesThatLookAheadAgreeWithTheListFromEveryOrigin) {
  Sphere similar, squashed;
  similar.set_transform(translation(3, -2, 7) * rotation_y(0.7) * scaling(2.5, 2.5, 2.5));
  squashed.set_transform(translation(1, 0, 0) * scaling(2, 0.1, 1.5));
  ASSERT_TRUE(similar.similarity());
  ASSERT_FALSE(squashed.similarity());
  std::uint64_t key = 4242;
  const auto coordinate = [&] { return 2 * unit_interval(key = splitmix64(key)) - 1; };
  int leaving = 0, entering = 0;
  for (const Sphere* s : {&similar, &squashed}) {
    for (int i = 0; i < 3000; ++i) {
      // An object-space origin inside (|p| < 1), near the surface or outside.
      const double reach = i % 3 == 0 ? 0.9 : i % 3 == 1 ? 1.0 : 2.5;
      Tuple local = vector(coordinate(), coordinate(), coordinate());
      local = normalize(local) * (reach * (i % 3 == 1 ? 1 + 1e-9 * coordinate() : std::abs(coordinate())));
      const Tuple from = s->transform() * point(local.x, local.y, local.z);
      const Ray r{from, vector(coordinate(), coordinate(), coordinate())};
      Intersections xs;
      s->intersect(r, xs);
      for (const double t_max : {1e300, 0.5, 3.0}) {
        const Intersection* first = nullptr;
        for (const Intersection& x : xs)
          if (x.t >= 0 && x.t < t_max && (first == nullptr || x.t < first->t)) first = &x;
        Intersection nearest;
        const bool found = s->intersect_nearest(r, t_max, nearest);
        ASSERT_EQ(found, first != nullptr) << i << " " << t_max;
        if (found) {
          EXPECT_EQ(nearest.t, first->t) << i;
        }
        EXPECT_EQ(s->blocks(r, t_max), found) << i << " " << t_max;
      }
      const Ray local_ray = transform(r, s->inverse_transform());
      const double b = dot(local_ray.direction, vector(local_ray.origin.x, local_ray.origin.y, local_ray.origin.z));
      if (xs.size() == 2) ++(b > 0 ? leaving : entering);
    }
  }
  EXPECT_GT(leaving, 1000);  // lines that meet the sphere but leave its centre
  EXPECT_GT(entering, 1000);
}

// The sphere keeps its half thickness in its parent's space (asked at every
// hit, for the surface bias): the bits Shape's expression gives, for every
// transform it is given.
TEST(Spheres, KeepTheirParentSpaceHalfThicknessAsShapeComputesIt) {
  Sphere s;
  EXPECT_EQ(s.parent_space_half_thickness(), s.Shape::parent_space_half_thickness());
  for (const Matrix4& m : {scaling(2.5, 2.5, 2.5), translation(1, 2, 3) * rotation_z(0.3) * scaling(10, 0.01, 10),
                           rotation_x(1.5707) * scaling(0.33, 0.33, 0.33), Matrix4::identity()}) {
    s.set_transform(m);
    EXPECT_EQ(s.parent_space_half_thickness(), s.Shape::parent_space_half_thickness());
  }
  s.set_transform(scaling(4, 4, 4));
  EXPECT_NEAR(s.parent_space_half_thickness(), 4 / std::sqrt(3.0), 1e-15);
}

TEST(SpheresUnderSimilarity, AMirrorKeepsTheNormalOutwards) {
  Sphere s;
  s.set_transform(translation(1, 2, 3) * scaling(-2, -2, -2));
  ASSERT_TRUE(s.similarity());
  EXPECT_APPROX(s.centre(), point(1, 2, 3));
  EXPECT_APPROX(s.radius(), 2.0);
  EXPECT_APPROX(s.normal_at(point(3, 2, 3)), vector(1, 0, 0));
}

TEST(SpheresUnderSimilarity, OtherTransformsTakeTheBooksWayBitForBit) {
  Sphere s;
  s.set_transform(translation(1, 0, 0) * scaling(2, 1, 1.5));
  EXPECT_FALSE(s.similarity());
  std::uint64_t key = 777;
  for (int i = 0; i < 500; ++i) {
    const Ray r = random_ray(key, point(1, 0, 0), 2);
    const Intersections book = book_intersect(s, r);
    Intersections xs;
    s.intersect(r, xs);
    ASSERT_EQ(xs.size(), book.size());
    for (std::size_t k = 0; k < xs.size(); ++k) EXPECT_EQ(xs[k].t, book[k].t);
  }
}

TEST(SpheresUnderSimilarity, InAGroupTheNormalGoesThroughTheGroup) {
  auto g = std::make_shared<Group>();
  g->set_transform(scaling(1, 2, 1));
  auto s = std::make_shared<Sphere>();
  s->set_transform(translation(5, 0, 0));
  g->add_child(s);
  ASSERT_TRUE(s->similarity());
  // The group's squash tilts the normal: the world point (5 + a, 2a, 0),
  // a = sqrt(1/2), is (5 + a, a, 0) in the group, whose normal (a, a, 0)
  // goes to the world as (a, a / 2, 0), normalised.
  const Tuple q = point(5 + std::sqrt(0.5), 2 * std::sqrt(0.5), 0);
  EXPECT_APPROX(s->normal_at(q), normalize(vector(std::sqrt(0.5), std::sqrt(0.5) / 2, 0)));
}

}  // namespace
}  // namespace toroid
