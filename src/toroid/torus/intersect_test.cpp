// SPDX-License-Identifier: Apache-2.0
// intersect_torus at known roots, including the seed's special geometries.
#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace toroid {
namespace {

struct Roots {
  int n;
  double t[4];
};

Roots roots(double R, double r, std::array<double, 3> o, std::array<double, 3> d,
            TorusSolver s = TorusSolver::Default) {
  Roots out{};
  out.n = intersect_torus(R, r, o.data(), d.data(), out.t, s);
  return out;
}

TEST(TorusIntersect, RayThroughTheHoleHasFourRoots) {
  const Roots x = roots(1, 0.25, {-5, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_DOUBLE_EQ(x.t[0], 3.75);
  EXPECT_DOUBLE_EQ(x.t[1], 4.25);
  EXPECT_DOUBLE_EQ(x.t[2], 5.75);
  EXPECT_DOUBLE_EQ(x.t[3], 6.25);
}

TEST(TorusIntersect, DirectionNeedNotBeUnit) {
  const Roots x = roots(1, 0.25, {-5, 0, 0}, {2, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_DOUBLE_EQ(x.t[0], 1.875);
  EXPECT_DOUBLE_EQ(x.t[3], 3.125);
}

TEST(TorusIntersect, DirectionsOfAnyScaleGiveTheSameRootsScaled) {
  // |d|^2 of 1e300 or 1e-300 overflows or underflows a double; the roots
  // are still those of the unit direction, divided by the length.
  const Roots unit = roots(1, 0.25, {-5, 0.1, 0.05}, {1, 0, 0});
  ASSERT_EQ(unit.n, 4);
  for (const double length : {0x1p-1000, 0x1p-300, 1.2e151, 0x1p300, 0x1p1000}) {
    SCOPED_TRACE(length);
    const Roots x = roots(1, 0.25, {-5, 0.1, 0.05}, {length, 0, 0});
    ASSERT_EQ(x.n, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i] * length, unit.t[i], 4e-16 * unit.t[i]) << i;
  }
  // The fuzzer's case: a direction of 1.2e151 along a diameter, ±0.75 / |d|.
  const Roots far = roots(1, 0.25, {0, 0, 0}, {12e150, 0, 0});
  ASSERT_EQ(far.n, 4);
  EXPECT_DOUBLE_EQ(far.t[1], -0.75 / 12e150);
  EXPECT_DOUBLE_EQ(far.t[2], 0.75 / 12e150);
}

TEST(TorusIntersect, RootsBeyondTheLargestDoubleAreLeftOut) {
  // A denormal direction puts the torus at t ~ 1e325: no double holds that.
  const Roots x = roots(1e4, 1, {0, 0, 0}, {3.16e-322, 1.58e-322, 0});
  for (int i = 0; i < x.n; ++i) EXPECT_TRUE(std::isfinite(x.t[i])) << i << ": " << x.t[i];
  // Just inside the range the roots are there, finite.
  const Roots y = roots(1e4, 1, {0, 0, 0}, {0x1p-1000, 0, 0});
  ASSERT_EQ(y.n, 4);
  EXPECT_DOUBLE_EQ(y.t[3], 10001 * 0x1p1000);
}

TEST(TorusIntersect, ToriOfAnySizeGiveTheSameRootsScaled) {
  // R^2 of a 1e-185 torus underflows a double, of a 1e185 one overflows.
  const Roots unit = roots(1, 0.25, {-5, 0.1, 0.05}, {1, 0, 0});
  ASSERT_EQ(unit.n, 4);
  for (const double size : {0x1p-700, 2.35e-185, 0x1p-120, 0x1p120, 2.35e185, 0x1p700}) {
    SCOPED_TRACE(size);
    const Roots x = roots(size, 0.25 * size, {-5 * size, 0.1 * size, 0.05 * size}, {1, 0, 0});
    ASSERT_EQ(x.n, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i] / size, unit.t[i], 4e-16 * unit.t[i]) << i;
  }
  // The fuzzer's case: a nearly horn torus of 2.35e-185 seen from its
  // centre, which is not on it (R - r = 7e-192).
  const double R = 2.3534389759566928e-185, r = 2.3534382785503553e-185;
  const Roots x = roots(R, r, {0, 0, 0}, {4.7068772545070478e-185, 0, 0});
  ASSERT_EQ(x.n, 4);
  for (int i = 0; i < 4; ++i) EXPECT_NE(x.t[i], 0.0) << i;
  EXPECT_NEAR(x.t[3], (R + r) / 4.7068772545070478e-185, 1e-15);
}

TEST(TorusIntersect, ARayGrazingTheAxisHasNoRootAtTheCentre) {
  // 1e-90 from the axis: the test for h_out's concave part near the axis
  // squares and cubes numbers that underflow.
  for (const double offset : {1e-90, 1e-150, 1e-200}) {
    SCOPED_TRACE(offset);
    const Roots x = roots(1, 0.25, {offset, 0, 0}, {1, 1, 0});
    ASSERT_EQ(x.n, 4);
    const double want[4] = {-1.25 / M_SQRT2, -0.75 / M_SQRT2, 0.75 / M_SQRT2, 1.25 / M_SQRT2};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i], want[i], 1e-15) << i;
  }
}

// A ray along x through the tube, 1e-162 from the axis, with |d| = 1000:
// K / c and R K / |d|^2 (rho_min^2 and rho_i^3) both underflow to 0 while K
// does not. The passage is a kink of rho, as for K = 0; the list dropped the
// two roots beyond the axis (an input of fuzz/corpus/intersect, R ~ 1e21,
// showed it once the nearest-root query from inside the tube found them).
TEST(TorusIntersect, ARayWhoseConcaveTestUnderflowsKeepsItsRoots) {
  for (const double offset : {1e-162, 3e-162, 1e-170}) {
    SCOPED_TRACE(offset);
    const Roots x = roots(1, 0.25, {1, offset, 0}, {1000, 0, 0});
    ASSERT_EQ(x.n, 4);
    const double want[4] = {-2.25e-3, -1.75e-3, -0.25e-3, 0.25e-3};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i], want[i], 1e-18) << i;
  }
}

// The fuzzer's ray (an input of fuzz/corpus/intersect): along y, |d| ~ 1e57,
// through a nearly horn torus of size 3e-40 within 7e-198 of its axis.
// Rescaled, rho_i is far above rho_min but the concave stretch's half-width
// underflows to 0: the passage is cut as a kink; the list dropped the two
// roots beyond the axis.
TEST(TorusIntersect, ARayWhoseConcaveStretchUnderflowsKeepsItsRoots) {
  const double R = 2.7227121453917246e-40, r = 2.7226278339608488e-40;
  const Roots x = roots(R, r, {-6.6888822612257112e-198, 8.275809495493886e-313, 8.7623505883960522e-313},
                        {2.7825777173779005e-320, -1.35914919392845e+57, -0.0});
  ASSERT_EQ(x.n, 4);
  const double speed = 1.35914919392845e+57;
  const double want[4] = {-(R + r) / speed, -(R - r) / speed, (R - r) / speed, (R + r) / speed};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i], want[i], 1e-9 * std::abs(want[i])) << i;
}

// The fuzzer's rays through the centre of tiny, nearly horn tori: R K / |d|^2
// (rho_i^3) underflows to 0 while K / c (rho_min^2) does not, so the roots
// cannot be compared; the test is made in exponents (R^2 c^3 > K |d|^4), and
// rho_i = 0 is a kink. The list dropped the two roots beyond the axis.
// Size 1e-153, 1e-162 of it off the axis once rescaled (K subnormal):
TEST(TorusIntersect, ARayWithASubnormalKKeepsItsRoots) {
  const Roots x = roots(6.0134742846961391e-154, 6.0134700169990685e-154, {4.9928551262996198e-315, 0, 0},
                        {-6.8356728929826799e-154, 4.8348331849788138e-154, -5.5313556424034503e-154});
  ASSERT_EQ(x.n, 4);
  EXPECT_NEAR(x.t[0], -1, 1e-12);
  EXPECT_NEAR(x.t[3], 1, 1e-12);
  EXPECT_NEAR(x.t[1], -x.t[2], 1e-18);
  EXPECT_GT(x.t[2], 0);
}

// Size 2e-25 along |d| ~ 1e21, 6e-154 off the axis (K normal):
TEST(TorusIntersect, ARayWhoseRhoICubedUnderflowsKeepsItsRoots) {
  const double R = 8.6367387487154352e-26, r = 8.6358191609518039e-26, speed = 7.4770820838688988e+20;
  const Roots x = roots(R, r, {6.2386826586862896e-154, 6.0134700224691388e-154, 6.0134700169990685e-154},
                        {speed, 9.7330932230725569e-322, 3.7516131147708069e-307});
  ASSERT_EQ(x.n, 4);
  const double want[4] = {-(R + r) / speed, -(R - r) / speed, (R - r) / speed, (R + r) / speed};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i], want[i], 1e-9 * std::abs(want[i])) << i;
}

// A ray that passes the axis far from its point nearest the centre: there
// rho is as small as its rounding, and h_out's concave stretch beside the
// axis is narrower than the samples resolve. Its roots are those of the ray
// through the axis (K = 0, a kink of rho).
TEST(TorusIntersect, ARayPassingTheAxisAwayFromTheCentreKeepsItsRoots) {
  for (const double z : {0.2, -0.1}) {
    const Roots exact = roots(1, 0.25, {-2, 0, z + 0.6}, {1, 0, -0.3});
    ASSERT_EQ(exact.n, 2);
    for (const double offset : {1e-10, 1e-20, 1e-26, 1e-30, 1e-40, 1e-60, 1e-100, 1e-200, 1e-300}) {
      SCOPED_TRACE(std::to_string(z) + " " + std::to_string(std::log10(offset)));
      const Roots x = roots(1, 0.25, {-2, offset, z + 0.6}, {1, 0, -0.3});
      ASSERT_EQ(x.n, 2);
      for (int i = 0; i < 2; ++i) EXPECT_NEAR(x.t[i], exact.t[i], 1e-15) << i;
    }
  }
}

// The fuzzer's spindle (fuzz/corpus/intersect/spindle-near-axis-origin-
// beyond-pole): minor / major = 1.19, a ray that crosses within 1e-54 sizes
// of the axis at its origin, beyond the lemon's pole, and climbs at a slope
// of 4e-19. It meets each pole twice (the outer sheet and the lemon).
TEST(TorusIntersect, ASpindleRayBesideTheAxisMeetsEachPoleTwice) {
  const double R = 6.8355779448292253e+124, r = 8.1576898862883575e+124;
  const double o[3] = {-4.2525584673585782e+71, -4.2525583765009148e+71, -6.8351024672236235e+124};
  const double d[3] = {3.1424635695958265e-310, -6.8346989773204297e+124, o[0] * o[1]};
  double t[4];
  ASSERT_EQ(intersect_torus(R, r, o, d, t), 4);
  const double pole = std::sqrt((r - R) * (r + R));
  const double want[4] = {-pole, -pole, pole, pole};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR((o[2] + t[i] * d[2]) / pole, want[i] / pole, 1e-15) << i;
}

// A nearly horn spindle (minor - major = 2^-40): a ray along a diameter, 1e-30
// from the axis, crosses the outer sheet twice and the lemon, 2^-40 across,
// twice. Its point nearest the centre carries the rounding of the shift,
// 1e-16, so the axis passage is blurred.
TEST(TorusIntersect, ANearlyHornLemonIsFoundBesideTheAxis) {
  const double R = 1, r = 1 + 0x1p-40;
  const Roots x = roots(R, r, {-1, 1e-30, 0}, {3, 0, 0});
  ASSERT_EQ(x.n, 4);
  const double want[4] = {(1 - (R + r)) / 3, (1 - (r - R)) / 3, (1 + (r - R)) / 3, (1 + R + r) / 3};
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(x.t[i], want[i], 1e-15) << i;
  EXPECT_LT(x.t[1], x.t[2]);
}

TEST(TorusIntersect, ClosedFormsReportNoNonFiniteRoots) {
  // Coefficients overflow here (R = 1e4, |o| ~ 1e113): the closed forms
  // may find nothing, but never a NaN.
  const std::array<double, 3> o{-4.425e113, 2.0000000000074567, 1.78e-307}, d{-1.0546875, 0, -8.85e113};
  for (const TorusSolver s : {TorusSolver::Ferrari, TorusSolver::Tianheng, TorusSolver::Default}) {
    SCOPED_TRACE(solver_name(s));
    const Roots x = roots(1e4, 5.78e-275, o, d, s);
    for (int i = 0; i < x.n; ++i) EXPECT_TRUE(std::isfinite(x.t[i])) << i;
  }
}

TEST(TorusIntersect, NegativeRootsAreReported) {
  const Roots x = roots(1, 0.25, {5, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_DOUBLE_EQ(x.t[0], -6.25);
  EXPECT_DOUBLE_EQ(x.t[3], -3.75);
}

TEST(TorusIntersect, RayTangentToTheTopGivesTwoDoubleRoots) {
  const Roots x = roots(1, 0.25, {-5, 0, 0.25}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_DOUBLE_EQ(x.t[0], 4);
  EXPECT_DOUBLE_EQ(x.t[1], 4);
  EXPECT_DOUBLE_EQ(x.t[2], 6);
  EXPECT_DOUBLE_EQ(x.t[3], 6);
}

TEST(TorusIntersect, RayAboveTheTorusMisses) { EXPECT_EQ(roots(1, 0.25, {-5, 0, 0.2500001}, {1, 0, 0}).n, 0); }

TEST(TorusIntersect, RayAlongTheAxisMissesARingTorus) { EXPECT_EQ(roots(1, 0.25, {0, 0, -5}, {0, 0, 1}).n, 0); }

// The hole test (hole.h) rejects a chord only when both its ends lie inside
// the cylinder rho < R - r, less its margin: these rays keep their roots.
TEST(TorusIntersect, RaysJustOutsideTheHoleKeepTheirRoots) {
  // Parallel to the axis, about 1e-12 outside the inner equator: two roots
  // close to z = 0, z^2 = r^2 - (r - gap)^2 (the gap is exact: Sterbenz).
  const double x = 0.75 + 1e-12, gap = x - 0.75, z = std::sqrt(0.5 * gap - gap * gap);
  const Roots grazing = roots(1, 0.25, {x, 0, -5}, {0, 0, 1});
  ASSERT_EQ(grazing.n, 2);
  EXPECT_NEAR(grazing.t[0], 5 - z, 1e-12);
  EXPECT_NEAR(grazing.t[1], 5 + z, 1e-12);
  // Into the hole through the top face and out through the inner wall:
  // one end of the chord is in the hole, the other in the tube.
  const Roots wall = roots(1, 0.25, {0, 0, 1}, {0.75, 0, -1});
  ASSERT_EQ(wall.n, 2);
  EXPECT_NEAR(wall.t[0], 1, 1e-12);  // (0.75, 0, 0), the inner equator, is on the surface
}

TEST(TorusIntersect, AWindowInsideTheHoleHoldsNoRoot) {
  const double o[3] = {0, 0, 0}, d[3] = {1, 0, 0};  // roots at -1.25, -0.75, 0.75, 1.25
  double t = 0;
  EXPECT_FALSE(intersect_torus_nearest(1, 0.25, o, d, 0, 0.5, &t));
  EXPECT_FALSE(torus_blocks(1, 0.25, o, d, -0.5, 0.5));
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, 0.5, 1, &t));
  EXPECT_DOUBLE_EQ(t, 0.75);
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, -1, -0.5, &t));
  EXPECT_DOUBLE_EQ(t, -0.75);
  EXPECT_TRUE(torus_blocks(1, 0.25, o, d, 0, 0.76));
}

// A ray with a subnormal direction meets the torus at t beyond the largest
// double: those roots are left out, and the nearest-root query finds the
// first root it can return, not none.
TEST(TorusIntersect, TheNearestRootIsTheFirstRepresentableOne) {
  const double o[3] = {0, 0, 0}, d[3] = {0x1p-1024, 0, 0};  // roots at -+0.75 and -+1.25 times 2^1024
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double all[4];
  ASSERT_EQ(intersect_torus(1, 0.25, o, d, all), 2);
  EXPECT_DOUBLE_EQ(all[0], -0x1.8p1023);
  double t = 0;
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, -kInf, 0, &t));
  EXPECT_DOUBLE_EQ(t, -0x1.8p1023);
  EXPECT_TRUE(torus_blocks(1, 0.25, o, d, -kInf, 0));
}

// From exactly a root, the nearest root is the next one: the search decides
// whether a root lies in the window on the t value the caller gets. On a
// torus rescaled into the solver's range (here about 1e-307 across) with
// roots at subnormal t, scaling t back rounds it: the root found just
// inside the scaled window is t_min itself once scaled back.
TEST(TorusIntersect, FromARootOfARescaledTorusTheNearestRootIsTheNext) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const double R = 6.9803000881154317e-307, r = 1.2547219690010596e-314;
  const double o[3] = {6.9803002135876285e-307, 0, 0}, d[3] = {-0.0, 1, 0};
  double all[4];
  ASSERT_EQ(intersect_torus(R, r, o, d, all), 2);
  ASSERT_LT(all[0], all[1]);
  double t = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, r, o, d, all[0], kInf, &t));
  EXPECT_EQ(t, all[1]);
  EXPECT_TRUE(torus_blocks(R, r, o, d, all[0], kInf));
  EXPECT_FALSE(intersect_torus_nearest(R, r, o, d, all[1], kInf, &t));
}

// Shadow rays leave a surface: from 1e-5 above random points of the torus,
// in random directions away from it, towards a light at infinity, beyond
// the torus or between its roots. torus_blocks skips a piece that straddles
// the window's start (it holds the surface just left) when a sample at the
// start shows that no root of it lies in the window; its answer must stay
// the nearest-root query's.
bool blocks_agrees_with_nearest(double minor, const double o[3], const double d[3], int* blocked) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double all[4];
  const int n = intersect_torus(1, minor, o, d, all);
  std::vector<double> ends = {kInf};
  for (int i = 0; i < n; ++i) {
    ends.push_back(all[i] * (1 + 1e-6));
    if (i + 1 < n) ends.push_back(0.5 * (all[i] + all[i + 1]));
  }
  for (const double t_max : ends) {
    if (!(t_max > 0)) continue;
    double t = 0;
    const bool nearest = intersect_torus_nearest(1, minor, o, d, 0, t_max, &t);
    if (torus_blocks(1, minor, o, d, 0, t_max) != nearest || torus_blocks(1, minor, o, d, -1e-300, t_max) != nearest)
      return false;
    *blocked += nearest;
  }
  return true;
}

TEST(TorusIntersect, ShadowRaysLeavingTheSurfaceAgreeWithTheNearestRoot) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> angle(0, 2 * M_PI), u(-1, 1);
  for (const double minor : {0.25, 0.01, 1.5}) {
    int blocked = 0;
    for (int i = 0; i < 2000; ++i) {
      const double theta = angle(rng), phi = angle(rng);
      const double n[3] = {std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), std::sin(phi)};
      double d[3];
      do {
        for (double& c : d) c = u(rng);
      } while (d[0] * n[0] + d[1] * n[1] + d[2] * n[2] <= 0);
      const double o[3] = {std::cos(theta) + (minor + 1e-5) * n[0], std::sin(theta) + (minor + 1e-5) * n[1],
                           (minor + 1e-5) * n[2]};
      ASSERT_TRUE(blocks_agrees_with_nearest(minor, o, d, &blocked)) << "minor " << minor << " ray " << i;
    }
    EXPECT_GT(blocked, 20) << "minor " << minor;
  }
  // Chords across the hole, from the inner equator to the far side of the
  // inner wall, close to the tangent: the factor is concave along them, and
  // the piece that holds the surface just left holds the far wall too.
  int blocked = 0;
  for (int i = 0; i < 500; ++i) {
    const double theta = angle(rng), alpha = 0.02 + 0.15 * (u(rng) + 1);
    const double c = std::cos(theta), sn = std::sin(theta), z = 0.01 * u(rng);
    const double rho = 1 - std::sqrt(0.0625 - z * z) - 1e-5;  // 1e-5 inside the inner wall's circle at height z
    const double o[3] = {rho * c, rho * sn, z};
    // The tangent (-sin, cos) turned by alpha towards the axis.
    const double d[3] = {-sn * std::cos(alpha) - c * std::sin(alpha), c * std::cos(alpha) - sn * std::sin(alpha),
                         0.01 * u(rng)};
    ASSERT_TRUE(blocks_agrees_with_nearest(0.25, o, d, &blocked)) << "chord " << i;
  }
  EXPECT_GT(blocked, 500);
}

// The window's end at the ray's passage through the axis, where the factor
// has a kink: the piece that ends there is searched whole (the root at -1
// is in the window).
TEST(TorusIntersect, AWindowEndingWhereTheRayCrossesTheAxis) {
  const double o[3] = {-2.3536708310291543e-185, -2.3536704014345216e-185, -2.353438279372284e-185};
  const double d[3] = {1.25, -5.8841632910920823e-186, -1.7654831433889378e-185};
  double t = 0;
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, -1.0002, 0, &t));
  EXPECT_DOUBLE_EQ(t, -1);
  EXPECT_TRUE(torus_blocks(1, 0.25, o, d, -1.0002, 0));
}

// A ray tangent to a nearly horn torus (found by the fuzzer): a double root
// beside the window's end. Whether the minimum there touches zero is decided
// in double-double at a point that depends on the piece's ends, so the
// shadow query searches the piece whole, as the nearest-root query does,
// rather than cut at the window's end.
TEST(TorusIntersect, AWindowThatEndsBesideATangentPoint) {
  const double R = 2.7227121454184523e-40, r = 2.7226523566839745e-40;
  const double o[3] = {-2.7226523566839745e-40, -2.7226523566839745e-40, -2.7226523566839745e-40};
  const double d[3] = {-1.3631157197591269e+57, -6.8003216365905096e+124, 7.4128358553567995e-80};
  double t = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, r, o, d, -4.0262408887369592e-165, 0, &t));
  EXPECT_DOUBLE_EQ(t, -3.9771777021225501e-165);
  EXPECT_TRUE(torus_blocks(R, r, o, d, -4.0262408887369592e-165, 0));
}

// The shadow query stands a point of a piece in for a root it does not
// locate; the piece's start was that point, and here (found by the fuzzer:
// the window starts at the ray's point nearest the centre, a piece's start)
// it rounded onto the window's start and the root was lost.
TEST(TorusIntersect, TheShadowQuerysStandInForARootLiesInsideTheWindow) {
  const double R = 2.8177690084182086e-202, r = 2.8177690079429357e-202;
  const double o[3] = {2.8177690153393701e-202, 2.8177690084182086e-202, 2.9912079144730175e-315};
  const double d[3] = {1.3583063983708621e-312, 0, 0};
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double t = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, r, o, d, -2.0744723125201882e+110, kInf, &t));
  EXPECT_DOUBLE_EQ(t, 1.5186191224300973e+110);
  EXPECT_TRUE(torus_blocks(R, r, o, d, -2.0744723125201882e+110, kInf));
}

// A ray that passes the axis of a nearly horn torus within underflow (found
// by the fuzzer): its factor's piece is taken as convex, with the narrow
// spike at the axis unresolved. The shadow query does not cut such a piece
// where the part inside the window holds or nears the axis passage, and so
// answers as the nearest-root query does.
TEST(TorusIntersect, AWindowAroundTheAxisPassageOfANearlyHornTorus) {
  const double R = 7.4776450468439327e+20, r = 7.4770802645436046e+20;
  const double o[3] = {-1.3555436176162515e-196, -5.0497568334997517e-195, 2.0236928853657458e-320};
  const double d[3] = {-8.1758209510048516e+40, 4.39129864643598e+41, 5.1079633984577081e+40};
  double t = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, r, o, d, -1.5366581105185789e-24, 1.7895405523539905e-24, &t));
  EXPECT_TRUE(torus_blocks(R, r, o, d, -1.5366581105185789e-24, 1.7895405523539905e-24));
  // A window that ends within rounding of the passage, from an origin on the
  // axis of another nearly horn torus: the pair of roots behind it is found.
  const double R2 = 2.5674598155443507e+151, r2 = 2.5673651826636406e+151;
  const double o2[3] = {1.538078964275271e-18, 1.5306383611560062e-18, 2.5673651826616232e+151};
  const double d2[3] = {3.5681192349341961e+46, 0, 2.3542426652068283e-36};
  ASSERT_TRUE(intersect_torus_nearest(R2, r2, o2, d2, -7.2027592970698048e+104, 0, &t));
  EXPECT_TRUE(torus_blocks(R2, r2, o2, d2, -7.2027592970698048e+104, 0));
}

TEST(TorusIntersect, RaysThroughTheHoleMiss) {
  EXPECT_EQ(roots(1, 0.25, {0.75 - 1e-9, 0, -5}, {0, 0, 1}).n, 0);
  EXPECT_EQ(roots(1, 0.25, {0.3, -0.2, 3}, {-0.1, 0.05, -1}).n, 0);
  double t = 0;
  EXPECT_FALSE(intersect_torus_nearest(1, 0.25, std::array<double, 3>{0.5, 0, 2}.data(),
                                       std::array<double, 3>{0, 0.1, -1}.data(), 0, 1e9, &t));
}

TEST(TorusIntersect, RayParallelToTheAxisThroughTheTube) {
  const Roots x = roots(1, 0.25, {1, 0, -5}, {0, 0, 1});
  ASSERT_EQ(x.n, 2);
  EXPECT_DOUBLE_EQ(x.t[0], 4.75);
  EXPECT_DOUBLE_EQ(x.t[1], 5.25);
}

TEST(TorusIntersect, HornTorusCentreIsADoubleRoot) {
  const Roots x = roots(1, 1, {-5, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_DOUBLE_EQ(x.t[0], 3);
  EXPECT_DOUBLE_EQ(x.t[1], 5);
  EXPECT_DOUBLE_EQ(x.t[2], 5);
  EXPECT_DOUBLE_EQ(x.t[3], 7);
}

// The horn's centre is where both factors vanish; the lemon, a point, has no
// chord to search, so its root is the outer sheet's root at the centre.
// Along the axis the root is fourfold, listed twice (as a ring torus's top
// circle touched in its plane).
TEST(TorusIntersect, HornTorusCentreAlongTheAxisIsListedTwice) {
  const Roots x = roots(1, 1, {0, 0, -3}, {0, 0, 1});
  ASSERT_EQ(x.n, 2);
  EXPECT_EQ(x.t[0], 3);
  EXPECT_EQ(x.t[1], 3);
}

TEST(TorusIntersect, ARayMissingTheHornCentreMeetsTheOuterSheetOnly) {
  const Roots x = roots(1, 1, {-3, 1e-17, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 2);
  EXPECT_DOUBLE_EQ(x.t[0], 1);
  EXPECT_DOUBLE_EQ(x.t[1], 5);
}

// Found by the fuzzer: a horn torus of subnormal-scale size, a ray that
// passes its centre within underflow, and a tiny direction. The lemon's
// chord, a few roundings wide, once read h_in = 0 at every sample: the
// centre came out three times and the far root was dropped, so the
// nearest root after the centre was none.
TEST(TorusIntersect, ASubnormalHornTorusKeepsItsFarRoot) {
  const double R = 2.7226523566839745e-40;
  const double o[3] = {-2.7223672762590401e-40, 8.692515570224397e-311, 2.1564478451596123e-315};
  const double d[3] = {8.3385946601779345e-309, 0, -0.0};
  double t[4];
  ASSERT_EQ(intersect_torus(R, R, o, d, t), 4);
  EXPECT_LT(t[0], 0);
  EXPECT_GT(t[1], 0);
  EXPECT_EQ(t[1], t[2]);  // the centre, twice
  // (2R - o_x) / d_x, the far side of the outer sheet.
  EXPECT_NEAR(t[3], (2 * R - o[0]) / d[0], 1e-12 * t[3]);
  double next = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, R, o, d, t[1], std::numeric_limits<double>::infinity(), &next));
  EXPECT_EQ(next, t[3]);
  const Roots scaled = roots(1e-40, 1e-40, {-3e-40, 1e-300, 0}, {1e-300, 0, 0});
  ASSERT_EQ(scaled.n, 4);
  EXPECT_EQ(scaled.t[1], scaled.t[2]);
  EXPECT_NEAR(scaled.t[3], 5e260, 1e248);
}

// Found by the fuzzer: a ray that passes a subnormal-scale horn torus's axis
// 1e-129 of its size from the centre, where the outer sheet's concave
// stretch has both ends reading h = 0: the outer sheet lists the centre
// twice itself, and the lemon adds none.
TEST(TorusIntersect, AHornCentreTheOuterSheetListsTwiceIsNotListedAgain) {
  const double R = 2.7226523566839745e-40;
  const double o[3] = {6.6184012546675842e-103, -5.2997391148093205e-169, 6.5358285208114173e-307};
  const double d[3] = {2.1800754380841751e-106, 8.2889195776527596e-317, -3.5075800006864877e-271};
  double t[4];
  ASSERT_EQ(intersect_torus(R, R, o, d, t), 4);
  EXPECT_EQ(t[1], t[2]);
  EXPECT_DOUBLE_EQ(t[3], -t[0]);  // the outer sheet at -2R and +2R, the origin within 1e-63 R of the centre
  double next = 0;
  ASSERT_TRUE(intersect_torus_nearest(R, R, o, d, t[2], std::numeric_limits<double>::infinity(), &next));
  EXPECT_EQ(next, t[3]);
}

// Found by the fuzzer: a spindle torus of R = 3e-315, r = 3e151 (a sphere,
// to any double) touched at its top by a horizontal ray. Within the
// tangent's rounding the two factors find six roots between them, and the
// list keeps the first four; a query that searched only its window kept
// others. The queries read the list on spindle and horn tori: walking the
// roots one query at a time gives the list.
TEST(TorusIntersect, TheQueriesOnASpindleTorusGiveTheListsRoots) {
  const double R = 3.3985088839678189e-315, r = 2.5673651841076237e+151;
  const double o[3] = {5.9776128797411001e+141, 7.9054745135201817e-315, 2.5673651841076237e+151};
  const double d[3] = {1.6233963415903735e+154, 0, 4.7255866272483247e-173};
  double t[4];
  const int n = intersect_torus(R, r, o, d, t);
  ASSERT_GE(n, 1);
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double from = -kInf;
  for (int i = 0; i < n; ++i) {
    if (i > 0 && t[i] == t[i - 1]) continue;
    double next = 0;
    ASSERT_TRUE(intersect_torus_nearest(R, r, o, d, from, kInf, &next)) << i;
    EXPECT_EQ(next, t[i]) << i;
    EXPECT_TRUE(torus_blocks(R, r, o, d, from, kInf)) << i;
    from = t[i];
  }
  double next = 0;
  EXPECT_FALSE(intersect_torus_nearest(R, r, o, d, from, kInf, &next)) << next;
  EXPECT_FALSE(torus_blocks(R, r, o, d, from, kInf));
}

TEST(TorusIntersect, SpindleTorusInnerLemonIsIntersected) {
  // r = 1.5: outer surface at |x| = 2.5, lemon at |x| = 0.5.
  const Roots x = roots(1, 1.5, {-5, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_DOUBLE_EQ(x.t[0], 2.5);
  EXPECT_DOUBLE_EQ(x.t[1], 4.5);
  EXPECT_DOUBLE_EQ(x.t[2], 5.5);
  EXPECT_DOUBLE_EQ(x.t[3], 7.5);
}

TEST(TorusIntersect, SpindleAxisRayMeetsTheApexesTwice) {
  const Roots x = roots(1, 1.5, {0, 0, -5}, {0, 0, 1});
  ASSERT_EQ(x.n, 4);
  const double apex = std::sqrt(1.5 * 1.5 - 1);
  EXPECT_NEAR(x.t[0], 5 - apex, 1e-15);
  EXPECT_NEAR(x.t[1], 5 - apex, 1e-15);
  EXPECT_NEAR(x.t[2], 5 + apex, 1e-15);
  EXPECT_NEAR(x.t[3], 5 + apex, 1e-15);
}

TEST(TorusIntersect, FarOriginKeepsFullPrecision) {
  const Roots x = roots(1, 0.25, {-1e8, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_EQ(x.t[0], 1e8 - 1.25);
  EXPECT_EQ(x.t[1], 1e8 - 0.75);
  EXPECT_EQ(x.t[2], 1e8 + 0.75);
  EXPECT_EQ(x.t[3], 1e8 + 1.25);
}

TEST(TorusIntersect, ThinTubeIsFound) {
  const Roots x = roots(1, 1e-4, {-5, 0, 0}, {1, 0, 0});
  ASSERT_EQ(x.n, 4);
  EXPECT_NEAR(x.t[0], 3.9999, 1e-15);
  EXPECT_NEAR(x.t[1], 4.0001, 1e-15);
}

// A thin tube (r/R = 7e-9) entered just below its top, from 2 sizes away:
// the rounding of z along the ray (eps |z0|, 8e-9 r here) exceeded the slab's
// 1e-9 r margin, the chord started inside the tube, and the entry root was
// lost (a fuzz input: fuzz/corpus/intersect/thin-tube-top-entry).
TEST(TorusIntersect, ThinTubeEnteredAtItsTopKeepsBothRoots) {
  const double R = 0.0058671236038208008, r = 4.3655818380856221e-11;
  const std::array<double, 3> o{8.5762085909497909e-21, 0.0078125000053432814, 0.0058671242150012404};
  const std::array<double, 3> d{0.0058671236474766193, -0.0078125000053432814, -0.0058671242150012404};
  const Roots x = roots(R, r, o, d);
  ASSERT_EQ(x.n, 2);
  for (int i = 0; i < 2; ++i) {
    const double p[3] = {o[0] + x.t[i] * d[0], o[1] + x.t[i] * d[1], o[2] + x.t[i] * d[2]};
    EXPECT_LT(std::abs(std::hypot(std::hypot(p[0], p[1]) - R, p[2]) - r), 1e-3 * r) << "root " << x.t[i];
  }
  EXPECT_LT(x.t[0], x.t[1]);
}

TEST(TorusIntersect, NearestRootInAnInterval) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double t = -1;
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, 0, 100, &t));
  EXPECT_DOUBLE_EQ(t, 3.75);
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, 4, 100, &t));
  EXPECT_DOUBLE_EQ(t, 4.25);
  ASSERT_TRUE(intersect_torus_nearest(1, 0.25, o, d, 4.3, 100, &t));
  EXPECT_DOUBLE_EQ(t, 5.75);
  EXPECT_FALSE(intersect_torus_nearest(1, 0.25, o, d, 0, 3.7, &t));
  EXPECT_FALSE(intersect_torus_nearest(1, 0.25, o, d, 6.3, 100, &t));
}

TEST(TorusIntersect, NearestOnSpindleConsidersTheLemon) {
  const double o[3] = {0, 0, 0}, d[3] = {1, 0, 0};
  double t = -1;
  ASSERT_TRUE(intersect_torus_nearest(1, 1.5, o, d, 0, 100, &t));
  EXPECT_DOUBLE_EQ(t, 0.5);
}

TEST(TorusNormal, OuterEquatorPointsOutward) {
  const double p[3] = {1.25, 0, 0};
  double n[3];
  torus_normal(1, 0.25, p, n);
  EXPECT_GT(n[0], 0);
  EXPECT_DOUBLE_EQ(n[1], 0);
  EXPECT_DOUBLE_EQ(n[2], 0);
}

TEST(TorusNormal, InnerEquatorPointsToTheAxis) {
  const double p[3] = {0, 0.75, 0};
  double n[3];
  torus_normal(1, 0.25, p, n);
  EXPECT_LT(n[1], 0);
  EXPECT_DOUBLE_EQ(n[0], 0);
}

TEST(TorusNormal, TopPointsUp) {
  const double p[3] = {0, 1, 0.25};
  double n[3];
  torus_normal(1, 0.25, p, n);
  EXPECT_NEAR(n[1], 0, 1e-15);
  EXPECT_GT(n[2], 0);
}

TEST(TorusNormal, SpindleLemonPointsAwayFromTheCentre) {
  const double p[3] = {0.5, 0, 0};  // lemon of R = 1, r = 1.5
  double n[3];
  torus_normal(1, 1.5, p, n);
  EXPECT_GT(n[0], 0);
}

TEST(TorusNormal, AxisPointsAreFinite) {
  const double apex[3] = {0, 0, std::sqrt(1.25)};
  double n[3];
  torus_normal(1, 1.5, apex, n);
  for (double c : n) EXPECT_TRUE(std::isfinite(c));
  EXPECT_GT(n[2], 0);
  const double centre[3] = {0, 0, 0};
  torus_normal(1, 1, centre, n);
  for (double c : n) EXPECT_TRUE(std::isfinite(c));
}

TEST(TorusQuartic, CoefficientsMatchTheDerivation) {
  // o = (-5,0,0), d = (1,0,0), R = 1, r = 0.25: (t-3.75)(t-4.25)(t-5.75)(t-6.25).
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double k[5];
  torus_quartic_coefficients(1, 0.25, o, d, k);
  EXPECT_DOUBLE_EQ(k[0], 1);
  EXPECT_DOUBLE_EQ(k[1], -20);  // -(sum of roots)
  EXPECT_DOUBLE_EQ(k[4], 3.75 * 4.25 * 5.75 * 6.25);
}

}  // namespace
}  // namespace toroid
