// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/ray_line.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace toroid {
namespace {

TEST(RayLine, ParsesSixNumbers) {
  RayLine r{};
  std::string err;
  ASSERT_TRUE(parse_ray_line("  -5 0 0.5\t1 +2 -3e-2 ", r, err)) << err;
  EXPECT_EQ(r.origin[0], -5);
  EXPECT_EQ(r.origin[2], 0.5);
  EXPECT_EQ(r.direction[1], 2);
  EXPECT_EQ(r.direction[2], -3e-2);
}

TEST(RayLine, RejectsShortLines) {
  RayLine r{};
  std::string err;
  EXPECT_FALSE(parse_ray_line("1 2 3 4 5", r, err));
  EXPECT_EQ(err, "expected 6 numbers (ox oy oz dx dy dz), found 5");
  EXPECT_FALSE(parse_ray_line("", r, err));
}

TEST(RayLine, RejectsExtraNumbers) {
  RayLine r{};
  std::string err;
  EXPECT_FALSE(parse_ray_line("1 2 3 4 5 6 7", r, err));
  EXPECT_NE(err.find("found more"), std::string::npos);
}

TEST(RayLine, RejectsNonNumbersAndNonFinite) {
  RayLine r{};
  std::string err;
  EXPECT_FALSE(parse_ray_line("1 2 x 4 5 6", r, err));
  EXPECT_EQ(err, "not a number: 'x'");
  EXPECT_FALSE(parse_ray_line("1 2 3 4 5 6abc", r, err));
  EXPECT_FALSE(parse_ray_line("1 2 nan 4 5 6", r, err));
  EXPECT_EQ(err, "not a finite number: 'nan'");
  EXPECT_FALSE(parse_ray_line("1 2 inf 4 5 6", r, err));
  EXPECT_FALSE(parse_ray_line("1 2 1e999 4 5 6", r, err));
  EXPECT_EQ(err, "number out of range: '1e999'");
}

TEST(RayLine, RejectsZeroDirection) {
  RayLine r{};
  std::string err;
  EXPECT_FALSE(parse_ray_line("1 2 3 0 0 0", r, err));
  EXPECT_EQ(err, "the direction is the zero vector");
}

TEST(RayLine, RootsRoundTrip) {
  const double t[2] = {0.1, 1.0 / 3.0};
  const std::string s = format_roots(t, 2);
  char* end = nullptr;
  EXPECT_EQ(std::strtol(s.c_str(), &end, 10), 2);
  const double a = std::strtod(end, &end);
  const double b = std::strtod(end, &end);
  EXPECT_EQ(a, t[0]);
  EXPECT_EQ(b, t[1]);
  EXPECT_EQ(format_roots(t, 0), "0");
}

}  // namespace
}  // namespace toroid
