// SPDX-License-Identifier: Apache-2.0
// The Torus shape in the RTC scenario style: intersections, normals,
// transforms, bounds, groups, CSG, partial and spindle tori.
#include "toroid/shapes/torus.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/approx.h"
#include "support/torus_cases.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/cube.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/sphere.h"
#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid {
namespace {

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
  EXPECT_APPROX(t.normal_at(point(1.25, 0, 0)), vector(1, 0, 0));     // outer equator
  EXPECT_APPROX(t.normal_at(point(0.75, 0, 0)), vector(-1, 0, 0));    // inner equator
  EXPECT_APPROX(t.normal_at(point(0, 1, 0.25)), vector(0, 0, 1));     // top
  EXPECT_APPROX(t.normal_at(point(0, -1, -0.25)), vector(0, 0, -1));  // bottom
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

TEST(Torus, ParentSpaceBoundsAreExactUnderAnyAffineTransform) {
  // Rotated, sheared and unevenly scaled tori (a spindle too): every surface
  // point lies in the box, and on each side some point comes within 0.1% of
  // the box's size (a transformed object box is up to 41% wider).
  const Matrix4 transforms[] = {
      rotation_z(M_PI / 4),
      translation(3, -2, 5) * rotation_y(0.7) * rotation_x(1.1),
      translation(-1e3, 4e3, 2) * shearing(0.3, 0, 0.2, 0.1, 0, 0.5) * scaling(2, 0.5, 1.5) * rotation_x(0.4),
  };
  for (const double minor : {0.25, 1.5})
    for (const Matrix4& m : transforms) {
      Torus t(1, minor);
      t.set_transform(m);
      const BoundingBox b = t.parent_space_bounds();
      BoundingBox reached;
      for (int i = 0; i < 720; ++i)
        for (int j = 0; j < 720; ++j) {
          const double theta = 2 * M_PI * i / 720, phi = 2 * M_PI * j / 720;
          const double rho = 1 + minor * std::cos(phi);
          const Tuple p = m * point(rho * std::cos(theta), rho * std::sin(theta), minor * std::sin(phi));
          ASSERT_TRUE(b.contains_point(p));
          reached.add_point(p);
        }
      const double tol = 1e-3 * magnitude(b.max - b.min);
      EXPECT_NEAR(reached.min.x, b.min.x, tol);
      EXPECT_NEAR(reached.min.y, b.min.y, tol);
      EXPECT_NEAR(reached.min.z, b.min.z, tol);
      EXPECT_NEAR(reached.max.x, b.max.x, tol);
      EXPECT_NEAR(reached.max.y, b.max.y, tol);
      EXPECT_NEAR(reached.max.z, b.max.z, tol);
    }
}

TEST(Torus, APartialTorusKeepsItsTransformedObjectBox) {
  Torus t(1, 0.25);
  t.set_sweep({M_PI, -M_PI, M_PI});
  t.set_transform(rotation_z(0.3));
  const BoundingBox expected = transform(t.bounds(), t.transform());
  EXPECT_APPROX(t.parent_space_bounds().min, expected.min);
  EXPECT_APPROX(t.parent_space_bounds().max, expected.max);
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

// Partial tori (RenderMan's RiTorus: theta-max, phi-min, phi-max) --------

TEST(Torus, SweepRanges) {
  EXPECT_TRUE(TorusSweep{}.valid());
  EXPECT_TRUE(TorusSweep{}.whole());
  EXPECT_TRUE((TorusSweep{M_PI, M_PI / 2, 3 * M_PI / 2}.valid()));
  EXPECT_FALSE((TorusSweep{M_PI, M_PI / 2, 3 * M_PI / 2}.whole()));
  EXPECT_TRUE((TorusSweep{2 * M_PI, 0, 2 * M_PI}.whole()));
  EXPECT_FALSE((TorusSweep{0, -M_PI, M_PI}.valid()));
  EXPECT_FALSE((TorusSweep{7, -M_PI, M_PI}.valid()));
  EXPECT_FALSE((TorusSweep{M_PI, 1, 1}.valid()));
  EXPECT_FALSE((TorusSweep{M_PI, -4, 4}.valid()));
  EXPECT_FALSE((TorusSweep{M_PI, -7, 0}.valid()));
  EXPECT_FALSE((TorusSweep{NAN, -M_PI, M_PI}.valid()));
}

TEST(Torus, ARayHittingTheRemovedHalfPassesToTheNextRoot) {
  const auto t = partial_torus(M_PI);  // y >= 0 kept
  // Along y at x = 1: the whole torus is met at y = -0.75 and y = 0.75.
  const Intersections xs = intersect_sorted(*t, {point(1, -5, 0), vector(0, 1, 0)});
  ASSERT_EQ(xs.size(), 1u);
  EXPECT_DOUBLE_EQ(xs[0].t, 5.75);
  EXPECT_EQ(xs[0].object, t.get());
}

TEST(Torus, ARayThroughTheRemovedHalfMisses) {
  const auto t = partial_torus(M_PI);
  EXPECT_TRUE(intersect_sorted(*t, {point(-5, -1, 0), vector(1, 0, 0)}).empty());
  // The same ray at y = +1 meets the kept half twice.
  EXPECT_EQ(intersect_sorted(*t, {point(-5, 1, 0), vector(1, 0, 0)}).size(), 2u);
}

TEST(Torus, APhiSweepAcrossPiKeepsTheInnerHalf) {
  // phi from pi/2 to 3 pi/2 wraps past pi: the half of the tube facing the axis.
  const auto t = partial_torus(2 * M_PI, M_PI / 2, 3 * M_PI / 2);
  const Intersections xs = intersect_sorted(*t, {point(-5, 0, 0), vector(1, 0, 0)});
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_DOUBLE_EQ(xs[0].t, 4.25);
  EXPECT_DOUBLE_EQ(xs[1].t, 5.75);
  // The same sweep written from -3 pi/2 to -pi/2.
  const auto u = partial_torus(2 * M_PI, -3 * M_PI / 2, -M_PI / 2);
  const Intersections ys = intersect_sorted(*u, {point(-5, 0, 0), vector(1, 0, 0)});
  ASSERT_EQ(ys.size(), 2u);
  EXPECT_DOUBLE_EQ(ys[0].t, 4.25);
}

TEST(Torus, ThetaAndPhiOfKnownPoints) {
  const double p[][3] = {{1.25, 0, 0}, {0, 1, 0.25}, {-0.75, 0, 0}, {0, -1, -0.25}, {1, 0, 0.25}};
  const double want[][2] = {{0, 0}, {M_PI / 2, M_PI / 2}, {M_PI, M_PI}, {3 * M_PI / 2, -M_PI / 2}, {0, M_PI / 2}};
  for (int i = 0; i < 5; ++i) {
    double theta, phi;
    torus_angles(1, 0.25, p[i], &theta, &phi);
    EXPECT_NEAR(theta, want[i][0], 1e-15) << "point " << i;
    EXPECT_NEAR(phi, want[i][1], 1e-15) << "point " << i;
  }
}

TEST(Torus, NormalsOfAPartialTorusAreThoseOfTheWholeOne) {
  const auto t = partial_torus(M_PI / 2, 0, M_PI);
  EXPECT_APPROX(t->normal_at(point(1.25, 0, 0)), vector(1, 0, 0));
  EXPECT_APPROX(t->normal_at(point(0, 1, 0.25)), vector(0, 0, 1));
  const double s = std::sqrt(0.5);
  EXPECT_APPROX(t->normal_at(point(s * 0.75, s * 0.75, 0)), vector(-s, -s, 0));
}

TEST(Torus, BoundsShrinkToTheSweptPart) {
  struct Case {
    double theta_max, phi_min, phi_max;
    Tuple min, max;
  };
  const double c = std::sqrt(0.5);
  const Case cases[] = {
      {M_PI, -M_PI, M_PI, point(-1.25, 0, -0.25), point(1.25, 1.25, 0.25)},
      {M_PI / 2, -M_PI, M_PI, point(0, 0, -0.25), point(1.25, 1.25, 0.25)},
      {3 * M_PI / 4, -M_PI, M_PI, point(-1.25 * c, 0, -0.25), point(1.25, 1.25, 0.25)},
      {3 * M_PI / 2, -M_PI, M_PI, point(-1.25, -1.25, -0.25), point(1.25, 1.25, 0.25)},
      {2 * M_PI, 0, M_PI, point(-1.25, -1.25, 0), point(1.25, 1.25, 0.25)},
      {2 * M_PI, -M_PI / 2, 0, point(-1.25, -1.25, -0.25), point(1.25, 1.25, 0)},
      // The outer half of the tube over an eighth of the turn.
      {M_PI / 4, -M_PI / 2, M_PI / 2, point(c, 0, -0.25), point(1.25, 1.25 * c, 0.25)},
      // A thin band around the top: z >= 0.25 sin(pi/3), radius 1 +- 0.125.
      {2 * M_PI, M_PI / 3, 2 * M_PI / 3, point(-1.125, -1.125, 0.25 * std::sin(M_PI / 3)), point(1.125, 1.125, 0.25)},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(::testing::Message() << k.theta_max << " " << k.phi_min << " " << k.phi_max);
    const auto t = partial_torus(k.theta_max, k.phi_min, k.phi_max);
    const BoundingBox b = t->bounds();
    EXPECT_APPROX(b.min, k.min);
    EXPECT_APPROX(b.max, k.max);
  }
}

TEST(Torus, EveryKeptPointLiesInTheBoundsAndIsKept) {
  // Points on the parametric surface inside the sweep are kept and bounded;
  // points outside it are not kept. Spindle tori (the lemon: R + r cos phi
  // < 0) included.
  const double sweeps[][3] = {{M_PI, -M_PI, M_PI}, {1.0, -0.5, 2.5}, {5.0, -5.5, 0.25}, {2 * M_PI, 2.0, 4.0}};
  for (const double minor : {0.25, 1.0, 1.5}) {
    for (const auto& sw : sweeps) {
      Torus t(1, minor);
      t.set_sweep({sw[0], sw[1], sw[2]});
      const BoundingBox b = t.bounds();
      for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
          const double theta = 2 * M_PI * (i + 0.37) / 41, phi = -M_PI + 2 * M_PI * (j + 0.61) / 41;
          const double rho = 1 + minor * std::cos(phi);
          const Tuple p = point(rho * std::cos(theta), rho * std::sin(theta), minor * std::sin(phi));
          if (std::abs(rho) < 1e-9) continue;  // the axis: theta is not defined
          const bool in_phi = (phi >= sw[1] && phi <= sw[2]) || (phi + 2 * M_PI >= sw[1] && phi + 2 * M_PI <= sw[2]) ||
                              (phi - 2 * M_PI >= sw[1] && phi - 2 * M_PI <= sw[2]);
          const bool inside = theta <= sw[0] && in_phi;
          SCOPED_TRACE(::testing::Message() << "r=" << minor << " theta=" << theta << " phi=" << phi);
          EXPECT_EQ(t.keeps(p), inside);
          if (inside) {
            EXPECT_TRUE(b.contains_point(p));
          }
        }
    }
  }
}

// Spindle and horn tori (r >= R) --------------------------------------------

TEST(Torus, ASpindleTorusAlongItsEquatorMeetsTheOuterSheetAndTheLemon) {
  // R = 1, r = 1.5: the outer sheet at |x| = 2.5, the lemon at |x| = 0.5.
  Torus t(1, 1.5);
  const Ray r{point(-5, 0, 0), vector(1, 0, 0)};
  const Intersections whole = intersect_sorted(t, r);
  ASSERT_EQ(whole.size(), 4u);
  const double want[4] = {2.5, 4.5, 5.5, 7.5};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(whole[i].t, want[i], 1e-12);
  EXPECT_APPROX(t.normal_at(point(-0.5, 0, 0)), vector(-1, 0, 0));  // the lemon's outside
  const double lemon[3] = {-0.5, 0, 0}, outer[3] = {-2.5, 0, 0};
  EXPECT_TRUE(on_torus_lemon(1, 1.5, lemon));
  EXPECT_FALSE(on_torus_lemon(1, 1.5, outer));

  t.set_spindle(SpindleSurface::Outer);
  const Intersections outside = intersect_sorted(t, r);
  ASSERT_EQ(outside.size(), 2u);
  EXPECT_NEAR(outside[0].t, 2.5, 1e-12);
  EXPECT_NEAR(outside[1].t, 7.5, 1e-12);
}

TEST(Torus, TheLemonHasTheParametricAnglesOfRiTorus) {
  // On the lemon R + r cos(phi) < 0: (-0.5, 0, 0) is theta = 0, phi = pi.
  double theta, phi;
  const double lemon[3] = {-0.5, 0, 0};
  torus_angles(1, 1.5, lemon, &theta, &phi);
  EXPECT_NEAR(theta, 0, 1e-15);
  EXPECT_NEAR(phi, M_PI, 1e-15);
  // So sweeping theta to pi keeps the lemon's half at x < 0, across the axis
  // from the kept outer half (y >= 0).
  Torus t(1, 1.5);
  t.set_sweep({M_PI, -M_PI, M_PI});
  const Intersections xs = intersect_sorted(t, {point(-0.3, -5, 0), vector(0, 1, 0)});
  // Along y at x = -0.3: outer sheet at y = +-sqrt(2.5^2 - 0.09), kept for
  // y > 0; the lemon at y = +-0.4, kept for y < 0 (theta = atan2 + pi < pi).
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0].t, 5 - 0.4, 1e-12);
  EXPECT_NEAR(xs[1].t, 5 + std::sqrt(2.5 * 2.5 - 0.09), 1e-12);
}

TEST(Torus, SpindleAndHornToriHaveNoCrackAtTheAxis) {
  // Rays down the axis and just beside it, and rays crossing the axis at the
  // apex at several slopes, must all meet the surface near the apex.
  for (const double minor : {1.0, 1.5, 3.0}) {
    for (const SpindleSurface mode : {SpindleSurface::Whole, SpindleSurface::Outer}) {
      Torus t(1, minor);
      t.set_spindle(mode);
      const double apex = std::sqrt(minor * minor - 1);  // 0 for the horn
      for (const double off : {0.0, 1e-12, 1e-9, 1e-6, 1e-3}) {
        const Intersections xs = intersect_sorted(t, {point(off, 0, 10), vector(0, 0, -1)});
        SCOPED_TRACE(::testing::Message() << "r=" << minor << " offset=" << off);
        ASSERT_GE(xs.size(), 2u);
        // The outer sheet at rho = off: z = sqrt(r^2 - (off - R)^2).
        const double z = std::sqrt(minor * minor - (off - 1) * (off - 1));
        EXPECT_NEAR(xs[0].t, 10 - z, 1e-6);
        EXPECT_NEAR(xs.back().t, 10 + z, 1e-6);
      }
      for (const double slope : {0.01, 0.3, 1.0, 5.0}) {
        const Tuple target = point(0, 0, apex);
        const Tuple d = normalize(vector(1, 0.3, slope));
        const Intersections xs = intersect_sorted(t, {target - d * 10, d});
        SCOPED_TRACE(::testing::Message() << "r=" << minor << " slope=" << slope);
        ASSERT_GE(xs.size(), 2u);
      }
    }
  }
}

}  // namespace
}  // namespace toroid

namespace toroid {
namespace {

// The surface bias scales with half_thickness(): a whole torus answers r
// without building its box, and that is what its box says too.
TEST(Torus, HalfThicknessIsTheTubeRadiusAsTheBoxSays) {
  for (const auto& [R, r] : {std::pair{1.0, 0.25}, {1.0, 1e-3}, {1.0, 1.5}, {1e4, 1.0}}) {
    const Torus t(R, r);
    const BoundingBox box = t.bounds();
    const double thinnest_half = std::min({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z}) / 2;
    EXPECT_EQ(t.half_thickness(), r);
    EXPECT_DOUBLE_EQ(t.half_thickness(), thinnest_half);
  }
}

}  // namespace
}  // namespace toroid
