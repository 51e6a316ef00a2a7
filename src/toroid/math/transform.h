// SPDX-License-Identifier: Apache-2.0
// Affine transforms as 4x4 matrices (RTC chapter 4 and 7).
#pragma once

#include "toroid/math/matrix.h"

namespace toroid {

Matrix4 translation(double x, double y, double z);
Matrix4 scaling(double x, double y, double z);
Matrix4 rotation_x(double radians);
Matrix4 rotation_y(double radians);
Matrix4 rotation_z(double radians);
Matrix4 shearing(double xy, double xz, double yx, double yz, double zx, double zy);
// World-to-camera transform for an eye at `from` looking at `to`.
Matrix4 view_transform(const Tuple& from, const Tuple& to, const Tuple& up);

}  // namespace toroid
