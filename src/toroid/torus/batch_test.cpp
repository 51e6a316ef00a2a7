// SPDX-License-Identifier: Apache-2.0
// The batch (checked.h, batch.h) on every path this CPU can run: every row
// is the single-ray call's answer, bit for bit, and the unused slots are NaN.
#include "toroid/torus/batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "toroid/math/cube_root.h"
#include "toroid/torus/checked.h"
#include "toroid/torus/intersect.h"

namespace toroid {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Ray {
  double o[3], d[3];
};

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

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

// Rays as renderers cast them, where the SIMD paths do their own work:
// pinhole cameras near and far (up to 1e6 torus sizes), rays that graze the
// tube (near-tangent pairs, which go to the scalar code), rays from inside
// the tube, vertical rays, rays in a plane through the axis, and shadow-like
// rays from points on the surface.
std::vector<Ray> renderer_rays(double R, double r, int count) {
  std::mt19937_64 gen(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Ray> rays;
  const double size = R + r;
  for (int i = 0; i < count; ++i) {
    Ray ray{};
    switch (i % 7) {
      case 0:
      case 1: {  // a camera 2 to 1e6 sizes away, aimed into the bounding box
        const double dist = size * std::pow(10.0, 0.3 + 5.7 * (0.5 + 0.5 * u(gen)));
        double dir[3] = {u(gen), u(gen), u(gen)};
        const double n = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        for (int k = 0; k < 3; ++k) ray.o[k] = dir[k] / n * dist;
        const double target[3] = {size * u(gen), size * u(gen), r * u(gen)};
        for (int k = 0; k < 3; ++k) ray.d[k] = target[k] - ray.o[k];
        break;
      }
      case 2: {  // grazing the tube's top from the side: h's minimum near 0
        const double a = 3.14159 * u(gen), rho = R + 0.5 * r * u(gen);
        const double z = r * (1 + 1e-7 * u(gen));
        ray = Ray{{rho * std::cos(a) - 4 * size * std::sin(a), rho * std::sin(a) + 4 * size * std::cos(a), z},
                  {std::sin(a), -std::cos(a), 1e-9 * u(gen)}};
        break;
      }
      case 3: {  // from inside the tube, any direction
        const double a = 3.14159 * u(gen), rho = R + 0.5 * r * u(gen);
        ray = Ray{{rho * std::cos(a), rho * std::sin(a), 0.5 * r * u(gen)}, {u(gen), u(gen), u(gen)}};
        break;
      }
      case 4:  // vertical (no horizontal component: no convexity cut)
        ray = Ray{{(R + r * u(gen)) * u(gen), (R + r * u(gen)) * u(gen), 3 * size * u(gen)}, {0, 0, u(gen)}};
        break;
      case 5: {  // in a plane through the axis (K = 0: the scalar code's)
        const double a = 3.14159 * u(gen), q = 3 * size * u(gen);
        ray = Ray{{q * std::cos(a), q * std::sin(a), r * u(gen)}, {std::cos(a), std::sin(a), 0.2 * u(gen)}};
        break;
      }
      default: {  // from a point on the surface towards a random light
        const double a = 3.14159 * u(gen), b = 3.14159 * u(gen);
        ray = Ray{{(R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a), r * std::sin(b)},
                  {5 * u(gen), 5 * u(gen), 5 * u(gen)}};
        break;
      }
    }
    rays.push_back(ray);
  }
  return rays;
}

class TorusBatch : public testing::TestWithParam<BatchPath> {
 protected:
  void SetUp() override {
    if (!batch_path_available(GetParam()))
      GTEST_SKIP() << "this CPU or build has no " << batch_path_name(GetParam()) << " path";
  }

  // Every row of the batch on this path is intersect_torus_checked's answer
  // for its ray, bit for bit, and the unused slots are NaN. Returns the
  // number of rays with roots.
  int expect_rows_match(double R, double r, const std::vector<Ray>& rays) {
    const std::size_t n = rays.size();
    std::vector<double> origins(3 * n), directions(3 * n), roots(4 * n, 7.0);
    std::vector<int> counts(n, 7);
    for (std::size_t i = 0; i < n; ++i)
      for (int k = 0; k < 3; ++k) origins[3 * i + k] = rays[i].o[k], directions[3 * i + k] = rays[i].d[k];
    const long long total =
        intersect_torus_batch_on(GetParam(), R, r, n, origins.data(), directions.data(), counts.data(), roots.data());
    long long expected_total = 0;
    int hits = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double t[4];
      const int c = intersect_torus_checked(R, r, rays[i].o, rays[i].d, t);
      EXPECT_EQ(counts[i], c) << "ray " << i;
      if (counts[i] != c) continue;
      for (int k = 0; k < c; ++k)
        EXPECT_TRUE(same_bits(roots[4 * i + k], t[k]))
            << "ray " << i << " root " << k << ": " << roots[4 * i + k] << " != " << t[k];
      for (int k = std::max(c, 0); k < 4; ++k) EXPECT_TRUE(std::isnan(roots[4 * i + k])) << i << " " << k;
      expected_total += std::max(c, 0);
      hits += c > 0;
    }
    EXPECT_EQ(total, torus_radii_valid(R, r) ? expected_total : -1);
    return hits;
  }
};

// The tangent rays of the mix touch exactly (a double root) where R + r and
// r are exact in binary: not for the thin torus.
void expect_mix_has_every_kind(const std::vector<Ray>& rays, double R, double r, bool exact_tangents) {
  int hits = 0, tangents = 0, invalid = 0;
  for (const Ray& ray : rays) {
    double t[4];
    const int c = intersect_torus_checked(R, r, ray.o, ray.d, t);
    hits += c > 0;
    tangents += c >= 2 && t[0] == t[1];
    invalid += !torus_ray_valid(ray.o, ray.d);
  }
  const int n = static_cast<int>(rays.size());
  EXPECT_GT(hits, n / 4);
  EXPECT_GT(n - hits - invalid, n / 10);
  if (exact_tangents) {
    EXPECT_GT(tangents, 0);
  }
  EXPECT_GT(invalid, n / 5);
}

TEST_P(TorusBatch, EveryRowIsTheSingleRayCallRingTorus) {
  const auto rays = mixed_rays(1, 0.25, 4000);
  expect_mix_has_every_kind(rays, 1, 0.25, true);
  expect_rows_match(1, 0.25, rays);
}

TEST_P(TorusBatch, EveryRowIsTheSingleRayCallSpindleTorus) {
  const auto rays = mixed_rays(1, 1.5, 4000);
  expect_mix_has_every_kind(rays, 1, 1.5, true);
  expect_rows_match(1, 1.5, rays);
}

TEST_P(TorusBatch, EveryRowIsTheSingleRayCallThinTorus) {
  const auto rays = mixed_rays(1e4, 1e-2, 4000);
  expect_mix_has_every_kind(rays, 1e4, 1e-2, false);
  expect_rows_match(1e4, 1e-2, rays);
}

// Renderer-like rays on tori of several shapes and sizes (the tiny and huge
// ones are the scalar code's, rescaled), in batches of every length up to
// two chunks and a few vectors, so that every tail is exercised.
TEST_P(TorusBatch, RendererRaysMatchTheSingleRayCallOnEveryTorus) {
  const double tori[][2] = {{1, 0.25}, {1, 0.9}, {3, 0.01}, {1, 1e-6}, {1e-120, 2e-121}, {1e120, 3e119}, {1, 1}};
  for (const auto& torus : tori) {
    SCOPED_TRACE(std::to_string(torus[0]) + " " + std::to_string(torus[1]));
    const auto rays = renderer_rays(torus[0], torus[1], 3000);
    const int hits = expect_rows_match(torus[0], torus[1], rays);
    EXPECT_GT(hits, 300);
  }
  const auto rays = renderer_rays(1, 0.25, 300);
  for (std::size_t n : {1, 2, 3, 5, 7, 8, 9, 15, 17, 127, 128, 129, 255, 256, 257, 300}) {
    SCOPED_TRACE(n);
    expect_rows_match(1, 0.25, std::vector<Ray>(rays.begin(), rays.begin() + n));
  }
}

// Rays that pass the axis, 1e-5 to 1e-300 from it, two units from their
// point nearest the centre: from some distance on, the scalar code cuts the
// axis passage as a kink, and the batch must hand those rays to it.
TEST_P(TorusBatch, RaysPassingTheAxisAwayFromTheCentreMatchTheSingleRayCall) {
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const double r : {0.25, 0.9}) {
    SCOPED_TRACE(r);
    std::vector<Ray> rays;
    for (int i = 0; i < 2000; ++i) {
      const double offset = std::pow(10.0, -5.0 - (i % 60) * 5), a = 3.14159 * u(gen);
      const double d[3] = {std::cos(a), std::sin(a), -0.3 + 0.1 * u(gen)};
      const double q[3] = {-std::sin(a) * offset, std::cos(a) * offset, r * 0.8 * u(gen)};
      rays.push_back(Ray{{q[0] - 2 * d[0], q[1] - 2 * d[1], q[2] - 2 * d[2]}, {d[0], d[1], d[2]}});
    }
    EXPECT_GT(expect_rows_match(1, r, rays), 500);
  }
}

TEST_P(TorusBatch, InvalidRadiiSetEveryCountMinusOneAndEveryRootNaN) {
  const double o[6] = {-5, 0, 0, -5, 0.1, 0}, d[6] = {1, 0, 0, 1, 0, 0};
  for (const double bad : {0.0, -1.0, kNaN, kInf}) {
    int counts[2] = {7, 7};
    double roots[8] = {7, 7, 7, 7, 7, 7, 7, 7};
    EXPECT_EQ(intersect_torus_batch_on(GetParam(), bad, 0.25, 2, o, d, counts, roots), -1);
    EXPECT_EQ(counts[0], -1);
    EXPECT_EQ(counts[1], -1);
    for (const double t : roots) EXPECT_TRUE(std::isnan(t));
  }
}

TEST_P(TorusBatch, KnownRowsAndNaNPadding) {
  const double o[9] = {-5, 0, 0, 1.25, -5, 0, -5, 5, 0}, d[9] = {1, 0, 0, 0, 1, 0, 1, 0, 0};
  int counts[3];
  double roots[12];
  EXPECT_EQ(intersect_torus_batch_on(GetParam(), 1, 0.25, 3, o, d, counts, roots), 6);
  EXPECT_EQ(counts[0], 4);
  EXPECT_EQ(roots[0], 3.75);
  EXPECT_EQ(roots[1], 4.25);
  EXPECT_EQ(roots[2], 5.75);
  EXPECT_EQ(roots[3], 6.25);
  EXPECT_EQ(counts[1], 2);  // tangent to the outer equator at (1.25, 0, 0): a double root
  EXPECT_EQ(roots[4], 5);
  EXPECT_EQ(roots[5], 5);
  EXPECT_TRUE(std::isnan(roots[6]) && std::isnan(roots[7]));
  EXPECT_EQ(counts[2], 0);
  for (int k = 8; k < 12; ++k) EXPECT_TRUE(std::isnan(roots[k]));
}

TEST_P(TorusBatch, EmptyBatchTouchesNothing) {
  EXPECT_EQ(intersect_torus_batch_on(GetParam(), 1, 0.25, 0, nullptr, nullptr, nullptr, nullptr), 0);
  EXPECT_EQ(intersect_torus_batch_on(GetParam(), -1, 0.25, 0, nullptr, nullptr, nullptr, nullptr), -1);
}

// The cube root's seed, which the SIMD paths compute from the bits with
// double arithmetic, is the scalar seed's integer division, bit for bit:
// over the whole range, every exponent, and both ends.
TEST_P(TorusBatch, CubeRootSeedIsTheScalarSeed) {
  std::mt19937_64 rng(7);
  std::vector<double> in;
  for (int e = -900; e < 900; ++e)
    for (int k = 0; k < 200; ++k) in.push_back(std::ldexp(1.0 + std::ldexp(static_cast<double>(rng() >> 12), -52), e));
  for (int e = -900; e <= 900; ++e) {
    in.push_back(std::ldexp(1.0, e));
    in.push_back(std::nextafter(std::ldexp(1.0, e + 1), 0.0));
  }
  std::vector<double> vector_seeds(in.size());
  cube_root_seeds_on(GetParam(), in.size(), in.data(), vector_seeds.data());
  int differ = 0;
  for (std::size_t i = 0; i < in.size(); ++i) differ += !same_bits(vector_seeds[i], cube_root_seed(in[i]));
  EXPECT_EQ(differ, 0) << "of " << in.size();
}

INSTANTIATE_TEST_SUITE_P(Paths, TorusBatch, testing::Values(BatchPath::Scalar, BatchPath::Avx2, BatchPath::Avx512),
                         [](const testing::TestParamInfo<BatchPath>& info) {
                           return std::string(batch_path_name(info.param));
                         });

// The batch call takes the widest path this CPU has.
TEST(TorusBatchPath, TheBatchCallTakesTheWidestAvailablePath) {
  EXPECT_TRUE(batch_path_available(BatchPath::Scalar));
  const BatchPath best = batch_path_best();
  EXPECT_TRUE(batch_path_available(best));
  if (batch_path_available(BatchPath::Avx512))
    EXPECT_EQ(best, BatchPath::Avx512);
  else if (batch_path_available(BatchPath::Avx2))
    EXPECT_EQ(best, BatchPath::Avx2);
  else
    EXPECT_EQ(best, BatchPath::Scalar);
}

}  // namespace
}  // namespace toroid
