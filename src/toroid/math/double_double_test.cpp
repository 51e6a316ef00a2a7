// SPDX-License-Identifier: Apache-2.0
#include "toroid/math/double_double.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

namespace toroid {
namespace {

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// product_error is a * b - fl(a * b) exactly, as one fused multiply-add
// gives it, whichever way the target computes it (Dekker's split on x86-64
// without FMA): bit for bit, signed zeros included.
TEST(DoubleDouble, ProductErrorIsTheFusedMultiplyAdd) {
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> moderate(-1e3, 1e3);
  int compared = 0;
  for (int i = 0; i < 300000; ++i) {
    double a, b;
    switch (i % 3) {
      case 0:  // any finite doubles: every exponent, subnormals, overflow
        a = std::bit_cast<double>(rng());
        b = std::bit_cast<double>(rng());
        break;
      case 1:  // the solver's range
        a = moderate(rng);
        b = moderate(rng);
        break;
      default:  // exact products, whose error is zero
        a = static_cast<double>(static_cast<int>(rng() % 2001) - 1000) * 0.5;
        b = static_cast<double>(static_cast<int>(rng() % 2001) - 1000) * 0.25;
    }
    const double p = a * b;
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(p)) continue;
    ++compared;
    ASSERT_EQ(bits(product_error(a, b, p)), bits(std::fma(a, b, -p))) << std::hexfloat << a << " * " << b;
  }
  EXPECT_GT(compared, 250000);
}

TEST(DoubleDouble, TwoProdAndAddScaledAreExact) {
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the last term is the product's error.
  const DoubleDouble p = two_prod(1 + 0x1p-30, 1 + 0x1p-30);
  EXPECT_EQ(p.hi, 1 + 0x1p-29);
  EXPECT_EQ(p.lo, 0x1p-60);
  // The double nearest 1/3 is 1/3 - 2^-54/3, so 1e12 + 3 times it is
  // 1e12 + 1 - 2^-54 exactly: the low part keeps what a double loses.
  const DoubleDouble s = add_scaled(1e12, 3, 0x1.5555555555555p-2);
  EXPECT_EQ(s.hi, 1e12 + 1);
  EXPECT_EQ(s.lo, -0x1p-54);
}

}  // namespace
}  // namespace toroid
