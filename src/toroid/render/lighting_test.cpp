// materials.feature: lighting().
#include "toroid/render/lighting.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "support/approx.h"
#include "toroid/render/pattern.h"
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
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), Color(1.9, 1.9, 1.9));
}

TEST(Materials, LightingWithTheEyeBetweenLightAndSurfaceEyeOffset45Degrees) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, kHalfSqrt2, -kHalfSqrt2);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), Color(1.0, 1.0, 1.0));
}

TEST(Materials, LightingWithEyeOppositeSurfaceLightOffset45Degrees) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 10, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), Color(0.7364, 0.7364, 0.7364));
}

TEST(Materials, LightingWithEyeInThePathOfTheReflectionVector) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, -kHalfSqrt2, -kHalfSqrt2);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 10, -10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), Color(1.6364, 1.6364, 1.6364));
}

TEST(Materials, LightingWithTheLightBehindTheSurface) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, 10), Color{1, 1, 1}};
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv), Color(0.1, 0.1, 0.1));
}

TEST(Materials, LightingWithTheSurfaceInShadow) {
  auto [m, position, object] = Background{};
  const Tuple eyev = vector(0, 0, -1);
  const Tuple normalv = vector(0, 0, -1);
  const PointLight light{point(0, 0, -10), Color{1, 1, 1}};
  const bool in_shadow = true;
  EXPECT_APPROX(lighting(m, object, light, position, eyev, normalv, in_shadow), Color(0.1, 0.1, 0.1));
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
  EXPECT_APPROX(c1, Color(1, 1, 1));
  EXPECT_APPROX(c2, Color(0, 0, 0));
}

}  // namespace
}  // namespace toroid
