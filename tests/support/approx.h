// SPDX-License-Identifier: Apache-2.0
// gtest assertions for the RTC book's "=" on tuples, colours and matrices,
// which compares each component within kEpsilon and prints both on failure.
#pragma once

#include <gtest/gtest.h>

#include <sstream>

#include "toroid/math/color.h"
#include "toroid/math/matrix.h"
#include "toroid/math/tuple.h"

namespace toroid::testing {

template <typename T>
::testing::AssertionResult ApproxEqual(const char* a_expr, const char* b_expr, const T& a, const T& b) {
  if (approx_equal(a, b)) return ::testing::AssertionSuccess();
  std::ostringstream os;
  os << a_expr << " = " << a << "\n  expected " << b_expr << " = " << b;
  return ::testing::AssertionFailure() << os.str();
}

}  // namespace toroid::testing

#define EXPECT_APPROX(a, b) EXPECT_PRED_FORMAT2(::toroid::testing::ApproxEqual, a, b)
#define ASSERT_APPROX(a, b) ASSERT_PRED_FORMAT2(::toroid::testing::ApproxEqual, a, b)
