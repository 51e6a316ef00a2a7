// SPDX-License-Identifier: Apache-2.0
// Phong material (RTC chapter 6) with reflection and refraction (chapter 11),
// and emission. The path integrator maps these keys onto an energy-conserving
// model (render/path_tracer.h, path_material).
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
  // Light the surface gives off (radiance, linear RGB, non-negative): added
  // to the surface colour by the book's renderer, emitted from both sides by
  // the path integrator.
  Color emissive{0, 0, 0};
  std::shared_ptr<const Pattern> pattern;  // overrides `color` when set
};

}  // namespace toroid
