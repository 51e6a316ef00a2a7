// SPDX-License-Identifier: Apache-2.0
#include "toroid/math/affine.h"

#include <gtest/gtest.h>

#include "toroid/math/transform.h"

namespace toroid {
namespace {

Matrix4 some_affine() {
  return translation(1.5, -2.25, 3) * rotation_y(0.7) * rotation_x(-1.1) * scaling(2, 0.5, 3) *
         shearing(0.1, 0.2, 0.3, 0.4, 0.5, 0.6);
}

TEST(Affine, MultipliesPointsAndVectorsBitForBitLikeMatrix4) {
  const Matrix4 m = some_affine();
  const Affine a = Affine::from(m);
  for (const Tuple& t : {point(0.3, -7, 11), vector(-0.3, 5e-8, 2), point(0, 0, 0), vector(1e300, -1e-300, 3)}) {
    const Tuple expected = m * t;
    const Tuple got = a * t;
    EXPECT_EQ(got.x, expected.x);
    EXPECT_EQ(got.y, expected.y);
    EXPECT_EQ(got.z, expected.z);
    EXPECT_EQ(got.w, t.w);
  }
}

TEST(Affine, RoundTripsThroughMatrix4) {
  const Matrix4 m = some_affine();
  EXPECT_EQ(Affine::from(m).to_matrix(), m);
  EXPECT_EQ(Affine{}.to_matrix(), Matrix4::identity());
}

TEST(Affine, TransposeTimesMatchesTheTransposedLinearPart) {
  const Matrix4 m = some_affine();
  const Tuple n = vector(0.25, -1.5, 2);
  const Tuple expected = transpose(m) * n;
  const Tuple got = Affine::from(m).transpose_times(n);
  EXPECT_DOUBLE_EQ(got.x, expected.x);
  EXPECT_DOUBLE_EQ(got.y, expected.y);
  EXPECT_DOUBLE_EQ(got.z, expected.z);
  EXPECT_EQ(got.w, 0.0);
}

}  // namespace
}  // namespace toroid
