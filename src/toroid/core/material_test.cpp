// SPDX-License-Identifier: Apache-2.0
// materials.feature: the defaults (the lighting scenarios are in lighting_test.cpp).
#include "toroid/core/material.h"

#include <gtest/gtest.h>

#include "support/approx.h"

namespace toroid {
namespace {

TEST(Materials, TheDefaultMaterial) {
  const Material m;
  EXPECT_APPROX(m.color, (Color{1, 1, 1}));
  EXPECT_EQ(m.ambient, 0.1);
  EXPECT_EQ(m.diffuse, 0.9);
  EXPECT_EQ(m.specular, 0.9);
  EXPECT_EQ(m.shininess, 200.0);
}

TEST(Materials, ReflectivityForTheDefaultMaterial) {
  const Material m;
  EXPECT_EQ(m.reflective, 0.0);
}

TEST(Materials, TransparencyAndRefractiveIndexForTheDefaultMaterial) {
  const Material m;
  EXPECT_EQ(m.transparency, 0.0);
  EXPECT_EQ(m.refractive_index, 1.0);
}

}  // namespace
}  // namespace toroid
