// SPDX-License-Identifier: Apache-2.0
// gtest assertion for the RTC book's "=" on materials: every field equal
// (colours within kEpsilon, the same pattern object), printing the first
// difference on failure.
#pragma once

#include <gtest/gtest.h>

#include "toroid/core/material.h"

namespace toroid::testing {

inline ::testing::AssertionResult MaterialsEqual(const char* a_expr, const char* b_expr, const Material& a,
                                                 const Material& b) {
  const auto fail = [&](const char* field) {
    return ::testing::AssertionFailure() << a_expr << " and " << b_expr << " differ in " << field;
  };
  if (!approx_equal(a.color, b.color)) return fail("color");
  if (!approx_equal(a.ambient, b.ambient)) return fail("ambient");
  if (!approx_equal(a.diffuse, b.diffuse)) return fail("diffuse");
  if (!approx_equal(a.specular, b.specular)) return fail("specular");
  if (!approx_equal(a.shininess, b.shininess)) return fail("shininess");
  if (!approx_equal(a.reflective, b.reflective)) return fail("reflective");
  if (!approx_equal(a.transparency, b.transparency)) return fail("transparency");
  if (!approx_equal(a.refractive_index, b.refractive_index)) return fail("refractive_index");
  if (!approx_equal(a.emissive, b.emissive)) return fail("emissive");
  if (a.pattern != b.pattern) return fail("pattern");
  return ::testing::AssertionSuccess();
}

}  // namespace toroid::testing

#define EXPECT_MATERIAL_EQ(a, b) EXPECT_PRED_FORMAT2(::toroid::testing::MaterialsEqual, a, b)
