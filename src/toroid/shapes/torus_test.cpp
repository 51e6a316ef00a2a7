// The Torus shape in the RTC scenario style: intersections, normals,
// transforms, groups, CSG, shadows and refraction.
#include "toroid/shapes/torus.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/render/computations.h"
#include "toroid/render/world.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/sphere.h"

namespace toroid {
namespace {

Intersections intersect_sorted(const Shape& s, const Ray& r) {
  Intersections xs;
  s.intersect(r, xs);
  sort_intersections(xs);
  return xs;
}

TEST(Torus, ARayThroughTheHoleIntersectsFourTimes) {
  const Torus t(1, 0.25);
  const Intersections xs = intersect_sorted(t, {point(-5, 0, 0), vector(1, 0, 0)});
  ASSERT_EQ(xs.size(), 4u);
  EXPECT_DOUBLE_EQ(xs[0].t, 3.75);
  EXPECT_DOUBLE_EQ(xs[1].t, 4.25);
  EXPECT_DOUBLE_EQ(xs[2].t, 5.75);
  EXPECT_DOUBLE_EQ(xs[3].t, 6.25);
  for (const auto& x : xs) EXPECT_EQ(x.object, &t);
}

TEST(Torus, ARayTangentToTheTopTouchesTwice) {
  const Torus t(1, 0.25);
  const Intersections xs = intersect_sorted(t, {point(-5, 0, 0.25), vector(1, 0, 0)});
  ASSERT_EQ(xs.size(), 4u);
  EXPECT_DOUBLE_EQ(xs[0].t, 4);
  EXPECT_DOUBLE_EQ(xs[1].t, 4);
}

TEST(Torus, ARayMissesATorus) {
  const Torus t(1, 0.25);
  EXPECT_TRUE(intersect_sorted(t, {point(-5, 0, 1), vector(1, 0, 0)}).empty());
  EXPECT_TRUE(intersect_sorted(t, {point(0, 0, -5), vector(0, 0, 1)}).empty());  // down the hole
}

TEST(Torus, ARayThatOnlyTouchesTheOuterEquator) {
  const Torus t(1, 0.25);
  const Intersections xs = intersect_sorted(t, {point(1.25, -5, 0), vector(0, 1, 0)});
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_DOUBLE_EQ(xs[0].t, 5);
  EXPECT_DOUBLE_EQ(xs[1].t, 5);
}

TEST(Torus, NormalsAtKnownPoints) {
  const Torus t(1, 0.25);
  EXPECT_APPROX(t.normal_at(point(1.25, 0, 0)), vector(1, 0, 0));   // outer equator
  EXPECT_APPROX(t.normal_at(point(0.75, 0, 0)), vector(-1, 0, 0));  // inner equator
  EXPECT_APPROX(t.normal_at(point(0, 1, 0.25)), vector(0, 0, 1));   // top
  EXPECT_APPROX(t.normal_at(point(0, -1, -0.25)), vector(0, 0, -1)); // bottom
  const double s = std::sqrt(0.5);
  EXPECT_APPROX(t.normal_at(point(s * 1.25, s * 1.25, 0)), vector(s, s, 0));
}

TEST(Torus, ATranslatedAndRotatedTorus) {
  Torus t(1, 0.25);
  // Stand the ring up: axis along y, then move it to x = 10.
  t.set_transform(translation(10, 0, 0) * rotation_x(M_PI / 2));
  const Intersections xs = intersect_sorted(t, {point(10, -5, 0), vector(0, 1, 0)});
  EXPECT_TRUE(xs.empty());  // down the hole, now along y
  const Intersections ys = intersect_sorted(t, {point(5, 0, 0), vector(1, 0, 0)});
  ASSERT_EQ(ys.size(), 4u);
  EXPECT_NEAR(ys[0].t, 3.75, 1e-12);
  EXPECT_NEAR(ys[3].t, 6.25, 1e-12);
  EXPECT_APPROX(t.normal_at(point(11.25, 0, 0)), vector(1, 0, 0));
}

TEST(Torus, NonUniformScaleMakesAnEllipticalTube) {
  Torus t(1, 0.25);
  t.set_transform(scaling(1, 1, 4));  // the tube is 0.25 wide, 1.0 tall
  // Down through the tube's centre at (1, 0): the tube's z extent is +-1.
  const Intersections xs = intersect_sorted(t, {point(1, 0, -5), vector(0, 0, 1)});
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0].t, 4, 1e-12);
  EXPECT_NEAR(xs[1].t, 6, 1e-12);
  // Across at z = 0 the tube is still 0.25 wide.
  const Intersections ys = intersect_sorted(t, {point(-5, 0, 0), vector(1, 0, 0)});
  ASSERT_EQ(ys.size(), 4u);
  EXPECT_NEAR(ys[0].t, 3.75, 1e-12);
  // The normal at the top of the ellipse points straight up.
  EXPECT_APPROX(t.normal_at(point(1, 0, 1)), vector(0, 0, 1));
  // On the side of the ellipse the world normal is tilted by the scale:
  // object normal (1,0,1)/sqrt2 at object point (1+0.25/sqrt2, 0, 0.25/sqrt2).
  const double k = 0.25 / std::sqrt(2.0);
  const Tuple n = t.normal_at(point(1 + k, 0, 4 * k));
  EXPECT_APPROX(n, normalize(vector(1, 0, 0.25)));
}

TEST(Torus, BoundsOfATorus) {
  const Torus t(2, 0.5);
  const BoundingBox b = t.bounds();
  EXPECT_APPROX(b.min, point(-2.5, -2.5, -0.5));
  EXPECT_APPROX(b.max, point(2.5, 2.5, 0.5));
}

TEST(Torus, ATorusInATransformedGroup) {
  auto g = std::make_shared<Group>();
  g->set_transform(scaling(2, 2, 2));
  auto t = std::make_shared<Torus>(1, 0.25);
  t->set_transform(translation(5, 0, 0));
  g->add_child(t);
  Intersections xs;
  g->intersect({point(0, 0, 0), vector(1, 0, 0)}, xs);
  sort_intersections(xs);
  ASSERT_EQ(xs.size(), 4u);
  EXPECT_NEAR(xs[0].t, 2 * 3.75, 1e-12);
  EXPECT_NEAR(xs[3].t, 2 * 6.25, 1e-12);
  // The normal comes back to world space through the group.
  EXPECT_APPROX(t->normal_at(point(2 * 6.25, 0, 0), xs[3]), vector(1, 0, 0));
}

TEST(Torus, ABagelCutInHalfWithCsg) {
  // Difference of a torus and a cube covering x > 0: half a bagel.
  auto torus = std::make_shared<Torus>(1, 0.25);
  auto cube = std::make_shared<Cube>();
  cube->set_transform(translation(2, 0, 0) * scaling(2, 2, 2));
  const Csg half(CsgOp::Difference, torus, cube);
  Intersections xs;
  half.intersect({point(-5, 0, 0), vector(1, 0, 0)}, xs);
  // The left tube stays (t = 3.75, 4.25); the cut face at x = 0 lies in the
  // hole, so the right tube is gone entirely.
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_DOUBLE_EQ(xs[0].t, 3.75);
  EXPECT_DOUBLE_EQ(xs[1].t, 4.25);
  // Along y through the right-hand tube: the cube's face x = 0 is not crossed,
  // and the tube at y = +-1 lies partly at x > 0: a ray along y at x = -0.1
  // still meets both tubes (they extend to x = -0.25).
  Intersections ys;
  half.intersect({point(-0.1, -5, 0), vector(0, 1, 0)}, ys);
  EXPECT_EQ(ys.size(), 4u);
  Intersections zs;
  half.intersect({point(0.1, -5, 0), vector(0, 1, 0)}, zs);
  EXPECT_TRUE(zs.empty());
}

TEST(Torus, ATorusCastsAShadow) {
  World w;
  w.lights.push_back({point(0, 0, 1000), Color{1, 1, 1}});  // nearly overhead
  auto t = std::make_shared<Torus>(1, 0.25);
  w.objects.push_back(t);
  EXPECT_TRUE(is_shadowed(w, point(1, 0, -5), w.lights[0]));   // under the tube
  EXPECT_FALSE(is_shadowed(w, point(0, 0, -5), w.lights[0]));  // under the hole
  EXPECT_FALSE(is_shadowed(w, point(2, 0, -5), w.lights[0]));  // beside it
}

TEST(Torus, RefractionThroughAGlassTorusCrossesTheHole) {
  // A ray through the hole leaves and re-enters the same torus: the
  // containers algorithm must give n1/n2 = 1.5/1.0 on leaving, 1.0/1.5 on
  // re-entering.
  auto t = std::make_shared<Torus>(1, 0.25);
  t->material.transparency = 1.0;
  t->material.refractive_index = 1.5;
  const Ray r{point(-5, 0, 0), vector(1, 0, 0)};
  const Intersections xs = intersect_sorted(*t, r);
  ASSERT_EQ(xs.size(), 4u);
  const double want[4][2] = {{1.0, 1.5}, {1.5, 1.0}, {1.0, 1.5}, {1.5, 1.0}};
  for (int i = 0; i < 4; ++i) {
    const Computations c = prepare_computations(xs[i], r, xs);
    EXPECT_DOUBLE_EQ(c.n1, want[i][0]) << "intersection " << i;
    EXPECT_DOUBLE_EQ(c.n2, want[i][1]) << "intersection " << i;
  }
}

TEST(Torus, AGlassTorusShadesWithoutBlackPixels) {
  // Looking through the hole of a glass torus at a lit sphere behind it:
  // every ray must come back finite and not black.
  World w;
  w.lights.push_back({point(-10, 10, -10), Color{1, 1, 1}});
  auto t = std::make_shared<Torus>(1, 0.25);
  t->material.transparency = 0.9;
  t->material.refractive_index = 1.5;
  t->material.reflective = 0.1;
  t->set_transform(rotation_x(M_PI / 2));  // ring faces the camera (axis along z -> y... axis now -y)
  w.objects.push_back(t);
  auto s = std::make_shared<Sphere>();
  s->set_transform(translation(0, 0, 5) * scaling(3, 3, 3));
  w.objects.push_back(s);
  for (double x = -1.3; x <= 1.3; x += 0.05) {
    const Color c = color_at(w, {point(x, 0, -10), vector(0, 0, 1)});
    EXPECT_TRUE(std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b));
    EXPECT_GT(c.r + c.g + c.b, 0.0) << "black pixel at x = " << x;
  }
}

}  // namespace
}  // namespace toroid
