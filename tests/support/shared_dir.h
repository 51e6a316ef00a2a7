// SPDX-License-Identifier: Apache-2.0
// Tests that read the RTC reference material in TOROID_SHARED_DIR skip, with
// the reason, when a checkout has none beside it (CI always has it).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>

#define TOROID_REQUIRE_SHARED_DIR()                                            \
  do {                                                                         \
    if (!std::filesystem::exists(TOROID_SHARED_DIR))                           \
      GTEST_SKIP() << "RTC reference material not found at " TOROID_SHARED_DIR \
                      " (configure with -DTOROID_SHARED_DIR=...)";             \
  } while (0)
