// SPDX-License-Identifier: Apache-2.0
// Square matrices of size 2, 3 and 4 as in The Ray Tracer Challenge. Only the
// 4x4 ones are used by the renderer; the smaller ones exist for the cofactor
// expansion that the book's inverse is built from.
#pragma once

#include <array>
#include <iosfwd>

#include "toroid/math/tuple.h"

namespace toroid {

template <int N>
struct Matrix {
  std::array<std::array<double, N>, N> m{};

  constexpr double& operator()(int row, int col) { return m[row][col]; }
  constexpr double operator()(int row, int col) const { return m[row][col]; }

  static constexpr Matrix identity() {
    Matrix r;
    for (int i = 0; i < N; ++i) r.m[i][i] = 1.0;
    return r;
  }
};

using Matrix2 = Matrix<2>;
using Matrix3 = Matrix<3>;
using Matrix4 = Matrix<4>;

template <int N>
constexpr Matrix<N> operator*(const Matrix<N>& a, const Matrix<N>& b) {
  Matrix<N> r;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      double s = 0;
      for (int k = 0; k < N; ++k) s += a.m[i][k] * b.m[k][j];
      r.m[i][j] = s;
    }
  return r;
}

constexpr Tuple operator*(const Matrix4& a, const Tuple& t) {
  return {a.m[0][0] * t.x + a.m[0][1] * t.y + a.m[0][2] * t.z + a.m[0][3] * t.w,
          a.m[1][0] * t.x + a.m[1][1] * t.y + a.m[1][2] * t.z + a.m[1][3] * t.w,
          a.m[2][0] * t.x + a.m[2][1] * t.y + a.m[2][2] * t.z + a.m[2][3] * t.w,
          a.m[3][0] * t.x + a.m[3][1] * t.y + a.m[3][2] * t.z + a.m[3][3] * t.w};
}

template <int N>
constexpr Matrix<N> transpose(const Matrix<N>& a) {
  Matrix<N> r;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) r.m[i][j] = a.m[j][i];
  return r;
}

// The matrix with one row and one column removed.
template <int N>
constexpr Matrix<N - 1> submatrix(const Matrix<N>& a, int row, int col) {
  Matrix<N - 1> r;
  for (int i = 0, ri = 0; i < N; ++i) {
    if (i == row) continue;
    for (int j = 0, rj = 0; j < N; ++j) {
      if (j == col) continue;
      r.m[ri][rj++] = a.m[i][j];
    }
    ++ri;
  }
  return r;
}

template <int N>
constexpr double determinant(const Matrix<N>& a);

template <int N>
constexpr double minor(const Matrix<N>& a, int row, int col) {
  return determinant(submatrix(a, row, col));
}

template <int N>
constexpr double cofactor(const Matrix<N>& a, int row, int col) {
  const double mi = minor(a, row, col);
  return ((row + col) % 2 == 0) ? mi : -mi;
}

template <int N>
constexpr double determinant(const Matrix<N>& a) {
  if constexpr (N == 2) {
    return a.m[0][0] * a.m[1][1] - a.m[0][1] * a.m[1][0];
  } else {
    double d = 0;
    for (int j = 0; j < N; ++j) d += a.m[0][j] * cofactor(a, 0, j);
    return d;
  }
}

template <int N>
constexpr bool is_invertible(const Matrix<N>& a) {
  return determinant(a) != 0.0;
}

// Inverse by cofactors. Precondition: is_invertible(a); callers that take
// matrices from user input check that first (see Shape::set_transform).
template <int N>
constexpr Matrix<N> inverse(const Matrix<N>& a) {
  const double det = determinant(a);
  Matrix<N> r;
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) r.m[j][i] = cofactor(a, i, j) / det;
  return r;
}

template <int N>
bool approx_equal(const Matrix<N>& a, const Matrix<N>& b, double eps = kEpsilon) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      if (!approx_equal(a.m[i][j], b.m[i][j], eps)) return false;
  return true;
}

template <int N>
constexpr bool operator==(const Matrix<N>& a, const Matrix<N>& b) {
  return a.m == b.m;
}

std::ostream& operator<<(std::ostream& os, const Matrix2& a);
std::ostream& operator<<(std::ostream& os, const Matrix3& a);
std::ostream& operator<<(std::ostream& os, const Matrix4& a);

}  // namespace toroid
