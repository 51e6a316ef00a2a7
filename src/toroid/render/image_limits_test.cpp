// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/image_limits.h"

#include <gtest/gtest.h>

namespace toroid {
namespace {

TEST(ImageLimits, AcceptsSizesWithinTheLimits) {
  EXPECT_EQ(image_size_error(1, 1), "");
  EXPECT_EQ(image_size_error(16384, 4096), "");
  EXPECT_EQ(image_size_error(8192, 8192), "");
}

TEST(ImageLimits, NamesTheSideOutOfRange) {
  EXPECT_EQ(image_size_error(0, 10), "width must be in 1..16384, got 0");
  EXPECT_EQ(image_size_error(10, 16385), "height must be in 1..16384, got 16385");
  EXPECT_EQ(image_size_error(-3, -3), "width must be in 1..16384, got -3");
}

TEST(ImageLimits, RejectsTooManyPixels) {
  EXPECT_EQ(image_size_error(16384, 16384),
            "16384x16384 is 268435456 pixels, more than the limit of 67108864 (8192x8192)");
  EXPECT_EQ(image_size_error(8193, 8192).empty(), false);
}

}  // namespace
}  // namespace toroid
