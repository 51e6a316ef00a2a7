// SPDX-License-Identifier: Apache-2.0
// patterns.feature
#include "toroid/render/pattern.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/sphere.h"

namespace toroid {
namespace {

const Color black{0, 0, 0};
const Color white{1, 1, 1};

// The book's test_pattern(): the colour is the pattern-space point itself.
class TestPattern : public Pattern {
 public:
  Color pattern_at(const Tuple& p) const override { return Color{p.x, p.y, p.z}; }
};

TEST(Patterns, CreatingAStripePattern) {
  const StripePattern pattern(white, black);
  EXPECT_APPROX(pattern.a(), white);
  EXPECT_APPROX(pattern.b(), black);
}

TEST(Patterns, AStripePatternIsConstantInY) {
  const StripePattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 1, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 2, 0)), white);
}

TEST(Patterns, AStripePatternIsConstantInZ) {
  const StripePattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 1)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 2)), white);
}

TEST(Patterns, AStripePatternAlternatesInX) {
  const StripePattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0.9, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(1, 0, 0)), black);
  EXPECT_APPROX(pattern.pattern_at(point(-0.1, 0, 0)), black);
  EXPECT_APPROX(pattern.pattern_at(point(-1, 0, 0)), black);
  EXPECT_APPROX(pattern.pattern_at(point(-1.1, 0, 0)), white);
}

TEST(Patterns, StripesWithAnObjectTransformation) {
  Sphere object;
  object.set_transform(scaling(2, 2, 2));
  const StripePattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at_shape(object, point(1.5, 0, 0)), white);
}

TEST(Patterns, StripesWithAPatternTransformation) {
  const Sphere object;
  StripePattern pattern(white, black);
  pattern.set_transform(scaling(2, 2, 2));
  EXPECT_APPROX(pattern.pattern_at_shape(object, point(1.5, 0, 0)), white);
}

TEST(Patterns, StripesWithBothAnObjectAndAPatternTransformation) {
  Sphere object;
  object.set_transform(scaling(2, 2, 2));
  StripePattern pattern(white, black);
  pattern.set_transform(translation(0.5, 0, 0));
  EXPECT_APPROX(pattern.pattern_at_shape(object, point(2.5, 0, 0)), white);
}

TEST(Patterns, TheDefaultPatternTransformation) {
  const TestPattern pattern;
  EXPECT_APPROX(pattern.transform(), Matrix4::identity());
}

TEST(Patterns, AssigningATransformation) {
  TestPattern pattern;
  pattern.set_transform(translation(1, 2, 3));
  EXPECT_APPROX(pattern.transform(), translation(1, 2, 3));
}

TEST(Patterns, APatternWithAnObjectTransformation) {
  Sphere shape;
  shape.set_transform(scaling(2, 2, 2));
  const TestPattern pattern;
  EXPECT_APPROX(pattern.pattern_at_shape(shape, point(2, 3, 4)), (Color{1, 1.5, 2}));
}

TEST(Patterns, APatternWithAPatternTransformation) {
  const Sphere shape;
  TestPattern pattern;
  pattern.set_transform(scaling(2, 2, 2));
  EXPECT_APPROX(pattern.pattern_at_shape(shape, point(2, 3, 4)), (Color{1, 1.5, 2}));
}

TEST(Patterns, APatternWithBothAnObjectAndAPatternTransformation) {
  Sphere shape;
  shape.set_transform(scaling(2, 2, 2));
  TestPattern pattern;
  pattern.set_transform(translation(0.5, 1, 1.5));
  EXPECT_APPROX(pattern.pattern_at_shape(shape, point(2.5, 3, 3.5)), (Color{0.75, 0.5, 0.25}));
}

TEST(Patterns, AGradientLinearlyInterpolatesBetweenColors) {
  const GradientPattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0.25, 0, 0)), (Color{0.75, 0.75, 0.75}));
  EXPECT_APPROX(pattern.pattern_at(point(0.5, 0, 0)), (Color{0.5, 0.5, 0.5}));
  EXPECT_APPROX(pattern.pattern_at(point(0.75, 0, 0)), (Color{0.25, 0.25, 0.25}));
}

TEST(Patterns, ARingShouldExtendInBothXAndZ) {
  const RingPattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(1, 0, 0)), black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 1)), black);
  // 0.708 = just slightly more than sqrt(2)/2
  EXPECT_APPROX(pattern.pattern_at(point(0.708, 0, 0.708)), black);
}

TEST(Patterns, CheckersShouldRepeatInX) {
  const CheckersPattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0.99, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(1.01, 0, 0)), black);
}

TEST(Patterns, CheckersShouldRepeatInY) {
  const CheckersPattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0.99, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 1.01, 0)), black);
}

TEST(Patterns, CheckersShouldRepeatInZ) {
  const CheckersPattern pattern(white, black);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 0.99)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0, 0, 1.01)), black);
}

// Beyond the book.

TEST(PatternPrecision, StripesAlternateFarFromTheOriginAndBeyondWholeNumbers) {
  // Whole numbers below 2^52 are told even or odd by an integer test, larger
  // ones by fmod: both must agree with fmod(floor(x), 2) == 0.
  const StripePattern pattern(white, black);
  for (const double x : {0x1p52 - 1, 0x1p52 - 2, -0x1p40 - 1, -0x1p40 - 2, 0x1p51 + 3, -3.5, -4.5}) {
    const bool even = std::fmod(std::floor(x), 2.0) == 0.0;
    EXPECT_APPROX(pattern.pattern_at(point(x, 0, 0)), even ? white : black) << "x = " << x;
  }
  EXPECT_APPROX(pattern.pattern_at(point(0x1p52 - 1, 0, 0)), black);
  EXPECT_APPROX(pattern.pattern_at(point(0x1p60, 0, 0)), white);  // every double this large is even
  EXPECT_APPROX(pattern.pattern_at(point(-0x1p60, 0, 0)), white);
  EXPECT_APPROX(pattern.pattern_at(point(std::numeric_limits<double>::infinity(), 0, 0)), black);
  EXPECT_APPROX(pattern.pattern_at(point(std::nan(""), 0, 0)), black);
}

TEST(PatternPrecision, CheckersDoNotSpeckleOnAPlaneAtYZero) {
  // Points on y = 0 carry rounding noise of either sign; all must be white.
  const CheckersPattern pattern(white, black);
  for (const double y : {0.0, -0.0, 1e-15, -1e-15, -1e-12})
    EXPECT_APPROX(pattern.pattern_at(point(0.5, y, 0.5)), white) << "y = " << y;
  EXPECT_APPROX(pattern.pattern_at(point(0.5, -0.01, 0.5)), black);
}

TEST(PatternTransforms, ABlendedPatternAveragesItsPatternsEachThroughItsOwnTransform) {
  auto stripes_x = std::make_shared<StripePattern>(white, black);
  auto stripes_z = std::make_shared<StripePattern>(white, black);
  stripes_z->set_transform(rotation_y(-std::numbers::pi / 2));  // stripes across z
  const BlendedPattern blended(stripes_x, stripes_z);
  EXPECT_APPROX(blended.pattern_at(point(0.5, 0, 0.5)), white);
  EXPECT_APPROX(blended.pattern_at(point(1.5, 0, 0.5)), (Color{0.5, 0.5, 0.5}));
  EXPECT_APPROX(blended.pattern_at(point(1.5, 0, 1.5)), black);
}

TEST(PatternTransforms, APatternOnAPlaneFollowsThePlanesTransform) {
  Plane plane;
  plane.set_transform(translation(0, 1, 0));
  const TestPattern pattern;
  EXPECT_APPROX(pattern.pattern_at_shape(plane, point(2, 1, 3)), (Color{2, 0, 3}));
}

}  // namespace
}  // namespace toroid
