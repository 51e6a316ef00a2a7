// SPDX-License-Identifier: Apache-2.0
// Capped partial tori (`caps: true`): each cut of the sweep closed with the
// tube's disc (theta cuts) or the cone its radius sweeps (phi cuts), so that
// the torus bounds a solid. Checked against an independent inside test of
// that solid on random rays (every hit crosses its boundary, entering and
// leaving in turn), on known rays, and through CSG.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "support/approx.h"
#include "support/torus_cases.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/sphere.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

std::shared_ptr<Torus> capped_torus(double theta_max, double phi_min = -M_PI, double phi_max = M_PI, double major = 1,
                                    double minor = 0.25) {
  auto t = std::make_shared<Torus>(major, minor);
  t->set_sweep({theta_max, phi_min, phi_max});
  t->set_caps(true);
  return t;
}

// The solid a capped torus bounds, written out from its definition: within
// the tube, theta (from +x towards +y, in [0, 2 pi)) at most theta_max, phi
// (around the tube from the outer equator) in [phi_min, phi_max] mod 2 pi.
bool inside_solid(const Torus& t, const Tuple& p) {
  const double rho = std::hypot(p.x, p.y);
  const double a = rho - t.major();
  if (a * a + p.z * p.z > t.minor() * t.minor()) return false;
  double theta = std::atan2(p.y, p.x);
  if (theta < 0) theta += 2 * M_PI;
  const TorusSweep& s = t.sweep();
  if (theta > s.theta_max) return false;
  const double phi = std::atan2(p.z, a);
  for (const double f : {phi, phi - 2 * M_PI, phi + 2 * M_PI})
    if (f >= s.phi_min && f <= s.phi_max) return true;
  return false;
}

// A ray from a sphere of radius 4 around the torus towards a random point
// of a box a little larger than the torus's.
Ray random_ray(std::mt19937_64& rng, double major, double minor) {
  std::uniform_real_distribution<double> u(-1, 1);
  Tuple from;
  do from = vector(u(rng), u(rng), u(rng));
  while (magnitude(from) > 1 || magnitude(from) < 0.1);
  const double reach = major + minor;
  const Tuple to = point(1.1 * reach * u(rng), 1.1 * reach * u(rng), 1.2 * minor * u(rng));
  const Tuple origin = point(0, 0, 0) + normalize(from) * (4 * reach);
  return {origin, normalize(to - origin)};
}

struct Sweep {
  double theta_max, phi_min, phi_max;
  double minor;
};

// Theta cuts only, phi cuts only (flat, across pi, a sector wider than pi,
// a thin band, cylinders at +-pi/2), both, and a horn torus (minor = major).
const Sweep kSweeps[] = {
    {M_PI, -M_PI, M_PI, 0.25},
    {1.5 * M_PI, -M_PI, M_PI, 0.25},
    {0.7, -M_PI, M_PI, 0.25},
    {2 * M_PI, 0, M_PI, 0.25},
    {2 * M_PI, M_PI / 2, 3 * M_PI / 2, 0.25},
    {2 * M_PI, -M_PI / 2, M_PI / 2, 0.25},
    {2 * M_PI, 0.45, 2.75, 0.25},
    {2 * M_PI, -2.5, 1.0, 0.4},
    {4.4, 0.45, 2.75, 0.36},
    {5.0, -0.3, 4.0, 0.25},
    {1.2, M_PI / 3, 2 * M_PI / 3, 0.25},
    {4.0, -M_PI, M_PI, 1.0},
    {3.0, 0, M_PI, 1.0},
};

// Along every random ray the hits are the boundary crossings of the solid,
// listed in order: an even number, the solid entered and left in turn (the midpoints between
// hits alternate inside and outside, with the normal facing the ray on
// entering and away on leaving), and each hit lies in the torus's box.
TEST(TorusCaps, EveryRayCrossesTheSolidsBoundaryAtEveryHitAndAnEvenNumberOfTimes) {
  std::mt19937_64 rng(17);
  for (const Sweep& sw : kSweeps) {
    const auto t = capped_torus(sw.theta_max, sw.phi_min, sw.phi_max, 1, sw.minor);
    ASSERT_TRUE(t->capped());
    const BoundingBox box = t->bounds();
    const double pad = 1e-12;
    int hit_rays = 0, cap_hits = 0, most = 0;
    for (int i = 0; i < 20000; ++i) {
      const Ray r = random_ray(rng, 1, sw.minor);
      Intersections xs;
      t->intersect(r, xs);
      SCOPED_TRACE(::testing::Message() << "sweep " << sw.theta_max << " " << sw.phi_min << " " << sw.phi_max
                                        << " r=" << sw.minor << " ray " << i);
      // In order as listed, as CSG and refraction read them.
      ASSERT_TRUE(std::is_sorted(xs.begin(), xs.end(), [](const auto& a, const auto& b) { return a.t < b.t; }));
      ASSERT_EQ(xs.size() % 2, 0u);
      hit_rays += !xs.empty();
      most = std::max(most, static_cast<int>(xs.size()));
      for (std::size_t k = 0; k < xs.size(); ++k) {
        const Tuple p = r.position(xs[k].t);
        ASSERT_TRUE(p.x >= box.min.x - pad && p.x <= box.max.x + pad && p.y >= box.min.y - pad &&
                    p.y <= box.max.y + pad && p.z >= box.min.z - pad && p.z <= box.max.z + pad);
        cap_hits += Torus::face_of(xs[k]) != TorusFace::Tube;
        const double facing = dot(t->normal_at(p, xs[k]), r.direction);
        if (std::abs(facing) > 1e-6) {
          ASSERT_EQ(facing < 0, k % 2 == 0) << "hit " << k << " of " << xs.size();
        }
        const double next = k + 1 < xs.size() ? xs[k + 1].t : xs[k].t + 10;
        if (next - xs[k].t > 1e-9) {
          ASSERT_EQ(inside_solid(*t, r.position((xs[k].t + next) / 2)), k % 2 == 0) << "after hit " << k;
        }
      }
      if (!xs.empty() && xs[0].t > 1e-9) {
        ASSERT_FALSE(inside_solid(*t, r.position(xs[0].t / 2)));
      }
    }
    EXPECT_GT(hit_rays, 1000);
    EXPECT_GT(cap_hits, 500);
    EXPECT_LE(most, Torus::kMaxHits);
  }
}

TEST(TorusCaps, ARayThroughTheCutEntersAtTheCapAndLeavesThroughTheTube) {
  // Half a torus (y >= 0) and a ray along y into its cut at theta = pi
  // (the disc about (-1, 0, 0)): open, it meets only the tube's inside.
  const auto open = partial_torus(M_PI);
  const Ray r{point(-1, -5, 0), vector(0, 1, 0)};
  ASSERT_EQ(intersect_sorted(*open, r).size(), 1u);
  const auto t = capped_torus(M_PI);
  const Intersections xs = intersect_sorted(*t, r);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_DOUBLE_EQ(xs[0].t, 5);  // the cap
  EXPECT_EQ(Torus::face_of(xs[0]), TorusFace::ThetaEnd);
  EXPECT_DOUBLE_EQ(xs[1].t, 5.75);  // out through the tube at y = 0.75
  EXPECT_EQ(Torus::face_of(xs[1]), TorusFace::Tube);
  EXPECT_APPROX(t->normal_at(point(-1, 0, 0), xs[0]), vector(0, -1, 0));
  EXPECT_APPROX(t->normal_at(point(-1, 0.75, 0), xs[1]), vector(-0.8, 0.6, 0));
  // The same at the other cut, theta = 0.
  const Intersections ys = intersect_sorted(*t, {point(1, -5, 0.1), vector(0, 1, 0)});
  ASSERT_EQ(ys.size(), 2u);
  EXPECT_DOUBLE_EQ(ys[0].t, 5);
  EXPECT_EQ(Torus::face_of(ys[0]), TorusFace::ThetaStart);
  EXPECT_APPROX(t->normal_at(point(1, 0, 0.1), ys[0]), vector(0, -1, 0));
}

TEST(TorusCaps, AChordOfTheCentreCircleMeetsBothCaps) {
  // theta_max = pi/3: the caps are the discs about (1, 0, 0) and (cos pi/3,
  // sin pi/3, 0). The chord between those centres (length 1) stays in the
  // tube (it comes within cos(pi/6) = 0.87 of the axis).
  const auto t = capped_torus(M_PI / 3);
  const Tuple a = point(1, 0, 0), b = point(0.5, std::sqrt(0.75), 0);
  const Tuple d = b - a;
  const Intersections xs = intersect_sorted(*t, {a - d * 5, d});
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_NEAR(xs[0].t, 5, 1e-12);
  EXPECT_NEAR(xs[1].t, 6, 1e-12);
  EXPECT_EQ(Torus::face_of(xs[0]), TorusFace::ThetaStart);
  EXPECT_EQ(Torus::face_of(xs[1]), TorusFace::ThetaEnd);
  EXPECT_APPROX(t->normal_at(b, xs[1]), vector(-std::sqrt(0.75), 0.5, 0));
}

TEST(TorusCaps, ARayCanCrossACappedTorusSixTimes) {
  // A small bite (theta from 2 pi - 0.3 to 2 pi) and a chord through the
  // hole, 0.7 from the axis, whose second passage through the tube spans the
  // bite: in and out of the tube, then in, out at the cap theta = theta_max,
  // in at the cap theta = 0 and out of the tube. More than the four roots a
  // torus has.
  const auto t = capped_torus(2 * M_PI - 0.3);
  const double alpha = -0.15 - (std::acos(0.7 / 1.25) + std::acos(0.7 / 0.75)) / 2;
  const Tuple foot = point(0.7 * std::cos(alpha), 0.7 * std::sin(alpha), 0);
  const Tuple d = vector(-std::sin(alpha), std::cos(alpha), 0);
  const Intersections xs = intersect_sorted(*t, {foot - d * 5, d});
  ASSERT_EQ(xs.size(), 6u);
  const TorusFace want[6] = {TorusFace::Tube,     TorusFace::Tube,       TorusFace::Tube,
                             TorusFace::ThetaEnd, TorusFace::ThetaStart, TorusFace::Tube};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(Torus::face_of(xs[i]), want[i]) << "hit " << i;
  // The caps lie where the chord crosses theta = -0.3 and theta = 0.
  EXPECT_NEAR(xs[3].t, 5 + 0.7 * std::tan(-0.3 - alpha), 1e-12);
  EXPECT_NEAR(xs[4].t, 5 + 0.7 * std::tan(-alpha), 1e-12);
}

TEST(TorusCaps, PhiCutsAreClosedByAnnuliConesAndCylinders) {
  // The top half of the tube (phi 0..pi): closed below by the annulus z = 0.
  const auto top = capped_torus(2 * M_PI, 0, M_PI);
  const Ray up{point(1.1, 0, -5), vector(0, 0, 1)};
  const Intersections xs = intersect_sorted(*top, up);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_DOUBLE_EQ(xs[0].t, 5);
  EXPECT_EQ(Torus::face_of(xs[0]), TorusFace::PhiMin);  // the outer half, phi = 0
  EXPECT_APPROX(top->normal_at(point(1.1, 0, 0), xs[0]), vector(0, 0, -1));
  const Intersections ys = intersect_sorted(*top, {point(0.9, 0, -5), vector(0, 0, 1)});
  ASSERT_EQ(ys.size(), 2u);
  EXPECT_EQ(Torus::face_of(ys[0]), TorusFace::PhiMax);  // the inner half, phi = pi
  EXPECT_APPROX(top->normal_at(point(0.9, 0, 0), ys[0]), vector(0, 0, -1));

  // The outer half (phi -pi/2..pi/2): closed by the cylinder rho = 1.
  const auto outer = capped_torus(2 * M_PI, -M_PI / 2, M_PI / 2);
  const Intersections zs = intersect_sorted(*outer, {point(-5, 0, 0.1), vector(1, 0, 0)});
  // In at x = -1.2 (the tube), out at x = -1 (the cylinder), then in at
  // x = 1 and out at x = 1.2.
  ASSERT_EQ(zs.size(), 4u);
  const double rim = std::sqrt(0.25 * 0.25 - 0.01);
  EXPECT_NEAR(zs[0].t, 5 - 1 - rim, 1e-12);
  EXPECT_NEAR(zs[1].t, 4, 1e-12);
  EXPECT_NEAR(zs[2].t, 6, 1e-12);
  EXPECT_NEAR(zs[3].t, 6 + rim, 1e-12);
  EXPECT_EQ(Torus::face_of(zs[1]), TorusFace::PhiMax);  // z > 0: the top half of the cylinder
  EXPECT_APPROX(outer->normal_at(point(-1, 0, 0.1), zs[1]), vector(1, 0, 0));
  EXPECT_APPROX(outer->normal_at(point(1, 0, 0.1), zs[2]), vector(-1, 0, 0));
  const Intersections ws = intersect_sorted(*outer, {point(-5, 0, -0.1), vector(1, 0, 0)});
  ASSERT_EQ(ws.size(), 4u);
  EXPECT_EQ(Torus::face_of(ws[1]), TorusFace::PhiMin);

  // A cone: phi 0..pi/4, a wedge of the tube; its cap at pi/4 is the cone
  // z = rho - 1 for rho in [1, 1 + 0.25 cos(pi/4)]. Down through it at
  // rho = 1.1: in at z = 0.1 (the cone), out at z = 0 (the annulus).
  const auto wedge = capped_torus(2 * M_PI, 0, M_PI / 4);
  const Intersections vs = intersect_sorted(*wedge, {point(0, 1.1, 5), vector(0, 0, -1)});
  ASSERT_EQ(vs.size(), 2u);
  EXPECT_NEAR(vs[0].t, 4.9, 1e-12);
  EXPECT_NEAR(vs[1].t, 5, 1e-12);
  EXPECT_EQ(Torus::face_of(vs[0]), TorusFace::PhiMax);
  EXPECT_EQ(Torus::face_of(vs[1]), TorusFace::PhiMin);
  const double s = std::sqrt(0.5);
  EXPECT_APPROX(wedge->normal_at(point(0, 1.1, 0.1), vs[0]), vector(0, -s, s));
}

TEST(TorusCaps, ThetaCapsOfAPhiCutTorusAreSectorsOfTheDisc) {
  // theta to pi/2 and the top half of the tube: the cap at theta = 0 is the
  // upper half of the disc. A ray along y just below z = 0 passes under the
  // solid (the bottom half of the tube is gone, and so is the lower half of
  // the disc); just above it, it enters through the cap.
  const auto t = capped_torus(M_PI / 2, 0, M_PI);
  EXPECT_TRUE(intersect_sorted(*t, {point(1, -5, -0.1), vector(0, 1, 0)}).empty());
  const Intersections xs = intersect_sorted(*t, {point(1, -5, 0.1), vector(0, 1, 0)});
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_EQ(Torus::face_of(xs[0]), TorusFace::ThetaStart);
  EXPECT_EQ(Torus::face_of(xs[1]), TorusFace::Tube);
}

TEST(TorusCaps, TheNearestHitAndTheShadowTestAgreeWithTheListOfHits) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  for (const Sweep& sw : kSweeps) {
    const auto t = capped_torus(sw.theta_max, sw.phi_min, sw.phi_max, 1, sw.minor);
    t->set_transform(translation(0.3, -0.2, 0.1) * rotation_x(0.4) * scaling(1.5, 1.5, 1.5));
    for (int i = 0; i < 4000; ++i) {
      Ray r = random_ray(rng, 1.5, 1.5 * sw.minor);
      // Start some rays inside the solid or beyond a hit.
      r.origin = r.position(6 * u(rng));
      const double t_max = u(rng) < 0.2 ? std::numeric_limits<double>::infinity() : 10 * u(rng);
      Intersections xs;
      t->intersect(r, xs);
      const Intersection* want = nullptr;
      for (const Intersection& x : xs)
        if (x.t >= 0 && x.t < t_max && (!want || x.t < want->t)) want = &x;
      Intersection got;
      const bool found = t->intersect_nearest(r, t_max, got);
      SCOPED_TRACE(::testing::Message() << "ray " << i);
      ASSERT_EQ(found, want != nullptr);
      ASSERT_EQ(t->blocks(r, t_max), want != nullptr);
      if (found) {
        EXPECT_EQ(got.t, want->t);
        EXPECT_EQ(Torus::face_of(got), Torus::face_of(*want));
      }
    }
  }
}

TEST(TorusCaps, TheBoxesHoldTheCapsReachingInToTheCentreCircle) {
  // A band around the top of the tube (phi pi/3..2pi/3) reaches z = r sin
  // pi/3 at its lowest; capped, the wedge reaches in to the centre circle
  // (z = 0, rho = 1).
  const auto band = partial_torus(2 * M_PI, M_PI / 3, 2 * M_PI / 3);
  EXPECT_NEAR(band->bounds().min.z, 0.25 * std::sin(M_PI / 3), 1e-15);
  const auto t = capped_torus(2 * M_PI, M_PI / 3, 2 * M_PI / 3);
  EXPECT_APPROX(t->bounds().min, point(-1.125, -1.125, 0));
  EXPECT_APPROX(t->bounds().max, point(1.125, 1.125, 0.25));
  // The outer quarter (phi -pi/4..pi/4) reaches in to rho = 1.
  const auto q = capped_torus(M_PI / 2, -M_PI / 4, M_PI / 4);
  EXPECT_APPROX(q->bounds().min, point(0, 0, -0.25 * std::sqrt(0.5)));
  EXPECT_APPROX(q->bounds().max, point(1.25, 1.25, 0.25 * std::sqrt(0.5)));
  // Transformed, the parent-space box holds every cap point.
  t->set_transform(translation(1, 2, 3) * rotation_y(0.6) * scaling(2, 1, 0.5));
  const BoundingBox b = t->parent_space_bounds();
  for (int i = 0; i < 200; ++i)
    for (int j = 0; j <= 20; ++j) {
      const double theta = 2 * M_PI * i / 200, s = 0.25 * j / 20;
      for (const double phi : {M_PI / 3, 2 * M_PI / 3}) {
        const double rho = 1 + s * std::cos(phi);
        EXPECT_TRUE(
            b.contains_point(t->transform() * point(rho * std::cos(theta), rho * std::sin(theta), s * std::sin(phi))));
      }
    }
}

TEST(TorusCaps, CapsOnAWholeTorusChangeNothing) {
  auto whole = std::make_shared<Torus>(1, 0.25);
  whole->set_caps(true);
  EXPECT_TRUE(whole->caps());
  EXPECT_FALSE(whole->capped());
  const Torus plain(1, 0.25);
  const Ray r{point(-5, 0.1, 0.05), vector(1, 0, 0)};
  const Intersections a = intersect_sorted(*whole, r), b = intersect_sorted(plain, r);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].t, b[i].t);
  // Cutting it later puts them in effect; making it whole again removes them.
  whole->set_sweep({M_PI, -M_PI, M_PI});
  EXPECT_TRUE(whole->capped());
  whole->set_sweep({});
  EXPECT_FALSE(whole->capped());
  // Off again: the open partial torus.
  const auto t = capped_torus(M_PI);
  t->set_caps(false);
  EXPECT_EQ(intersect_sorted(*t, {point(-1, -5, 0), vector(0, 1, 0)}).size(), 1u);
}

TEST(TorusCaps, APartialSpindleTorusIsNotCapped) {
  auto t = std::make_shared<Torus>(1, 1.5);
  t->set_sweep({M_PI, -M_PI, M_PI});
  t->set_caps(true);
  EXPECT_FALSE(t->capped());
  // A horn torus is.
  const auto horn = capped_torus(M_PI, -M_PI, M_PI, 1, 1);
  EXPECT_TRUE(horn->capped());
}

// CSG treats a capped torus as the solid it bounds: the difference with a
// sphere is exactly the points inside the torus's solid and outside the
// ball, along every ray (the sphere bites into the cut at theta = 0).
TEST(TorusCaps, CsgOfACappedTorusMinusASphereHasNoHole) {
  const auto t = capped_torus(1.5 * M_PI);
  auto ball = std::make_shared<Sphere>();
  const Tuple centre = point(1.2, 0, 0.15);
  const double radius = 0.2;
  ball->set_transform(translation(centre.x, centre.y, centre.z) * scaling(radius, radius, radius));
  const Csg bitten(CsgOp::Difference, t, ball);
  std::mt19937_64 rng(3);
  int crossings = 0;
  for (int i = 0; i < 20000; ++i) {
    const Ray r = random_ray(rng, 1, 0.25);
    Intersections xs;
    bitten.intersect(r, xs);
    SCOPED_TRACE(::testing::Message() << "ray " << i);
    ASSERT_EQ(xs.size() % 2, 0u);
    for (std::size_t k = 0; k < xs.size(); ++k) {
      const double next = k + 1 < xs.size() ? xs[k + 1].t : xs[k].t + 10;
      if (next - xs[k].t < 1e-9) continue;
      const Tuple m = r.position((xs[k].t + next) / 2);
      const bool in = inside_solid(*t, m) && magnitude(m - centre) > radius;
      ASSERT_EQ(in, k % 2 == 0) << "after hit " << k;
      ++crossings;
    }
  }
  EXPECT_GT(crossings, 2000);
}

}  // namespace
}  // namespace toroid
