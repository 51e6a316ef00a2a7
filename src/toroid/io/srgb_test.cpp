// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/srgb.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace toroid {
namespace {

// The sRGB formula written out, rounded to nearest: the table must agree
// with it everywhere, boundaries included.
int formula(double c) {
  if (!(c > 0)) return 0;
  if (c >= 1) return 255;
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(s * 255.0));
}

TEST(Srgb, EncodingAgreesWithTheFormulaEverywhere) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 1.1);
  for (int i = 0; i < 200000; ++i) {
    const double c = u(rng);
    ASSERT_EQ(linear_to_srgb8(c), formula(c)) << c;
  }
  // Next to every code boundary, on both sides.
  for (int k = 0; k < 256; ++k) {
    const double s = (k + 0.5) / 255.0;
    const double edge = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
    double c = edge;
    for (int step = 0; step < 4; ++step) c = std::nextafter(c, 0.0);
    for (int step = 0; step < 8; ++step, c = std::nextafter(c, 2.0)) ASSERT_EQ(linear_to_srgb8(c), formula(c)) << c;
  }
}

TEST(Srgb, EncodingClampsAndRejectsNaN) {
  EXPECT_EQ(linear_to_srgb8(-1.0), 0);
  EXPECT_EQ(linear_to_srgb8(0.0), 0);
  EXPECT_EQ(linear_to_srgb8(std::nan("")), 0);
  EXPECT_EQ(linear_to_srgb8(1.0), 255);
  EXPECT_EQ(linear_to_srgb8(INFINITY), 255);
}

TEST(Srgb, TheRowFormGivesEachValuesCode) {
  std::vector<double> values = {-1.0, 0.0, std::nan(""), 1.0, INFINITY, 0.0031308, 0.5, 0.99999};
  for (int i = 0; i <= 1000; ++i) values.push_back(i / 1000.0);
  std::vector<unsigned char> codes(values.size() + 1, 77);
  linear_to_srgb8(values.data(), static_cast<int>(values.size()), codes.data());
  for (std::size_t i = 0; i < values.size(); ++i) ASSERT_EQ(codes[i], linear_to_srgb8(values[i])) << values[i];
  EXPECT_EQ(codes.back(), 77);  // nothing written past n
}

}  // namespace
}  // namespace toroid
