// A point light source (RTC chapter 6).
#pragma once

#include "toroid/math/color.h"
#include "toroid/math/tuple.h"

namespace toroid {

struct PointLight {
  Tuple position = point(0, 0, 0);
  Color intensity{1, 1, 1};
};

}  // namespace toroid
