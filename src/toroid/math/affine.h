// SPDX-License-Identifier: Apache-2.0
// An affine 4x4 matrix stored as its top three rows (the bottom row is
// always 0 0 0 1): 96 bytes instead of 128, and a multiply that skips the
// row and the terms that are known to be 0 or 1. Products are summed in the
// same order as Matrix4 * Tuple, so results are bit-identical to it.
#pragma once

#include <cmath>

#include "toroid/math/matrix.h"

namespace toroid {

struct Affine {
  double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};

  // Precondition: the bottom row of a is 0 0 0 1 (every RTC transform is).
  static Affine from(const Matrix4& a) {
    Affine r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) r.m[i][j] = a.m[i][j];
    return r;
  }

  Matrix4 to_matrix() const {
    Matrix4 r = Matrix4::identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) r.m[i][j] = m[i][j];
    return r;
  }

  // Points (w = 1) get the translation, vectors (w = 0) do not; w is kept.
  // Always inlined: every ray goes through it into object space, and
  // link-time optimisation otherwise calls it out of line from the largest
  // callers.
  [[gnu::always_inline]] constexpr Tuple operator*(const Tuple& t) const {
    return {row(0, t), row(1, t), row(2, t), t.w};
  }

  // (*this) * t for a t that is known to be a point (w = 1) or a vector
  // (w = 0), without the product by w: for a point the same bits (m * 1 is
  // m), for a vector the same but for the sign of a zero sum (no + 0). Every
  // ray's origin and direction go through these into object space.
  [[gnu::always_inline]] constexpr Tuple times_point(const Tuple& t) const {
    return {m[0][0] * t.x + m[0][1] * t.y + m[0][2] * t.z + m[0][3],
            m[1][0] * t.x + m[1][1] * t.y + m[1][2] * t.z + m[1][3],
            m[2][0] * t.x + m[2][1] * t.y + m[2][2] * t.z + m[2][3], t.w};
  }
  [[gnu::always_inline]] constexpr Tuple times_vector(const Tuple& t) const {
    return {m[0][0] * t.x + m[0][1] * t.y + m[0][2] * t.z, m[1][0] * t.x + m[1][1] * t.y + m[1][2] * t.z,
            m[2][0] * t.x + m[2][1] * t.y + m[2][2] * t.z, t.w};
  }

  // One component of (*this) * t, for callers that need only one (a
  // plane's height).
  constexpr double row(int i, const Tuple& t) const {
    return m[i][0] * t.x + m[i][1] * t.y + m[i][2] * t.z + m[i][3] * t.w;
  }

  // The transpose of the linear (3x3) part times the xyz of v, as a vector:
  // how normals go from object to world space when this is the inverse
  // transform.
  constexpr Tuple transpose_times(const Tuple& v) const {
    return vector(m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
                  m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z);
  }
};

// The Frobenius norm of the linear (top-left 3x3) part of an Affine's or a
// Matrix4's rows: a bound on the largest stretch of the map (exact for a
// rotation times a uniform scale, up to the factor sqrt(3)).
template <typename Rows>
double linear_frobenius_norm(const Rows& m) {
  double norm2 = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) norm2 += m[i][j] * m[i][j];
  return std::sqrt(norm2);
}

}  // namespace toroid
