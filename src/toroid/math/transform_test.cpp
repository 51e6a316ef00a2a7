// SPDX-License-Identifier: Apache-2.0
// transformations.feature
#include "toroid/math/transform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/approx.h"

namespace toroid {
namespace {

using std::numbers::pi;

const double kHalfSqrt2 = std::sqrt(2.0) / 2;

// Builds a 4x4 matrix from its rows, as the book's tables list them.
Matrix4 mat4(const double (&rows)[4][4]) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r(i, j) = rows[i][j];
  return r;
}

TEST(Transformations, MultiplyingByATranslationMatrix) {
  const Matrix4 transform = translation(5, -3, 2);
  const Tuple p = point(-3, 4, 5);
  EXPECT_APPROX(transform * p, point(2, 1, 7));
}

TEST(Transformations, MultiplyingByTheInverseOfATranslationMatrix) {
  const Matrix4 transform = translation(5, -3, 2);
  const Matrix4 inv = inverse(transform);
  const Tuple p = point(-3, 4, 5);
  EXPECT_APPROX(inv * p, point(-8, 7, 3));
}

TEST(Transformations, TranslationDoesNotAffectVectors) {
  const Matrix4 transform = translation(5, -3, 2);
  const Tuple v = vector(-3, 4, 5);
  EXPECT_APPROX(transform * v, v);
}

TEST(Transformations, AScalingMatrixAppliedToAPoint) {
  const Matrix4 transform = scaling(2, 3, 4);
  const Tuple p = point(-4, 6, 8);
  EXPECT_APPROX(transform * p, point(-8, 18, 32));
}

TEST(Transformations, AScalingMatrixAppliedToAVector) {
  const Matrix4 transform = scaling(2, 3, 4);
  const Tuple v = vector(-4, 6, 8);
  EXPECT_APPROX(transform * v, vector(-8, 18, 32));
}

TEST(Transformations, MultiplyingByTheInverseOfAScalingMatrix) {
  const Matrix4 transform = scaling(2, 3, 4);
  const Matrix4 inv = inverse(transform);
  const Tuple v = vector(-4, 6, 8);
  EXPECT_APPROX(inv * v, vector(-2, 2, 2));
}

TEST(Transformations, ReflectionIsScalingByANegativeValue) {
  const Matrix4 transform = scaling(-1, 1, 1);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(-2, 3, 4));
}

TEST(Transformations, RotatingAPointAroundTheXAxis) {
  const Tuple p = point(0, 1, 0);
  const Matrix4 half_quarter = rotation_x(pi / 4);
  const Matrix4 full_quarter = rotation_x(pi / 2);
  EXPECT_APPROX(half_quarter * p, point(0, kHalfSqrt2, kHalfSqrt2));
  EXPECT_APPROX(full_quarter * p, point(0, 0, 1));
}

TEST(Transformations, TheInverseOfAnXRotationRotatesInTheOppositeDirection) {
  const Tuple p = point(0, 1, 0);
  const Matrix4 half_quarter = rotation_x(pi / 4);
  const Matrix4 inv = inverse(half_quarter);
  EXPECT_APPROX(inv * p, point(0, kHalfSqrt2, -kHalfSqrt2));
}

TEST(Transformations, RotatingAPointAroundTheYAxis) {
  const Tuple p = point(0, 0, 1);
  const Matrix4 half_quarter = rotation_y(pi / 4);
  const Matrix4 full_quarter = rotation_y(pi / 2);
  EXPECT_APPROX(half_quarter * p, point(kHalfSqrt2, 0, kHalfSqrt2));
  EXPECT_APPROX(full_quarter * p, point(1, 0, 0));
}

TEST(Transformations, RotatingAPointAroundTheZAxis) {
  const Tuple p = point(0, 1, 0);
  const Matrix4 half_quarter = rotation_z(pi / 4);
  const Matrix4 full_quarter = rotation_z(pi / 2);
  EXPECT_APPROX(half_quarter * p, point(-kHalfSqrt2, kHalfSqrt2, 0));
  EXPECT_APPROX(full_quarter * p, point(-1, 0, 0));
}

TEST(Transformations, AShearingTransformationMovesXInProportionToY) {
  const Matrix4 transform = shearing(1, 0, 0, 0, 0, 0);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(5, 3, 4));
}

TEST(Transformations, AShearingTransformationMovesXInProportionToZ) {
  const Matrix4 transform = shearing(0, 1, 0, 0, 0, 0);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(6, 3, 4));
}

TEST(Transformations, AShearingTransformationMovesYInProportionToX) {
  const Matrix4 transform = shearing(0, 0, 1, 0, 0, 0);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(2, 5, 4));
}

TEST(Transformations, AShearingTransformationMovesYInProportionToZ) {
  const Matrix4 transform = shearing(0, 0, 0, 1, 0, 0);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(2, 7, 4));
}

TEST(Transformations, AShearingTransformationMovesZInProportionToX) {
  const Matrix4 transform = shearing(0, 0, 0, 0, 1, 0);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(2, 3, 6));
}

TEST(Transformations, AShearingTransformationMovesZInProportionToY) {
  const Matrix4 transform = shearing(0, 0, 0, 0, 0, 1);
  const Tuple p = point(2, 3, 4);
  EXPECT_APPROX(transform * p, point(2, 3, 7));
}

TEST(Transformations, IndividualTransformationsAreAppliedInSequence) {
  const Tuple p = point(1, 0, 1);
  const Matrix4 A = rotation_x(pi / 2);
  const Matrix4 B = scaling(5, 5, 5);
  const Matrix4 C = translation(10, 5, 7);
  // Apply the rotation first,
  const Tuple p2 = A * p;
  EXPECT_APPROX(p2, point(1, -1, 0));
  // then the scaling,
  const Tuple p3 = B * p2;
  EXPECT_APPROX(p3, point(5, -5, 0));
  // then the translation.
  const Tuple p4 = C * p3;
  EXPECT_APPROX(p4, point(15, 0, 7));
}

TEST(Transformations, ChainedTransformationsMustBeAppliedInReverseOrder) {
  const Tuple p = point(1, 0, 1);
  const Matrix4 A = rotation_x(pi / 2);
  const Matrix4 B = scaling(5, 5, 5);
  const Matrix4 C = translation(10, 5, 7);
  const Matrix4 T = C * B * A;
  EXPECT_APPROX(T * p, point(15, 0, 7));
}

TEST(Transformations, TheTransformationMatrixForTheDefaultOrientation) {
  const Tuple from = point(0, 0, 0);
  const Tuple to = point(0, 0, -1);
  const Tuple up = vector(0, 1, 0);
  const Matrix4 t = view_transform(from, to, up);
  EXPECT_APPROX(t, Matrix4::identity());
}

TEST(Transformations, AViewTransformationMatrixLookingInPositiveZDirection) {
  const Tuple from = point(0, 0, 0);
  const Tuple to = point(0, 0, 1);
  const Tuple up = vector(0, 1, 0);
  const Matrix4 t = view_transform(from, to, up);
  EXPECT_APPROX(t, scaling(-1, 1, -1));
}

TEST(Transformations, TheViewTransformationMovesTheWorld) {
  const Tuple from = point(0, 0, 8);
  const Tuple to = point(0, 0, 0);
  const Tuple up = vector(0, 1, 0);
  const Matrix4 t = view_transform(from, to, up);
  EXPECT_APPROX(t, translation(0, 0, -8));
}

TEST(Transformations, AnArbitraryViewTransformation) {
  const Tuple from = point(1, 3, 2);
  const Tuple to = point(4, -2, 8);
  const Tuple up = vector(1, 1, 0);
  const Matrix4 t = view_transform(from, to, up);
  EXPECT_APPROX(t, mat4({{-0.50709, 0.50709, 0.67612, -2.36643},  //
                         {0.76772, 0.60609, 0.12122, -2.82843},
                         {-0.35857, 0.59761, -0.71714, 0.00000},
                         {0.00000, 0.00000, 0.00000, 1.00000}}));
}

}  // namespace
}  // namespace toroid
