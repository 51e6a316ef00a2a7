// SPDX-License-Identifier: Apache-2.0
// materials.feature: lighting().
#include "toroid/render/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "support/approx.h"
#include "toroid/render/pattern.h"
#include "toroid/render/world.h"
#include "toroid/shapes/sphere.h"

namespace toroid {
namespace {

const double kHalfSqrt2 = std::sqrt(2.0) / 2;

// Background: m <- material(), position <- point(0, 0, 0); the lit object is
// a default sphere. (A plain struct, not a fixture: material_test.cpp shares
// the suite name with plain TESTs.)
struct Background {
  Material m;
  Tuple position = point(0, 0, 0);
  Sphere object;
};

TEST(Materials, LightingWithTheEyeBetweenTheLightAndTheSurface) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), (Color{1.9, 1.9, 1.9}));
}

TEST(Materials, LightingWithTheEyeBetweenLightAndSurfaceEyeOffset45Degrees) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, kHalfSqrt2, -kHalfSqrt2);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), (Color{1.0, 1.0, 1.0}));
}

TEST(Materials, LightingWithEyeOppositeSurfaceLightOffset45Degrees) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 10, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), (Color{0.7364, 0.7364, 0.7364}));
}

TEST(Materials, LightingWithEyeInThePathOfTheReflectionVector) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, -kHalfSqrt2, -kHalfSqrt2);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 10, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), (Color{1.6364, 1.6364, 1.6364}));
}

TEST(Materials, LightingWithTheLightBehindTheSurface) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, 10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), (Color{0.1, 0.1, 0.1}));
}

TEST(Materials, LightingWithTheSurfaceInShadow) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, -10), Color{1, 1, 1}};
  const bool in_shadow = true;
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv, in_shadow), (Color{0.1, 0.1, 0.1}));
}

TEST(Materials, LightingWithAPatternApplied) {
  Background bg;
  Material& m = bg.m;
  const Sphere& object = bg.object;
  m.pattern = std::make_shared<StripePattern>(Color{1, 1, 1}, Color{0, 0, 0});
  m.ambient = 1;
  m.diffuse = 0;
  m.specular = 0;
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, -10), Color{1, 1, 1}};
  const Color c1 = lighting(m, object, light, point(0.9, 0, 0), eyev, normalv, false);
  const Color c2 = lighting(m, object, light, point(1.1, 0, 0), eyev, normalv, false);
  EXPECT_APPROX(c1, (Color{1, 1, 1}));
  EXPECT_APPROX(c2, (Color{0, 0, 0}));
}

// The soft-shadows bonus chapter's materials scenarios (from the book's
// bonus chapter; not in the community transcription).

// Both scenarios' "shape.material.ambient ← 0.1, .diffuse ← 0.9,
// .specular ← 0, .color ← color(1, 1, 1)".
Material without_specular() {
  Material m;
  m.ambient = 0.1;
  m.diffuse = 0.9;
  m.specular = 0;
  m.color = Color{1, 1, 1};
  return m;
}

TEST(Materials, LightingUsesLightIntensityToAttenuateColor) {
  World w = default_world();
  w.lights[0] = PointLight{point(0, 0, -10), Color{1, 1, 1}};
  Shape& shape = *w.objects[0];
  shape.set_material(without_specular());
  const Tuple pt = point(0, 0, -1);
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const struct {
    double intensity;
    Color result;
  } examples[] = {{1.0, Color{1, 1, 1}}, {0.5, Color{0.55, 0.55, 0.55}}, {0.0, Color{0.1, 0.1, 0.1}}};
  for (const auto& e : examples) {
    SCOPED_TRACE(e.intensity);
    EXPECT_APPROX(lighting(shape.material(), shape, w.lights[0], pt, eyev, normalv, e.intensity), e.result);
  }
}

TEST(Materials, LightingSamplesTheAreaLight) {
  const AreaLight light(point(-0.5, -0.5, -5), vector(1, 0, 0), 2, vector(0, 1, 0), 2, Color{1, 1, 1});
  Sphere shape;
  shape.set_material(without_specular());
  const Tuple eye = point(0, 0, -5);
  const struct {
    Tuple pt;
    Color result;
  } examples[] = {{point(0, 0, -1), Color{0.9965, 0.9965, 0.9965}},
                  {point(0, 0.7071, -0.7071), Color{0.6232, 0.6232, 0.6232}}};
  // The book prints four decimals: the exact values are 0.996505 and
  // 0.623183 (0.1 + 0.9 x the mean cosine to the four cell centres), so the
  // comparison is at the printed precision, 1e-4.
  for (const auto& e : examples) {
    SCOPED_TRACE(::testing::PrintToString(e.pt));
    const Tuple eyev = normalize(eye - e.pt);
    const Tuple normalv = vector(e.pt.x, e.pt.y, e.pt.z);
    EXPECT_TRUE(approx_equal(lighting(shape.material(), shape, light, e.pt, eyev, normalv, 1.0), e.result, 1e-4));
  }
}

TEST(Materials, TheHighlightsPowerIsPowsToWithinItsExponentInUlps) {
  // Whole exponents by squaring (within about n ulps of pow), others by pow
  // itself; over the whole range of cosines, tiny ones included.
  std::uint64_t state = 0x2545F4914F6CDD1Dull;
  auto next = [&] {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return static_cast<double>(state >> 11) * 0x1p-53;
  };
  for (const double n : {1.0, 2.0, 3.0, 10.0, 50.0, 60.0, 200.0, 255.0, 1023.0, 1024.0}) {
    SCOPED_TRACE(n);
    EXPECT_EQ(specular_power(1.0, n), 1.0);
    EXPECT_EQ(specular_power(0.0, n), 0.0);
    EXPECT_EQ(specular_power(0.5, n), std::ldexp(1.0, -static_cast<int>(n)));  // exact: a power of two
    for (int i = 0; i < 2000; ++i) {
      const double x = 1 - next() * (i % 2 ? 1.0 : 0.01);  // highlights' cosines, near 1 and across (0, 1]
      const double want = std::pow(x, n);
      if (want < 0x1p-1000) continue;  // below the normal range ulps are wider
      EXPECT_LE(std::abs(specular_power(x, n) - want), 2 * n * 0x1p-52 * want) << x;
    }
  }
  // Not whole, or beyond the squaring's range: pow itself, bit for bit.
  for (const double n : {0.5, 7.25, 199.999, 1025.0, 4096.0})
    for (const double x : {0.25, 0.9, 0.999999}) EXPECT_EQ(specular_power(x, n), std::pow(x, n)) << n << " " << x;
}

}  // namespace
}  // namespace toroid
