// SPDX-License-Identifier: Apache-2.0
// The float entry points (float_api.h) answer what the double functions
// answer, rounded to float, and the float nearest root always lies in the
// float interval.
#include "toroid/torus/float_api.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace toroid {
namespace {

constexpr float kInfF = std::numeric_limits<float>::infinity();
constexpr double kInf = std::numeric_limits<double>::infinity();

struct FloatRay {
  float o[3], d[3];
};

std::vector<FloatRay> float_rays(float R, float r, int count) {
  std::mt19937_64 gen(99);
  std::uniform_real_distribution<float> u(-1, 1);
  std::vector<FloatRay> rays;
  for (int i = 0; i < count; ++i) {
    FloatRay ray{};
    for (int k = 0; k < 3; ++k) ray.o[k] = 4 * (R + r) * u(gen);
    if (i % 3 == 0) {
      for (float& c : ray.d) c = u(gen);
    } else {
      ray.d[0] = R * u(gen) - ray.o[0];
      ray.d[1] = R * u(gen) - ray.o[1];
      ray.d[2] = r * u(gen) - ray.o[2];
    }
    rays.push_back(ray);
  }
  return rays;
}

void widen(const float in[3], double out[3]) {
  for (int k = 0; k < 3; ++k) out[k] = in[k];
}

TEST(TorusFloat, RootsAreTheDoubleRootsRounded) {
  int hits = 0;
  for (const TorusSolver s : {TorusSolver::Default, TorusSolver::Ferrari})
    for (const FloatRay& ray : float_rays(1, 0.25f, 3000)) {
      double o[3], d[3], td[4];
      widen(ray.o, o);
      widen(ray.d, d);
      const int nd = intersect_torus(1.0, 0.25, o, d, td, s);
      float tf[4];
      const int nf = intersect_torus(1.0f, 0.25f, ray.o, ray.d, tf, s);
      ASSERT_EQ(nf, nd);
      for (int i = 0; i < nf; ++i) ASSERT_EQ(tf[i], static_cast<float>(td[i])) << i;
      hits += nf > 0;
    }
  EXPECT_GT(hits, 1000);
}

TEST(TorusFloat, KnownRoots) {
  const float o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  float t[4];
  ASSERT_EQ(intersect_torus(1.0f, 0.25f, o, d, t), 4);
  EXPECT_EQ(t[0], 3.75f);
  EXPECT_EQ(t[1], 4.25f);
  EXPECT_EQ(t[2], 5.75f);
  EXPECT_EQ(t[3], 6.25f);
  float n[3];
  const float p[3] = {1.25f, 0, 0};
  torus_normal(1.0f, 0.25f, p, n);
  EXPECT_EQ(n[0], 0.25f);
  EXPECT_EQ(n[1], 0);
  EXPECT_EQ(n[2], 0);
}

TEST(TorusFloat, RootsBeyondFloatRangeAreLeftOut) {
  // With |d| = 2^-140 the roots are about 2^140 > FLT_MAX: none is a float.
  const float o[3] = {-5, 0, 0}, d[3] = {0x1p-140f, 0, 0};
  float t[4];
  EXPECT_EQ(intersect_torus(1.0f, 0.25f, o, d, t), 0);
}

TEST(TorusFloat, NormalIsTheDoubleNormalRounded) {
  std::mt19937_64 gen(5);
  std::uniform_real_distribution<float> u(-2, 2);
  for (int i = 0; i < 1000; ++i) {
    const float p[3] = {u(gen), u(gen), u(gen)};
    double q[3], nd[3];
    widen(p, q);
    torus_normal(1.0, 1.5, q, nd);
    float nf[3];
    torus_normal(1.0f, 1.5f, p, nf);
    for (int k = 0; k < 3; ++k) ASSERT_EQ(nf[k], static_cast<float>(nd[k]));
  }
}

// (lo, hi) holds exactly the doubles whose float lies in (t_min, t_max):
// checked at the interval's ends, their neighbours, and the float bounds.
void expect_interval_exact(float t_min, float t_max) {
  double lo, hi;
  ASSERT_TRUE(float_interval_in_double(t_min, t_max, &lo, &hi)) << t_min << " " << t_max;
  for (const double x : {lo, hi, std::nextafter(lo, kInf), std::nextafter(lo, -kInf), std::nextafter(hi, kInf),
                         std::nextafter(hi, -kInf), static_cast<double>(t_min), static_cast<double>(t_max)}) {
    const float f = static_cast<float>(x);
    const bool inside_float = f > t_min && f < t_max && std::isfinite(f);
    EXPECT_EQ(x > lo && x < hi, inside_float) << t_min << " " << t_max << " x " << x;
  }
}

TEST(TorusFloat, FloatIntervalInDoubleIsExact) {
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<float> u(-10, 10);
  for (int i = 0; i < 2000; ++i) {
    float a = u(gen), b = u(gen);
    if (a > b) std::swap(a, b);
    if (std::nextafter(a, kInfF) < b) expect_interval_exact(a, b);
  }
  // Bounds whose neighbours are even and odd, zeros, subnormals, the ends.
  const float special[] = {
      -kInfF,  -FLT_MAX, -1.0f, -0x1p-149f, -0.0f, 0.0f, 0x1p-149f, 0x1p-148f, 1.0f, 1.5f, std::nextafter(1.0f, 2.0f),
      FLT_MAX, kInfF};
  for (const float a : special)
    for (const float b : special)
      if (a < b && std::nextafter(a, kInfF) < b) expect_interval_exact(a, b);
  double lo = 7, hi = 7;
  EXPECT_FALSE(float_interval_in_double(1.0f, 1.0f, &lo, &hi));
  EXPECT_FALSE(float_interval_in_double(1.0f, std::nextafter(1.0f, 2.0f), &lo, &hi));
  EXPECT_FALSE(float_interval_in_double(2.0f, 1.0f, &lo, &hi));
  EXPECT_FALSE(float_interval_in_double(std::nanf(""), 1.0f, &lo, &hi));
  EXPECT_FALSE(float_interval_in_double(FLT_MAX, kInfF, &lo, &hi));
  EXPECT_EQ(lo, 7);
}

TEST(TorusFloat, NearestIsTheDoubleNearestRoundedAndInsideTheFloatInterval) {
  int found = 0;
  for (const FloatRay& ray : float_rays(1, 0.25f, 3000)) {
    double o[3], d[3], all[4];
    widen(ray.o, o);
    widen(ray.d, d);
    const int n = intersect_torus(1.0, 0.25, o, d, all);
    // Windows that start just below, at, and just above each root's float.
    std::vector<float> starts = {-kInfF, 0.0f};
    for (int i = 0; i < n; ++i) {
      const float f = static_cast<float>(all[i]);
      starts.insert(starts.end(), {std::nextafter(f, -kInfF), f, std::nextafter(f, kInfF)});
    }
    for (const float t_min : starts)
      for (const float t_max : {kInfF, 1e4f}) {
        float t = -7;
        const bool hit = intersect_torus_nearest(1.0f, 0.25f, ray.o, ray.d, t_min, t_max, &t);
        EXPECT_EQ(torus_blocks(1.0f, 0.25f, ray.o, ray.d, t_min, t_max), hit);
        // The expected answer: the first root whose float is strictly inside.
        bool want = false;
        float want_t = 0;
        for (int i = 0; i < n && !want; ++i) {
          const float f = static_cast<float>(all[i]);
          if (f > t_min && f < t_max) want = true, want_t = f;
        }
        ASSERT_EQ(hit, want) << t_min;
        if (hit) {
          ASSERT_EQ(t, want_t) << t_min;
          ASSERT_TRUE(t > t_min && t < t_max);
          ++found;
        } else {
          ASSERT_EQ(t, -7);  // untouched
        }
      }
  }
  EXPECT_GT(found, 1000);
}

// A root just above a float bound rounds onto it: it is not in the open
// interval, and the next root is the answer.
TEST(TorusFloat, RootRoundingOntoTheLowerBoundIsSkipped) {
  int cases = 0;
  for (const FloatRay& ray : float_rays(1, 0.25f, 2000)) {
    double o[3], d[3], all[4];
    widen(ray.o, o);
    widen(ray.d, d);
    const int n = intersect_torus(1.0, 0.25, o, d, all);
    for (int i = 0; i < n; ++i) {
      const float f = static_cast<float>(all[i]);
      if (!(all[i] > f)) continue;  // need a root strictly above its float
      if (i + 1 < n && static_cast<float>(all[i + 1]) == f) continue;
      float t = -7;
      const bool hit = intersect_torus_nearest(1.0f, 0.25f, ray.o, ray.d, f, kInfF, &t);
      // In double the root is inside (f, inf); in float it is not.
      double td;
      ASSERT_TRUE(intersect_torus_nearest(1.0, 0.25, o, d, f, kInf, &td));
      ASSERT_EQ(static_cast<float>(td), f);
      if (i + 1 < n) {
        ASSERT_TRUE(hit);
        EXPECT_EQ(t, static_cast<float>(all[i + 1]));
      } else {
        EXPECT_FALSE(hit);
      }
      ++cases;
    }
  }
  EXPECT_GT(cases, 100);
}

}  // namespace
}  // namespace toroid
