// SPDX-License-Identifier: Apache-2.0
// Phong material (RTC chapter 6) with reflection and refraction (chapter 11).
#pragma once

#include <memory>

#include "toroid/math/color.h"

namespace toroid {

class Pattern;

struct Material {
  Color color{1, 1, 1};
  double ambient = 0.1;
  double diffuse = 0.9;
  double specular = 0.9;
  double shininess = 200.0;
  double reflective = 0.0;
  double transparency = 0.0;
  double refractive_index = 1.0;
  std::shared_ptr<const Pattern> pattern;  // overrides `color` when set
};

}  // namespace toroid
