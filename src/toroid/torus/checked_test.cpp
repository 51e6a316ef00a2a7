// SPDX-License-Identifier: Apache-2.0
// The checked calls and the batch (checked.h): invalid inputs get their
// documented answers, valid ones exactly intersect_torus's, and every batch
// row is the single-ray call's answer, bit for bit.
#include "toroid/torus/checked.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Ray {
  double o[3], d[3];
};

// Rays of every kind the batch must pass through unchanged: random ones
// aimed at the torus (hits through the tube and the hole), random
// directions (mostly misses), rays tangent to the top and the outer
// equator, and invalid ones (NaN, infinite, zero direction).
std::vector<Ray> mixed_rays(double R, double r, int count) {
  std::mt19937_64 gen(12345);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray ray{};
    switch (i % 8) {
      case 0:
      case 1: {  // from far away towards a point inside the tube
        for (int k = 0; k < 3; ++k) ray.o[k] = 5 * (R + r) * u(gen);
        const double a = 4 * u(gen), rho = R + 0.9 * r * u(gen);
        ray.d[0] = rho * std::cos(a) - ray.o[0];
        ray.d[1] = rho * std::sin(a) - ray.o[1];
        ray.d[2] = 0.3 * r * u(gen) - ray.o[2];
        break;
      }
      case 2:  // random directions
        for (int k = 0; k < 3; ++k) ray.o[k] = 3 * (R + r) * u(gen), ray.d[k] = u(gen);
        break;
      case 3:  // tangent to the top circle z = r (a double root)
        ray = Ray{{-5 * R, R * u(gen), r}, {1, 0, 0}};
        break;
      case 4:  // tangent to the outer equator x = R + r
        ray = Ray{{R + r, -5 * R, 0}, {0, 1, 0}};
        break;
      case 5: {  // a NaN or infinite component, in the origin or the direction
        ray = Ray{{-5, 0.1, 0}, {1, 0, 0}};
        const double bad[] = {kNaN, kInf, -kInf};
        (i / 8 % 2 ? ray.o : ray.d)[i / 16 % 3] = bad[i / 48 % 3];
        break;
      }
      case 6:  // a zero direction (either sign of zero)
        ray = Ray{{u(gen), u(gen), u(gen)}, {0, i / 8 % 2 ? -0.0 : 0.0, 0}};
        break;
      default:  // through the hole along a diameter
        ray = Ray{{-5 * R, 0, 0.5 * r * u(gen)}, {1, 0, 0}};
        break;
    }
    rays.push_back(ray);
  }
  return rays;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(TorusChecked, InvalidRadiiGiveMinusOne) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double t[4], n[3];
  for (const double bad : {0.0, -0.0, -1.0, kNaN, kInf, -kInf}) {
    SCOPED_TRACE(bad);
    EXPECT_FALSE(torus_radii_valid(bad, 0.25));
    EXPECT_FALSE(torus_radii_valid(1, bad));
    EXPECT_EQ(intersect_torus_checked(bad, 0.25, o, d, t), -1);
    EXPECT_EQ(intersect_torus_checked(1, bad, o, d, t), -1);
    EXPECT_EQ(intersect_torus_nearest_checked(bad, 0.25, o, d, 0, kInf, t), -1);
    EXPECT_EQ(intersect_torus_nearest_checked(1, bad, o, d, 0, kInf, t), -1);
    torus_unit_normal(1, bad, o, n);
    EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
  }
  EXPECT_TRUE(torus_radii_valid(1e-300, 1e300));
}

TEST(TorusChecked, InvalidRaysHaveNoRoots) {
  const double good_o[3] = {-5, 0, 0}, good_d[3] = {1, 0, 0};
  for (int k = 0; k < 3; ++k)
    for (const double bad : {kNaN, kInf, -kInf}) {
      double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0}, t[4] = {7, 7, 7, 7};
      o[k] = bad;
      EXPECT_EQ(intersect_torus_checked(1, 0.25, o, good_d, t), 0);
      EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, good_d, -kInf, kInf, t), 0);
      d[k] = bad;
      EXPECT_EQ(intersect_torus_checked(1, 0.25, good_o, d, t), 0);
      EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, good_o, d, -kInf, kInf, t), 0);
      EXPECT_EQ(t[0], 7);  // untouched
    }
  const double zero[3] = {0, -0.0, 0};
  double t[4];
  EXPECT_EQ(intersect_torus_checked(1, 0.25, good_o, zero, t), 0);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, good_o, zero, -kInf, kInf, t), 0);
}

TEST(TorusChecked, NearestWithNaNBoundsFindsNothing) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double t = 7;
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, kNaN, kInf, &t), 0);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, 0, kNaN, &t), 0);
  EXPECT_EQ(t, 7);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, 4, kInf, &t), 1);
  EXPECT_EQ(t, 4.25);
  EXPECT_EQ(intersect_torus_nearest_checked(1, 0.25, o, d, 6.25, kInf, &t), 0);
}

TEST(TorusChecked, UnitNormalIsTheNormalScaled) {
  const double p[3] = {1.25, 0, 0};
  double n[3];
  torus_unit_normal(1, 0.25, p, n);
  EXPECT_EQ(n[0], 1);
  EXPECT_EQ(n[1], 0);
  EXPECT_EQ(n[2], 0);
  // Where n / |n| neither overflows nor underflows, the same bits.
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < 1000; ++i) {
    const double q[3] = {2 * u(gen), 2 * u(gen), u(gen)};
    double m[3], plain[3];
    torus_normal(1, 0.4, q, m);
    const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (int k = 0; k < 3; ++k) plain[k] = m[k] / len;
    torus_unit_normal(1, 0.4, q, n);
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_bits(n[k], plain[k])) << i << " " << k;
  }
  // Far from unit scale the plain formula overflows or underflows; this
  // one still gives unit length.
  for (const double s : {1e-200, 1e200}) {
    const double q[3] = {s * 1.5, s * 0.5, s * 0.25};
    torus_unit_normal(s, s * 0.75, q, n);
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-15) << s;
  }
  // The centre circle has no normal; nor has a non-finite point.
  const double centre[3] = {1, 0, 0}, far[3] = {kInf, 0, 0};
  torus_unit_normal(1, 0.25, centre, n);
  EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
  torus_unit_normal(1, 0.25, far, n);
  EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
}

// Every row of the batch is intersect_torus_checked's answer for its ray, bit
// for bit, and the unused slots are NaN.
void expect_batch_matches_single(double R, double r, bool exact_tangents) {
  const std::vector<Ray> rays = mixed_rays(R, r, 4000);
  const std::size_t n = rays.size();
  std::vector<double> origins(3 * n), directions(3 * n), roots(4 * n, 7.0);
  std::vector<int> counts(n, 7);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) origins[3 * i + k] = rays[i].o[k], directions[3 * i + k] = rays[i].d[k];
  const int total = intersect_torus_batch(R, r, n, origins.data(), directions.data(), counts.data(), roots.data());
  int expected_total = 0, hits = 0, tangents = 0, invalid = 0;
  for (std::size_t i = 0; i < n; ++i) {
    double t[4];
    const int c = intersect_torus_checked(R, r, rays[i].o, rays[i].d, t);
    ASSERT_EQ(counts[i], c) << i;
    if (torus_ray_valid(rays[i].o, rays[i].d)) {
      double raw[4];
      ASSERT_EQ(intersect_torus(R, r, rays[i].o, rays[i].d, raw), c) << i;
    } else {
      ASSERT_EQ(c, 0) << i;
      ++invalid;
    }
    for (int k = 0; k < c; ++k) ASSERT_TRUE(same_bits(roots[4 * i + k], t[k])) << i << " " << k;
    for (int k = c; k < 4; ++k) ASSERT_TRUE(std::isnan(roots[4 * i + k])) << i << " " << k;
    expected_total += c;
    hits += c > 0;
    tangents += c >= 2 && t[0] == t[1];
  }
  EXPECT_EQ(total, expected_total);
  // The mix has all kinds in it.
  EXPECT_GT(hits, static_cast<int>(n) / 4);
  EXPECT_GT(static_cast<int>(n) - hits - invalid, static_cast<int>(n) / 10);
  if (exact_tangents) {
    EXPECT_GT(tangents, 0);
  }
  EXPECT_GT(invalid, static_cast<int>(n) / 5);
}

// The tangent rays of the mix touch exactly (a double root) where R + r and
// r are exact in binary: not for the thin torus.
TEST(TorusBatch, EveryRowIsTheSingleRayCallRingTorus) { expect_batch_matches_single(1, 0.25, true); }
TEST(TorusBatch, EveryRowIsTheSingleRayCallSpindleTorus) { expect_batch_matches_single(1, 1.5, true); }
TEST(TorusBatch, EveryRowIsTheSingleRayCallThinTorus) { expect_batch_matches_single(1e4, 1e-2, false); }

TEST(TorusBatch, InvalidRadiiSetEveryCountMinusOneAndEveryRootNaN) {
  const double o[6] = {-5, 0, 0, -5, 0.1, 0}, d[6] = {1, 0, 0, 1, 0, 0};
  for (const double bad : {0.0, -1.0, kNaN, kInf}) {
    int counts[2] = {7, 7};
    double roots[8] = {7, 7, 7, 7, 7, 7, 7, 7};
    EXPECT_EQ(intersect_torus_batch(bad, 0.25, 2, o, d, counts, roots), -1);
    EXPECT_EQ(counts[0], -1);
    EXPECT_EQ(counts[1], -1);
    for (const double t : roots) EXPECT_TRUE(std::isnan(t));
  }
}

TEST(TorusBatch, KnownRowsAndNaNPadding) {
  const double o[9] = {-5, 0, 0, 1.25, -5, 0, -5, 5, 0}, d[9] = {1, 0, 0, 0, 1, 0, 1, 0, 0};
  int counts[3];
  double roots[12];
  EXPECT_EQ(intersect_torus_batch(1, 0.25, 3, o, d, counts, roots), 6);
  EXPECT_EQ(counts[0], 4);
  EXPECT_EQ(roots[0], 3.75);
  EXPECT_EQ(roots[1], 4.25);
  EXPECT_EQ(roots[2], 5.75);
  EXPECT_EQ(roots[3], 6.25);
  EXPECT_EQ(counts[1],
            2);  // tangent to the outer equator at (1.25, 0, 0): a double root
  EXPECT_EQ(roots[4], 5);
  EXPECT_EQ(roots[5], 5);
  EXPECT_TRUE(std::isnan(roots[6]) && std::isnan(roots[7]));
  EXPECT_EQ(counts[2], 0);
  for (int k = 8; k < 12; ++k) EXPECT_TRUE(std::isnan(roots[k]));
}

TEST(TorusBatch, EmptyBatchTouchesNothing) {
  EXPECT_EQ(intersect_torus_batch(1, 0.25, 0, nullptr, nullptr, nullptr, nullptr), 0);
  EXPECT_EQ(intersect_torus_batch(-1, 0.25, 0, nullptr, nullptr, nullptr, nullptr), -1);
}

}  // namespace
}  // namespace toroid
