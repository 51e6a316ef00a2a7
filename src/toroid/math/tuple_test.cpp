// SPDX-License-Identifier: Apache-2.0
// tuples.feature (tuples, vectors, points, colours, reflection)
#include "toroid/math/tuple.h"

#include <gtest/gtest.h>

#include <cmath>

#include "support/approx.h"
#include "toroid/math/color.h"

namespace toroid {
namespace {

TEST(Tuples, ATupleWithW1IsAPoint) {
  const Tuple a{4.3, -4.2, 3.1, 1.0};
  EXPECT_DOUBLE_EQ(a.x, 4.3);
  EXPECT_DOUBLE_EQ(a.y, -4.2);
  EXPECT_DOUBLE_EQ(a.z, 3.1);
  EXPECT_DOUBLE_EQ(a.w, 1.0);
  EXPECT_TRUE(a.is_point());
  EXPECT_FALSE(a.is_vector());
}

TEST(Tuples, ATupleWithW0IsAVector) {
  const Tuple a{4.3, -4.2, 3.1, 0.0};
  EXPECT_DOUBLE_EQ(a.x, 4.3);
  EXPECT_DOUBLE_EQ(a.y, -4.2);
  EXPECT_DOUBLE_EQ(a.z, 3.1);
  EXPECT_DOUBLE_EQ(a.w, 0.0);
  EXPECT_FALSE(a.is_point());
  EXPECT_TRUE(a.is_vector());
}

TEST(Tuples, PointCreatesTuplesWithW1) {
  const Tuple p = point(4, -4, 3);
  EXPECT_APPROX(p, (Tuple{4, -4, 3, 1}));
}

TEST(Tuples, VectorCreatesTuplesWithW0) {
  const Tuple v = vector(4, -4, 3);
  EXPECT_APPROX(v, (Tuple{4, -4, 3, 0}));
}

TEST(Tuples, AddingTwoTuples) {
  const Tuple a1{3, -2, 5, 1};
  const Tuple a2{-2, 3, 1, 0};
  EXPECT_APPROX(a1 + a2, (Tuple{1, 1, 6, 1}));
}

TEST(Tuples, SubtractingTwoPoints) {
  const Tuple p1 = point(3, 2, 1);
  const Tuple p2 = point(5, 6, 7);
  EXPECT_APPROX(p1 - p2, vector(-2, -4, -6));
}

TEST(Tuples, SubtractingAVectorFromAPoint) {
  const Tuple p = point(3, 2, 1);
  const Tuple v = vector(5, 6, 7);
  EXPECT_APPROX(p - v, point(-2, -4, -6));
}

TEST(Tuples, SubtractingTwoVectors) {
  const Tuple v1 = vector(3, 2, 1);
  const Tuple v2 = vector(5, 6, 7);
  EXPECT_APPROX(v1 - v2, vector(-2, -4, -6));
}

TEST(Tuples, SubtractingAVectorFromTheZeroVector) {
  const Tuple zero = vector(0, 0, 0);
  const Tuple v = vector(1, -2, 3);
  EXPECT_APPROX(zero - v, vector(-1, 2, -3));
}

TEST(Tuples, NegatingATuple) {
  const Tuple a{1, -2, 3, -4};
  EXPECT_APPROX(-a, (Tuple{-1, 2, -3, 4}));
}

TEST(Tuples, MultiplyingATupleByAScalar) {
  const Tuple a{1, -2, 3, -4};
  EXPECT_APPROX(a * 3.5, (Tuple{3.5, -7, 10.5, -14}));
}

TEST(Tuples, MultiplyingATupleByAFraction) {
  const Tuple a{1, -2, 3, -4};
  EXPECT_APPROX(a * 0.5, (Tuple{0.5, -1, 1.5, -2}));
}

TEST(Tuples, DividingATupleByAScalar) {
  const Tuple a{1, -2, 3, -4};
  EXPECT_APPROX(a / 2, (Tuple{0.5, -1, 1.5, -2}));
}

TEST(Tuples, ComputingTheMagnitudeOfVector100) {
  const Tuple v = vector(1, 0, 0);
  EXPECT_DOUBLE_EQ(magnitude(v), 1);
}

TEST(Tuples, ComputingTheMagnitudeOfVector010) {
  const Tuple v = vector(0, 1, 0);
  EXPECT_DOUBLE_EQ(magnitude(v), 1);
}

TEST(Tuples, ComputingTheMagnitudeOfVector001) {
  const Tuple v = vector(0, 0, 1);
  EXPECT_DOUBLE_EQ(magnitude(v), 1);
}

TEST(Tuples, ComputingTheMagnitudeOfVector123) {
  const Tuple v = vector(1, 2, 3);
  EXPECT_DOUBLE_EQ(magnitude(v), std::sqrt(14.0));
}

TEST(Tuples, ComputingTheMagnitudeOfVectorNeg1Neg2Neg3) {
  const Tuple v = vector(-1, -2, -3);
  EXPECT_DOUBLE_EQ(magnitude(v), std::sqrt(14.0));
}

TEST(Tuples, NormalizingVector400Gives100) {
  const Tuple v = vector(4, 0, 0);
  EXPECT_APPROX(normalize(v), vector(1, 0, 0));
}

TEST(Tuples, NormalizingVector123) {
  const Tuple v = vector(1, 2, 3);
  // vector(1/√14, 2/√14, 3/√14)
  EXPECT_APPROX(normalize(v), vector(0.26726, 0.53452, 0.80178));
}

TEST(Tuples, TheMagnitudeOfANormalizedVector) {
  const Tuple v = vector(1, 2, 3);
  const Tuple norm = normalize(v);
  EXPECT_DOUBLE_EQ(magnitude(norm), 1);
}

TEST(Tuples, TheDotProductOfTwoTuples) {
  const Tuple a = vector(1, 2, 3);
  const Tuple b = vector(2, 3, 4);
  EXPECT_DOUBLE_EQ(dot(a, b), 20);
}

TEST(Tuples, TheCrossProductOfTwoVectors) {
  const Tuple a = vector(1, 2, 3);
  const Tuple b = vector(2, 3, 4);
  EXPECT_APPROX(cross(a, b), vector(-1, 2, -1));
  EXPECT_APPROX(cross(b, a), vector(1, -2, 1));
}

TEST(Tuples, ColorsAreRedGreenBlueTuples) {
  const Color c{-0.5, 0.4, 1.7};
  EXPECT_DOUBLE_EQ(c.r, -0.5);
  EXPECT_DOUBLE_EQ(c.g, 0.4);
  EXPECT_DOUBLE_EQ(c.b, 1.7);
}

TEST(Tuples, AddingColors) {
  const Color c1{0.9, 0.6, 0.75};
  const Color c2{0.7, 0.1, 0.25};
  EXPECT_APPROX(c1 + c2, (Color{1.6, 0.7, 1.0}));
}

TEST(Tuples, SubtractingColors) {
  const Color c1{0.9, 0.6, 0.75};
  const Color c2{0.7, 0.1, 0.25};
  EXPECT_APPROX(c1 - c2, (Color{0.2, 0.5, 0.5}));
}

TEST(Tuples, MultiplyingAColorByAScalar) {
  const Color c{0.2, 0.3, 0.4};
  EXPECT_APPROX(c * 2, (Color{0.4, 0.6, 0.8}));
}

TEST(Tuples, MultiplyingColors) {
  const Color c1{1, 0.2, 0.4};
  const Color c2{0.9, 1, 0.1};
  EXPECT_APPROX(c1 * c2, (Color{0.9, 0.2, 0.04}));
}

TEST(Tuples, ReflectingAVectorApproachingAt45Degrees) {
  const Tuple v = vector(1, -1, 0);
  const Tuple n = vector(0, 1, 0);
  const Tuple r = reflect(v, n);
  EXPECT_APPROX(r, vector(1, 1, 0));
}

TEST(Tuples, ReflectingAVectorOffASlantedSurface) {
  const Tuple v = vector(0, -1, 0);
  const Tuple n = vector(std::sqrt(2.0) / 2, std::sqrt(2.0) / 2, 0);
  const Tuple r = reflect(v, n);
  EXPECT_APPROX(r, vector(1, 0, 0));
}

}  // namespace
}  // namespace toroid
