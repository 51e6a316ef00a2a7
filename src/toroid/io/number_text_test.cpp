// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/number_text.h"

#include <gtest/gtest.h>

namespace toroid {
namespace {

TEST(NumberText, ReadsFiniteNumbers) {
  double v = 0;
  EXPECT_EQ(read_finite_double("-2.5e3", v), NumberText::Ok);
  EXPECT_EQ(v, -2500);
  EXPECT_EQ(read_finite_double("+4", v), NumberText::Ok);
  EXPECT_EQ(v, 4);
  EXPECT_EQ(read_finite_double(".5", v), NumberText::Ok);
  EXPECT_EQ(v, 0.5);
}

TEST(NumberText, SaysWhyAWordIsNotAUsableNumber) {
  double v = 0;
  EXPECT_EQ(read_finite_double("abc", v), NumberText::NotANumber);
  EXPECT_EQ(read_finite_double("1x", v), NumberText::NotANumber);
  EXPECT_EQ(read_finite_double("", v), NumberText::NotANumber);
  EXPECT_EQ(read_finite_double("+", v), NumberText::NotANumber);
  EXPECT_EQ(read_finite_double("++1", v), NumberText::NotANumber);
  EXPECT_EQ(read_finite_double("1e999", v), NumberText::OutOfRange);
  EXPECT_EQ(read_finite_double("nan", v), NumberText::NotFinite);
  EXPECT_EQ(read_finite_double("-inf", v), NumberText::NotFinite);
  EXPECT_EQ(describe(NumberText::NotANumber, "abc"), "not a number: 'abc'");
  EXPECT_EQ(describe(NumberText::OutOfRange, "1e999"), "number out of range: '1e999'");
  EXPECT_EQ(describe(NumberText::NotFinite, "nan"), "not a finite number: 'nan'");
  EXPECT_EQ(describe(NumberText::Ok, "1"), "");
}

}  // namespace
}  // namespace toroid
