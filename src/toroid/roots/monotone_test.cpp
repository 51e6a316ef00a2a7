// SPDX-License-Identifier: Apache-2.0
#include "toroid/roots/monotone.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

namespace toroid {
namespace {

// x^3 - 5 on [1, 3] from 2.9: Newton comes down on the root from above
// (the function is convex) and reaches it to the last bit in a few steps;
// there its step rounds to nothing, and the search must stop rather than
// bisect back out towards the far end (with tol = 0 nothing else stops it;
// doing so took 38 evaluations).
TEST(SolveMonotone, StopsWhereNewtonsStepLeavesXUnchanged) {
  int calls = 0;
  const auto f = [&](double x) {
    ++calls;
    return std::pair<double, double>{x * x * x - 5, 3 * x * x};
  };
  const double root = solve_monotone(f, 1.0, 3.0, true, 2.9, 0.0);
  EXPECT_LE(std::abs(root - std::cbrt(5.0)), 0x1p-51);
  EXPECT_LE(calls, 10);
}

TEST(SolveMonotone, BisectsWhereNewtonLeavesTheBracket) {
  // A flat start: Newton's first step jumps far outside [0, 3].
  const auto f = [](double x) { return std::pair<double, double>{std::atan(x - 2), 1 / (1 + (x - 2) * (x - 2))}; };
  const double root = solve_monotone(f, 0.0, 3.0, true, 0.01, 1e-15);
  EXPECT_NEAR(root, 2.0, 1e-14);
}

}  // namespace
}  // namespace toroid
