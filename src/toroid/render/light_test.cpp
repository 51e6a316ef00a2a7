// SPDX-License-Identifier: Apache-2.0
// lights.feature, with the soft-shadows bonus chapter's scenarios (community
// transcription in ../shared/rtc-features/bonus_community/).
#include "toroid/render/light.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "support/approx.h"
#include "support/sequence.h"
#include "toroid/math/hash.h"
#include "toroid/render/world.h"

namespace toroid {
namespace {

TEST(Lights, APointLightHasAPositionAndIntensity) {
  const Color intensity{1, 1, 1};
  const Tuple position = point(0, 0, 0);
  const PointLight light{position, intensity};
  EXPECT_APPROX(light.position, position);
  EXPECT_APPROX(light.intensity, intensity);
}

TEST(Lights, PointLightsEvaluateTheLightIntensityAtAGivenPoint) {
  const World w = default_world();
  const PointLight& light = w.lights[0];
  const struct {
    Tuple pt;
    double result;
  } examples[] = {
      {point(0, 1.0001, 0), 1.0}, {point(-1.0001, 0, 0), 1.0}, {point(0, 0, -1.0001), 1.0}, {point(0, 0, 1.0001), 0.0},
      {point(1.0001, 0, 0), 0.0}, {point(0, -1.0001, 0), 0.0}, {point(0, 0, 0), 0.0},
  };
  for (const auto& e : examples) {
    SCOPED_TRACE(::testing::PrintToString(e.pt));
    EXPECT_EQ(intensity_at(light, e.pt, w), e.result);
  }
}

// Given corner <- point(0, 0, 0), v1 <- vector(2, 0, 0), v2 <- vector(0, 0, 1).
AreaLight book_area_light() {
  return AreaLight(point(0, 0, 0), vector(2, 0, 0), 4, vector(0, 0, 1), 2, Color{1, 1, 1});
}

TEST(Lights, CreatingAnAreaLight) {
  const Tuple corner = point(0, 0, 0);
  const AreaLight light(corner, vector(2, 0, 0), 4, vector(0, 0, 1), 2, Color{1, 1, 1});
  EXPECT_APPROX(light.corner, corner);
  EXPECT_APPROX(light.uvec, vector(0.5, 0, 0));
  EXPECT_EQ(light.usteps, 4);
  EXPECT_APPROX(light.vvec, vector(0, 0, 0.5));
  EXPECT_EQ(light.vsteps, 2);
  EXPECT_EQ(light.samples, 8);
}

TEST(Lights, FindingASinglePointOnAnAreaLight) {
  const AreaLight light = book_area_light();
  const struct {
    int u, v;
    Tuple result;
  } examples[] = {
      {0, 0, point(0.25, 0, 0.25)}, {1, 0, point(0.75, 0, 0.25)}, {0, 1, point(0.25, 0, 0.75)},
      {2, 0, point(1.25, 0, 0.25)}, {3, 1, point(1.75, 0, 0.75)},
  };
  for (const auto& e : examples) {
    SCOPED_TRACE(::testing::Message() << "u=" << e.u << " v=" << e.v);
    EXPECT_APPROX(light.point_on_light(e.u, e.v), e.result);
  }
}

TEST(Lights, TheAreaLightIntensityFunction) {
  const World w = default_world();
  const AreaLight light(point(-0.5, -0.5, -5), vector(1, 0, 0), 2, vector(0, 1, 0), 2, Color{1, 1, 1});
  const struct {
    Tuple pt;
    double result;
  } examples[] = {
      {point(0, 0, 2), 0.0},        {point(1, -1, 2), 0.25}, {point(1.5, 0, 2), 0.5},
      {point(1.25, 1.25, 3), 0.75}, {point(0, 0, -2), 1.0},
  };
  for (const auto& e : examples) {
    SCOPED_TRACE(::testing::PrintToString(e.pt));
    EXPECT_EQ(intensity_at(light, e.pt, w), e.result);
  }
}

TEST(Lights, FindingASinglePointOnAJitteredAreaLight) {
  const AreaLight light = book_area_light();
  const struct {
    int u, v;
    Tuple result;
  } examples[] = {
      {0, 0, point(0.15, 0, 0.35)}, {1, 0, point(0.65, 0, 0.35)}, {0, 1, point(0.15, 0, 0.85)},
      {2, 0, point(1.15, 0, 0.35)}, {3, 1, point(1.65, 0, 0.85)},
  };
  for (const auto& e : examples) {
    SCOPED_TRACE(::testing::Message() << "u=" << e.u << " v=" << e.v);
    testing::Sequence jitter_by{0.3, 0.7};  // light.jitter_by <- sequence(0.3, 0.7)
    const double ju = jitter_by.next();
    const double jv = jitter_by.next();
    EXPECT_APPROX(light.point_on_light(e.u, e.v, ju, jv), e.result);
  }
}

// Beyond the feature: the renderer's jitter.
TEST(AreaLights, JitteredSamplesStayInTheirCellsAndDependOnlyOnThePoint) {
  AreaLight light = book_area_light();
  light.jitter = true;
  const std::uint64_t key = light.jitter_key(point(0.3, 2, -1));
  EXPECT_EQ(light.jitter_key(point(0.3, 2, -1)), key);
  const std::uint64_t other = light.jitter_key(point(0.3, 2, -1.0000001));
  bool differs = false;
  for (int v = 0; v < light.vsteps; ++v)
    for (int u = 0; u < light.usteps; ++u) {
      const Tuple s = light.sample(key, u, v);
      EXPECT_GE(s.x, 0.5 * u);
      EXPECT_LT(s.x, 0.5 * (u + 1));
      EXPECT_GE(s.z, 0.5 * v);
      EXPECT_LT(s.z, 0.5 * (v + 1));
      EXPECT_EQ(s.y, 0);
      const Tuple t = light.sample(other, u, v);
      differs = differs || t.x != s.x || t.z != s.z;
      // Jittered: not at the cell's centre.
      EXPECT_FALSE(approx_equal(s, light.point_on_light(u, v), 1e-12));
    }
  EXPECT_TRUE(differs);
  light.jitter = false;
  EXPECT_APPROX(light.sample(light.jitter_key(point(0.3, 2, -1)), 3, 1), point(1.75, 0, 0.75));
}

// The noise does not move with the last bits of the shaded point: a point
// a few roundings away keeps its key (the samples of a shape intersected
// another way, or built with fused multiply-adds, stay where they were).
TEST(AreaLights, APointAFewRoundingsAwayKeepsItsJitterKey) {
  AreaLight light = book_area_light();
  light.jitter = true;
  std::uint64_t state = 99;
  int kept = 0, moved_apart = 0;
  for (int i = 0; i < 1000; ++i) {
    const auto coordinate = [&] { return (2 * unit_interval(state = splitmix64(state)) - 1) * 20; };
    const Tuple p = point(coordinate(), coordinate(), coordinate());
    // Each coordinate moved by up to 4 units in the last place of the
    // largest one (how far a hit point's rounding reaches).
    const double ulp = std::ldexp(std::numeric_limits<double>::epsilon(),
                                  std::ilogb(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)})));
    const Tuple q = p + vector(3 * ulp, -4 * ulp, ulp);
    kept += light.jitter_key(q) == light.jitter_key(p) ? 1 : 0;
    // A point a millionth of the scene away has samples of its own.
    moved_apart += light.jitter_key(p + vector(0, 2e-5, 0)) != light.jitter_key(p) ? 1 : 0;
  }
  EXPECT_GE(kept, 995);  // all but the rare point beside a cell's edge
  EXPECT_EQ(moved_apart, 1000);
}

TEST(AreaLights, AnAreaLightWhollyBehindASurfaceLightsNothing) {
  const AreaLight light(point(-0.5, -0.5, -5), vector(1, 0, 0), 2, vector(0, 1, 0), 2, Color{1, 1, 1});
  EXPECT_TRUE(light.in_front_of(point(0, 0, 0), vector(0, 0, -1)));
  EXPECT_FALSE(light.in_front_of(point(0, 0, 0), vector(0, 0, 1)));
  // Seen edge-on from a plane through one corner's edge, part of it is in front.
  EXPECT_TRUE(light.in_front_of(point(0, 0, 0), vector(1, 0, 0)));
  EXPECT_FALSE(light.in_front_of(point(0.6, 0, 0), vector(1, 0, 0)));
}

}  // namespace
}  // namespace toroid
