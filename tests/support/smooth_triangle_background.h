// SPDX-License-Identifier: Apache-2.0
// smooth-triangles.feature's Background, shared by the shape's tests and
// the shading test that prepares its normal.
#pragma once

#include <gtest/gtest.h>

#include "toroid/shapes/smooth_triangle.h"

namespace toroid {

// The feature's Background.
class SmoothTriangles : public ::testing::Test {
 protected:
  const Tuple p1 = point(0, 1, 0);
  const Tuple p2 = point(-1, 0, 0);
  const Tuple p3 = point(1, 0, 0);
  const Tuple n1 = vector(0, 1, 0);
  const Tuple n2 = vector(-1, 0, 0);
  const Tuple n3 = vector(1, 0, 0);
  const SmoothTriangle tri{p1, p2, p3, n1, n2, n3};
};

}  // namespace toroid
