// SPDX-License-Identifier: Apache-2.0
// sequences.feature (soft-shadows bonus chapter, community transcription).
#include "support/sequence.h"

#include <gtest/gtest.h>

namespace toroid::testing {
namespace {

TEST(Sequences, ANumberGeneratorReturnsACyclicSequenceOfNumbers) {
  Sequence gen{0.1, 0.5, 1.0};
  EXPECT_EQ(gen.next(), 0.1);
  EXPECT_EQ(gen.next(), 0.5);
  EXPECT_EQ(gen.next(), 1.0);
  EXPECT_EQ(gen.next(), 0.1);
}

}  // namespace
}  // namespace toroid::testing
