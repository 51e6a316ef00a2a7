// SPDX-License-Identifier: Apache-2.0
// The C API's handling of NULL pointers and empty batches (torus_c.h); its
// answers from C are tested by tests/c_api/c_api_test.c.
#include "toroid/torus_c.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

TEST(TorusCApi, NullPointersGiveMinusOneAndWriteNothing) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0};
  double t[4] = {7, 7, 7, 7};
  EXPECT_EQ(toroid_torus_intersect(1, 0.25, nullptr, d, t), -1);
  EXPECT_EQ(toroid_torus_intersect(1, 0.25, o, nullptr, t), -1);
  EXPECT_EQ(toroid_torus_intersect(1, 0.25, o, d, nullptr), -1);
  EXPECT_EQ(toroid_torus_nearest(1, 0.25, nullptr, d, 0, 10, t), -1);
  EXPECT_EQ(toroid_torus_nearest(1, 0.25, o, nullptr, 0, 10, t), -1);
  EXPECT_EQ(toroid_torus_nearest(1, 0.25, o, d, 0, 10, nullptr), -1);
  EXPECT_EQ(t[0], 7);
  double n[3] = {7, 7, 7};
  toroid_torus_normal(1, 0.25, nullptr, n);
  EXPECT_TRUE(std::isnan(n[0]) && std::isnan(n[1]) && std::isnan(n[2]));
  toroid_torus_normal(1, 0.25, o, nullptr);  // nothing to write to
}

TEST(TorusCApi, BatchWithANullArrayMarksEveryRowInvalid) {
  const double o[6] = {-5, 0, 0, -5, 0, 0}, d[6] = {1, 0, 0, 1, 0, 0};
  int counts[2] = {7, 7};
  double roots[8] = {7, 7, 7, 7, 7, 7, 7, 7};
  toroid_torus_intersect_batch(1, 0.25, 2, nullptr, d, counts, roots);
  EXPECT_EQ(counts[0], -1);
  EXPECT_EQ(counts[1], -1);
  for (const double t : roots) EXPECT_TRUE(std::isnan(t));
  counts[0] = counts[1] = 7;
  toroid_torus_intersect_batch(1, 0.25, 2, o, d, counts, nullptr);
  EXPECT_EQ(counts[0], -1);
  EXPECT_EQ(counts[1], -1);
  toroid_torus_intersect_batch(1, 0.25, 2, o, nullptr, nullptr, roots);
  toroid_torus_intersect_batch(1, 0.25, 0, nullptr, nullptr, nullptr, nullptr);
  toroid_torus_intersect_batch(1, 0.25, 2, o, d, counts, roots);
  EXPECT_EQ(counts[0], 4);
  EXPECT_EQ(roots[7], 6.25);
}

}  // namespace
