// SPDX-License-Identifier: Apache-2.0
#include "toroid/math/transform.h"

#include <cmath>

namespace toroid {

Matrix4 translation(double x, double y, double z) {
  Matrix4 r = Matrix4::identity();
  r(0, 3) = x;
  r(1, 3) = y;
  r(2, 3) = z;
  return r;
}

Matrix4 scaling(double x, double y, double z) {
  Matrix4 r = Matrix4::identity();
  r(0, 0) = x;
  r(1, 1) = y;
  r(2, 2) = z;
  return r;
}

Matrix4 rotation_x(double a) {
  Matrix4 r = Matrix4::identity();
  r(1, 1) = std::cos(a);
  r(1, 2) = -std::sin(a);
  r(2, 1) = std::sin(a);
  r(2, 2) = std::cos(a);
  return r;
}

Matrix4 rotation_y(double a) {
  Matrix4 r = Matrix4::identity();
  r(0, 0) = std::cos(a);
  r(0, 2) = std::sin(a);
  r(2, 0) = -std::sin(a);
  r(2, 2) = std::cos(a);
  return r;
}

Matrix4 rotation_z(double a) {
  Matrix4 r = Matrix4::identity();
  r(0, 0) = std::cos(a);
  r(0, 1) = -std::sin(a);
  r(1, 0) = std::sin(a);
  r(1, 1) = std::cos(a);
  return r;
}

Matrix4 shearing(double xy, double xz, double yx, double yz, double zx, double zy) {
  Matrix4 r = Matrix4::identity();
  r(0, 1) = xy;
  r(0, 2) = xz;
  r(1, 0) = yx;
  r(1, 2) = yz;
  r(2, 0) = zx;
  r(2, 1) = zy;
  return r;
}

Matrix4 view_transform(const Tuple& from, const Tuple& to, const Tuple& up) {
  const Tuple forward = normalize(to - from);
  const Tuple left = cross(forward, normalize(up));
  const Tuple true_up = cross(left, forward);
  Matrix4 orientation = Matrix4::identity();
  orientation.m[0] = {left.x, left.y, left.z, 0};
  orientation.m[1] = {true_up.x, true_up.y, true_up.z, 0};
  orientation.m[2] = {-forward.x, -forward.y, -forward.z, 0};
  return orientation * translation(-from.x, -from.y, -from.z);
}

}  // namespace toroid
