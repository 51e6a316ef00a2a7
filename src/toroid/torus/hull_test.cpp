// SPDX-License-Identifier: Apache-2.0
// ray_leaves_hull and ray_leaves_through_hole (hull.h), the window queries'
// shortcuts for rays that leave the torus's convex hull or its hole: they
// must never pass a ray that meets the torus after its start (the all-roots
// call, which does not use them, is the judge), and they must pass the rays
// they are for.
#include "toroid/torus/hull.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

#include "toroid/torus/intersect.h"

namespace toroid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Torus {
  double R, r;
};

// Tori of every kind the window queries search (ring, thin, fat), at unit
// size and far from it.
constexpr Torus kTori[] = {{1, 0.25}, {1, 0.01}, {1, 0.9}, {1e3, 1}, {1e-3, 2e-4}, {5e4, 3e4}};

// A point `lift` off the tube along the normal at angles (theta, phi), and
// a random direction on the normal's side (outward for lift >= 0).
struct SurfaceRay {
  double o[3], d[3];
};

SurfaceRay surface_ray(const Torus& t, double theta, double phi, double lift, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double n[3] = {std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), std::sin(phi)};
  SurfaceRay s{};
  for (int i = 0; i < 3; ++i)
    s.o[i] = (i < 2 ? t.R * (i == 0 ? std::cos(theta) : std::sin(theta)) : 0) + (t.r + lift) * n[i];
  do {
    for (double& c : s.d) c = u(rng);
  } while (s.d[0] * n[0] + s.d[1] * n[1] + s.d[2] * n[2] <= 0);
  return s;
}

// Whether the all-roots list holds a root after t_min.
bool meets_after(const Torus& t, const double o[3], const double d[3], double t_min) {
  double roots[4];
  const int n = intersect_torus(t.R, t.r, o, d, roots);
  for (int i = 0; i < n; ++i)
    if (roots[i] > t_min) return true;
  return false;
}

// Of `rays` rays from 1e-5 torus sizes off the tube (a renderer's over-
// point) at tube angles phi in [phi_lo, phi_hi], outwards: how many `passes`
// passes, each checked to meet nothing after its start (fatal otherwise).
template <typename Passes>
int surface_rays_passed(const Torus& t, double phi_lo, double phi_hi, int rays, std::uint64_t seed, Passes passes) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), phi(phi_lo, phi_hi);
  int passed = 0;
  for (int i = 0; i < rays; ++i) {
    const SurfaceRay s = surface_ray(t, angle(rng), phi(rng), 1e-5 * (t.R + t.r), rng);
    if (!passes(s)) continue;
    ++passed;
    EXPECT_FALSE(meets_after(t, s.o, s.d, 0)) << "ray " << i;
    double nearest;
    EXPECT_FALSE(intersect_torus_nearest(t.R, t.r, s.o, s.d, 0, kInf, &nearest));
    EXPECT_FALSE(torus_blocks(t.R, t.r, s.o, s.d, 0, kInf));
  }
  return passed;
}

TEST(TorusHull, RaysLeavingTheOuterHalfOfTheTubePassAndMeetNothing) {
  for (const Torus& t : kTori) {
    SCOPED_TRACE(testing::Message() << "R " << t.R << " r " << t.r);
    constexpr int kRays = 2000;
    const int passed = surface_rays_passed(t, -M_PI / 2, M_PI / 2, kRays, 11,
                                           [&](const SurfaceRay& s) { return ray_leaves_hull(t.R, t.r, s.o, s.d, 0); });
    // All but the rays that leave nearly along the surface.
    EXPECT_GT(passed, 0.97 * kRays);
  }
}

TEST(TorusHull, RaysThatMeetTheTorusAfterTheirStartNeverPass) {
  // Rays through random points near the tube, in random directions, from
  // random starts along them before and after the tube: whatever the hull
  // test says, a ray it passes has no root after its start.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), u(-1, 1);
  for (const Torus& t : kTori) {
    SCOPED_TRACE(testing::Message() << "R " << t.R << " r " << t.r);
    const double size = t.R + t.r;
    int passed = 0, meeting = 0;
    for (int i = 0; i < 20000; ++i) {
      SurfaceRay s = surface_ray(t, angle(rng), angle(rng), t.r * u(rng), rng);
      for (double& c : s.d) c = u(rng);
      const double back = 2 * size * (u(rng) + 1);
      for (int k = 0; k < 3; ++k) s.o[k] -= back * s.d[k];
      const double t_min = i % 2 ? 0.0 : 2 * back * (u(rng) + 1);
      const bool meets = meets_after(t, s.o, s.d, t_min);
      meeting += meets;
      if (ray_leaves_hull(t.R, t.r, s.o, s.d, t_min)) {
        ++passed;
        ASSERT_FALSE(meets) << "ray " << i;
      }
    }
    // Both kinds are common, so the assertion above is a real test.
    EXPECT_GT(passed, 1000);
    EXPECT_GT(meeting, 1000);
  }
}

TEST(TorusHull, StartsOnTheSurfaceInsideOrFacingTheTorusDoNotPass) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), outer(-M_PI / 2, M_PI / 2);
  const Torus t{1, 0.25};
  for (int i = 0; i < 1000; ++i) {
    const double theta = angle(rng), phi = outer(rng);
    // On the surface (within rounding) and inside the tube: not outside the
    // hull by the margin.
    const SurfaceRay on = surface_ray(t, theta, phi, 0, rng);
    EXPECT_FALSE(ray_leaves_hull(t.R, t.r, on.o, on.d, 0)) << "on the surface, ray " << i;
    const SurfaceRay in = surface_ray(t, theta, phi, -1e-5, rng);
    EXPECT_FALSE(ray_leaves_hull(t.R, t.r, in.o, in.d, 0)) << "inside, ray " << i;
    // Outside, but moving towards the tube: the ray reversed.
    SurfaceRay back = surface_ray(t, theta, phi, 1e-5, rng);
    for (double& c : back.d) c = -c;
    EXPECT_FALSE(ray_leaves_hull(t.R, t.r, back.o, back.d, 0)) << "towards the tube, ray " << i;
  }
  // Starts at infinity or NaN are unsure, not passed.
  const double o[3] = {3, 0, 0}, d[3] = {1, 0, 0};
  EXPECT_TRUE(ray_leaves_hull(t.R, t.r, o, d, 0));
  EXPECT_FALSE(ray_leaves_hull(t.R, t.r, o, d, -kInf));
  EXPECT_FALSE(ray_leaves_hull(t.R, t.r, o, d, std::numeric_limits<double>::quiet_NaN()));
}

TEST(TorusHull, ARayBeyondTheSlabPassesOnlyWhileMovingAwayFromIt) {
  const Torus t{1, 0.25};
  // Above the hole and above the tube, rising or level: never meets the torus.
  for (const double x : {0.0, 0.5, 1.0, 1.2}) {
    SCOPED_TRACE(x);
    const double o[3] = {x, 0, 0.25 + 1e-6};
    const double up[3] = {0.3, -0.2, 1}, level[3] = {1, 1, 0}, down[3] = {0.1, 0, -1};
    EXPECT_TRUE(ray_leaves_hull(t.R, t.r, o, up, 0));
    EXPECT_TRUE(ray_leaves_hull(t.R, t.r, o, level, 0));
    EXPECT_FALSE(ray_leaves_hull(t.R, t.r, o, down, 0));
    if (x >= 1) {
      EXPECT_TRUE(meets_after(t, o, down, 0));  // down onto the tube (nearer the axis: the hole)
    }
  }
}

TEST(TorusHole, RaysLeavingTheInnerHalfUpwardsThroughTheHolePassAndMeetNothing) {
  for (const Torus& t : kTori) {
    SCOPED_TRACE(testing::Message() << "R " << t.R << " r " << t.r);
    constexpr int kRays = 4000;
    const int passed = surface_rays_passed(t, M_PI / 2, 3 * M_PI / 2, kRays, 21, [&](const SurfaceRay& s) {
      return ray_leaves_through_hole(t.R, t.r, s.o, s.d, 0);
    });
    // Rays from the inner half in random outward directions: many leave
    // through the hole nearer the axis (the others cross it).
    EXPECT_GT(passed, kRays / 10);
  }
}

TEST(TorusHole, RaysThatMeetTheTorusAfterTheirStartNeverPass) {
  // Rays from random points of the slab within rho < R (the hole, the tube's
  // inner half and inside it), in random directions: whatever the test
  // says, a ray it passes has no root after its start.
  std::mt19937_64 rng(22);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), u(-1, 1), unit(0, 1);
  for (const Torus& t : kTori) {
    SCOPED_TRACE(testing::Message() << "R " << t.R << " r " << t.r);
    int passed = 0, meeting = 0;
    for (int i = 0; i < 50000; ++i) {
      const double theta = angle(rng), rho = t.R * std::sqrt(unit(rng));
      const double o[3] = {rho * std::cos(theta), rho * std::sin(theta), t.r * u(rng)};
      const double d[3] = {u(rng), u(rng), u(rng)};
      const bool meets = meets_after(t, o, d, 0);
      meeting += meets;
      if (ray_leaves_through_hole(t.R, t.r, o, d, 0)) {
        ++passed;
        ASSERT_FALSE(meets) << "ray " << i;
      }
    }
    // Both kinds occur on every torus, so the assertion above is a real test.
    EXPECT_GT(passed, 500);
    EXPECT_GT(meeting, 200);
  }
}

// Found by intersect_fuzz: a ray almost parallel to the slab's top face
// (d_z ~ 1e-15 |d|), starting just below it inside the hole of a ring torus
// a hair short of a horn one, crosses the face where it started (t = 0,
// o_z = r) but the rounded q_z put the crossing at t = -0.005, before the ray
// has passed over the top of the tube: the test passed it, and the ray
// meets the torus at t = -0.0022.
TEST(TorusHole, ARayAlmostParallelToTheFaceIsNotPassedOnItsRoundedCrossing) {
  const double R = 1.038785616009364e-13, r = 1.0387856152602562e-13;
  const double o[3] = {7.105842330643226e-15, 1.0387866994624287e-13, 1.0387856152602562e-13};
  const double d[3] = {1.0387856152602562e-13, 1.0302869676730328e-13, 7.381454501549289e-28};
  const double t_min = -1.0660123280237737;
  double t[4];
  const int n = intersect_torus(R, r, o, d, t);
  ASSERT_EQ(n, 4);
  EXPECT_LT(t_min, t[2]);  // a root after the window's start
  EXPECT_FALSE(ray_leaves_through_hole(R, r, o, d, t_min));
  double nearest = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, r, o, d, t_min, kInf, &nearest));
  EXPECT_EQ(nearest, t[2]);
}

TEST(TorusHole, OnlyRingToriAndStartsOutsideTheTubeMovingOutOfTheSlabNearerTheAxis) {
  const Torus t{1, 0.25};
  // From the hole's side of the tube, at z = 0.1, rising steeply towards the axis: passes.
  const double o[3] = {0.75 - 1e-3, 0, 0.1}, up[3] = {-0.1, 0.05, 1};
  EXPECT_TRUE(ray_leaves_through_hole(t.R, t.r, o, up, 0));
  // Falling instead (|z| shrinks first), or level, or across the hole to its far side: not passed.
  const double down[3] = {-0.1, 0.05, -1}, level[3] = {-1, 0, 0}, across[3] = {-1, 0, 0.05};
  EXPECT_FALSE(ray_leaves_through_hole(t.R, t.r, o, down, 0));
  EXPECT_FALSE(ray_leaves_through_hole(t.R, t.r, o, level, 0));
  EXPECT_FALSE(ray_leaves_through_hole(t.R, t.r, o, across, 0));
  // Inside the tube, or on its outer half: not passed.
  const double in[3] = {0.8, 0, 0.1}, out[3] = {1.25 + 1e-3, 0, 0.1};
  EXPECT_FALSE(ray_leaves_through_hole(t.R, t.r, in, up, 0));
  EXPECT_FALSE(ray_leaves_through_hole(t.R, t.r, out, up, 0));
  // A spindle or horn torus fills its hole: never passed.
  EXPECT_FALSE(ray_leaves_through_hole(1, 1, o, up, 0));
  EXPECT_FALSE(ray_leaves_through_hole(1, 1.5, o, up, 0));
  EXPECT_FALSE(ray_leaves_through_hole(t.R, t.r, o, up, std::numeric_limits<double>::quiet_NaN()));
}

}  // namespace
}  // namespace toroid
