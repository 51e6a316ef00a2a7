// SPDX-License-Identifier: Apache-2.0
#include "toroid/math/matrix.h"

#include <ostream>

namespace toroid {
namespace {
template <int N>
std::ostream& print(std::ostream& os, const Matrix<N>& a) {
  os << "[";
  for (int i = 0; i < N; ++i) {
    os << (i ? "; " : "");
    for (int j = 0; j < N; ++j) os << (j ? " " : "") << a.m[i][j];
  }
  return os << "]";
}
}  // namespace

std::ostream& operator<<(std::ostream& os, const Matrix2& a) { return print(os, a); }
std::ostream& operator<<(std::ostream& os, const Matrix3& a) { return print(os, a); }
std::ostream& operator<<(std::ostream& os, const Matrix4& a) { return print(os, a); }

}  // namespace toroid
