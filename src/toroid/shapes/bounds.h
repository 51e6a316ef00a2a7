// Axis-aligned bounding boxes (RTC bonus chapter "Bounding boxes and hierarchies").
#pragma once

#include <limits>

#include "toroid/math/matrix.h"
#include "toroid/render/ray.h"

namespace toroid {

struct BoundingBox {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  Tuple min = point(kInf, kInf, kInf);
  Tuple max = point(-kInf, -kInf, -kInf);
};

}  // namespace toroid
