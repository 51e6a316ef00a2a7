// SPDX-License-Identifier: Apache-2.0
// matrices.feature
#include "toroid/math/matrix.h"

#include <gtest/gtest.h>

#include "support/approx.h"

namespace toroid {
namespace {

// Builds an NxN matrix from its rows, as the book's tables list them:
// mat({{a, b}, {c, d}}) is a Matrix2.
template <int N>
Matrix<N> mat(const double (&rows)[N][N]) {
  Matrix<N> r;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) r(i, j) = rows[i][j];
  return r;
}

TEST(Matrices, ConstructingAndInspectingA4x4Matrix) {
  const Matrix4 M = mat<4>({{1, 2, 3, 4},  //
                            {5.5, 6.5, 7.5, 8.5},
                            {9, 10, 11, 12},
                            {13.5, 14.5, 15.5, 16.5}});
  EXPECT_DOUBLE_EQ(M(0, 0), 1);
  EXPECT_DOUBLE_EQ(M(0, 3), 4);
  EXPECT_DOUBLE_EQ(M(1, 0), 5.5);
  EXPECT_DOUBLE_EQ(M(1, 2), 7.5);
  EXPECT_DOUBLE_EQ(M(2, 2), 11);
  EXPECT_DOUBLE_EQ(M(3, 0), 13.5);
  EXPECT_DOUBLE_EQ(M(3, 2), 15.5);
}

TEST(Matrices, A2x2MatrixOughtToBeRepresentable) {
  const Matrix2 M = mat<2>({{-3, 5},  //
                            {1, -2}});
  EXPECT_DOUBLE_EQ(M(0, 0), -3);
  EXPECT_DOUBLE_EQ(M(0, 1), 5);
  EXPECT_DOUBLE_EQ(M(1, 0), 1);
  EXPECT_DOUBLE_EQ(M(1, 1), -2);
}

TEST(Matrices, A3x3MatrixOughtToBeRepresentable) {
  const Matrix3 M = mat<3>({{-3, 5, 0},  //
                            {1, -2, -7},
                            {0, 1, 1}});
  EXPECT_DOUBLE_EQ(M(0, 0), -3);
  EXPECT_DOUBLE_EQ(M(1, 1), -2);
  EXPECT_DOUBLE_EQ(M(2, 2), 1);
}

TEST(Matrices, MatrixEqualityWithIdenticalMatrices) {
  const Matrix4 A = mat<4>({{1, 2, 3, 4},  //
                            {5, 6, 7, 8},
                            {9, 8, 7, 6},
                            {5, 4, 3, 2}});
  const Matrix4 B = mat<4>({{1, 2, 3, 4},  //
                            {5, 6, 7, 8},
                            {9, 8, 7, 6},
                            {5, 4, 3, 2}});
  EXPECT_APPROX(A, B);
  EXPECT_EQ(A, B);
}

TEST(Matrices, MatrixEqualityWithDifferentMatrices) {
  const Matrix4 A = mat<4>({{1, 2, 3, 4},  //
                            {5, 6, 7, 8},
                            {9, 8, 7, 6},
                            {5, 4, 3, 2}});
  const Matrix4 B = mat<4>({{2, 3, 4, 5},  //
                            {6, 7, 8, 9},
                            {8, 7, 6, 5},
                            {4, 3, 2, 1}});
  EXPECT_FALSE(approx_equal(A, B));
  EXPECT_NE(A, B);
}

TEST(Matrices, MultiplyingTwoMatrices) {
  const Matrix4 A = mat<4>({{1, 2, 3, 4},  //
                            {5, 6, 7, 8},
                            {9, 8, 7, 6},
                            {5, 4, 3, 2}});
  const Matrix4 B = mat<4>({{-2, 1, 2, 3},  //
                            {3, 2, 1, -1},
                            {4, 3, 6, 5},
                            {1, 2, 7, 8}});
  EXPECT_APPROX(A * B, mat<4>({{20, 22, 50, 48},  //
                               {44, 54, 114, 108},
                               {40, 58, 110, 102},
                               {16, 26, 46, 42}}));
}

TEST(Matrices, AMatrixMultipliedByATuple) {
  const Matrix4 A = mat<4>({{1, 2, 3, 4},  //
                            {2, 4, 4, 2},
                            {8, 6, 4, 1},
                            {0, 0, 0, 1}});
  const Tuple b{1, 2, 3, 1};
  EXPECT_APPROX(A * b, (Tuple{18, 24, 33, 1}));
}

TEST(Matrices, MultiplyingAMatrixByTheIdentityMatrix) {
  const Matrix4 A = mat<4>({{0, 1, 2, 4},  //
                            {1, 2, 4, 8},
                            {2, 4, 8, 16},
                            {4, 8, 16, 32}});
  EXPECT_APPROX(A * Matrix4::identity(), A);
}

TEST(Matrices, MultiplyingTheIdentityMatrixByATuple) {
  const Tuple a{1, 2, 3, 4};
  EXPECT_APPROX(Matrix4::identity() * a, a);
}

TEST(Matrices, TransposingAMatrix) {
  const Matrix4 A = mat<4>({{0, 9, 3, 0},  //
                            {9, 8, 0, 8},
                            {1, 8, 5, 3},
                            {0, 0, 5, 8}});
  EXPECT_APPROX(transpose(A), mat<4>({{0, 9, 1, 0},  //
                                      {9, 8, 8, 0},
                                      {3, 0, 5, 5},
                                      {0, 8, 3, 8}}));
}

TEST(Matrices, TransposingTheIdentityMatrix) {
  const Matrix4 A = transpose(Matrix4::identity());
  EXPECT_APPROX(A, Matrix4::identity());
  EXPECT_APPROX(A, mat<4>({{1, 0, 0, 0},  //
                           {0, 1, 0, 0},
                           {0, 0, 1, 0},
                           {0, 0, 0, 1}}));
}

TEST(Matrices, CalculatingTheDeterminantOfA2x2Matrix) {
  const Matrix2 A = mat<2>({{1, 5},  //
                            {-3, 2}});
  EXPECT_DOUBLE_EQ(determinant(A), 17);
}

TEST(Matrices, ASubmatrixOfA3x3MatrixIsA2x2Matrix) {
  const Matrix3 A = mat<3>({{1, 5, 0},  //
                            {-3, 2, 7},
                            {0, 6, -3}});
  EXPECT_APPROX(submatrix(A, 0, 2), mat<2>({{-3, 2},  //
                                            {0, 6}}));
}

TEST(Matrices, ASubmatrixOfA4x4MatrixIsA3x3Matrix) {
  const Matrix4 A = mat<4>({{-6, 1, 1, 6},  //
                            {-8, 5, 8, 6},
                            {-1, 0, 8, 2},
                            {-7, 1, -1, 1}});
  EXPECT_APPROX(submatrix(A, 2, 1), mat<3>({{-6, 1, 6},  //
                                            {-8, 8, 6},
                                            {-7, -1, 1}}));
}

TEST(Matrices, CalculatingAMinorOfA3x3Matrix) {
  const Matrix3 A = mat<3>({{3, 5, 0},  //
                            {2, -1, -7},
                            {6, -1, 5}});
  const Matrix2 B = submatrix(A, 1, 0);
  EXPECT_DOUBLE_EQ(determinant(B), 25);
  EXPECT_DOUBLE_EQ(minor(A, 1, 0), 25);
}

TEST(Matrices, CalculatingACofactorOfA3x3Matrix) {
  const Matrix3 A = mat<3>({{3, 5, 0},  //
                            {2, -1, -7},
                            {6, -1, 5}});
  EXPECT_DOUBLE_EQ(minor(A, 0, 0), -12);
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 0), -12);
  EXPECT_DOUBLE_EQ(minor(A, 1, 0), 25);
  EXPECT_DOUBLE_EQ(cofactor(A, 1, 0), -25);
}

TEST(Matrices, CalculatingTheDeterminantOfA3x3Matrix) {
  const Matrix3 A = mat<3>({{1, 2, 6},  //
                            {-5, 8, -4},
                            {2, 6, 4}});
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 0), 56);
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 1), 12);
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 2), -46);
  EXPECT_DOUBLE_EQ(determinant(A), -196);
}

TEST(Matrices, CalculatingTheDeterminantOfA4x4Matrix) {
  const Matrix4 A = mat<4>({{-2, -8, 3, 5},  //
                            {-3, 1, 7, 3},
                            {1, 2, -9, 6},
                            {-6, 7, 7, -9}});
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 0), 690);
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 1), 447);
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 2), 210);
  EXPECT_DOUBLE_EQ(cofactor(A, 0, 3), 51);
  EXPECT_DOUBLE_EQ(determinant(A), -4071);
}

TEST(Matrices, TestingAnInvertibleMatrixForInvertibility) {
  const Matrix4 A = mat<4>({{6, 4, 4, 4},  //
                            {5, 5, 7, 6},
                            {4, -9, 3, -7},
                            {9, 1, 7, -6}});
  EXPECT_DOUBLE_EQ(determinant(A), -2120);
  EXPECT_TRUE(is_invertible(A));
}

TEST(Matrices, TestingANoninvertibleMatrixForInvertibility) {
  const Matrix4 A = mat<4>({{-4, 2, -2, -3},  //
                            {9, 6, 2, 6},
                            {0, -5, 1, -5},
                            {0, 0, 0, 0}});
  EXPECT_DOUBLE_EQ(determinant(A), 0);
  EXPECT_FALSE(is_invertible(A));
}

TEST(Matrices, CalculatingTheInverseOfAMatrix) {
  const Matrix4 A = mat<4>({{-5, 2, 6, -8},  //
                            {1, -5, 1, 8},
                            {7, 7, -6, -7},
                            {1, -3, 7, 4}});
  const Matrix4 B = inverse(A);
  EXPECT_DOUBLE_EQ(determinant(A), 532);
  EXPECT_DOUBLE_EQ(cofactor(A, 2, 3), -160);
  EXPECT_DOUBLE_EQ(B(3, 2), -160.0 / 532);
  EXPECT_DOUBLE_EQ(cofactor(A, 3, 2), 105);
  EXPECT_DOUBLE_EQ(B(2, 3), 105.0 / 532);
  EXPECT_APPROX(B, mat<4>({{0.21805, 0.45113, 0.24060, -0.04511},  //
                           {-0.80827, -1.45677, -0.44361, 0.52068},
                           {-0.07895, -0.22368, -0.05263, 0.19737},
                           {-0.52256, -0.81391, -0.30075, 0.30639}}));
}

TEST(Matrices, CalculatingTheInverseOfAnotherMatrix) {
  const Matrix4 A = mat<4>({{8, -5, 9, 2},  //
                            {7, 5, 6, 1},
                            {-6, 0, 9, 6},
                            {-3, 0, -9, -4}});
  EXPECT_APPROX(inverse(A), mat<4>({{-0.15385, -0.15385, -0.28205, -0.53846},  //
                                    {-0.07692, 0.12308, 0.02564, 0.03077},
                                    {0.35897, 0.35897, 0.43590, 0.92308},
                                    {-0.69231, -0.69231, -0.76923, -1.92308}}));
}

TEST(Matrices, CalculatingTheInverseOfAThirdMatrix) {
  const Matrix4 A = mat<4>({{9, 3, 0, 9},  //
                            {-5, -2, -6, -3},
                            {-4, 9, 6, 4},
                            {-7, 6, 6, 2}});
  EXPECT_APPROX(inverse(A), mat<4>({{-0.04074, -0.07778, 0.14444, -0.22222},  //
                                    {-0.07778, 0.03333, 0.36667, -0.33333},
                                    {-0.02901, -0.14630, -0.10926, 0.12963},
                                    {0.17778, 0.06667, -0.26667, 0.33333}}));
}

TEST(Matrices, MultiplyingAProductByItsInverse) {
  const Matrix4 A = mat<4>({{3, -9, 7, 3},  //
                            {3, -8, 2, -9},
                            {-4, 4, 4, 1},
                            {-6, 5, -1, 1}});
  const Matrix4 B = mat<4>({{8, 2, 2, 2},  //
                            {3, -1, 7, 0},
                            {7, 0, 5, 4},
                            {6, -2, 0, 5}});
  const Matrix4 C = A * B;
  EXPECT_APPROX(C * inverse(B), A);
}

}  // namespace
}  // namespace toroid
