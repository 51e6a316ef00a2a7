// SPDX-License-Identifier: Apache-2.0
#include "toroid/math/tuple.h"

#include <ostream>

#include "toroid/math/color.h"

namespace toroid {

std::ostream& operator<<(std::ostream& os, const Tuple& t) {
  return os << "tuple(" << t.x << ", " << t.y << ", " << t.z << ", " << t.w << ")";
}

std::ostream& operator<<(std::ostream& os, const Color& c) {
  return os << "color(" << c.r << ", " << c.g << ", " << c.b << ")";
}

}  // namespace toroid
