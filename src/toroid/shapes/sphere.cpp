// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/sphere.h"

namespace toroid {

Tuple Sphere::local_normal_at(const Tuple& p, const Intersection&) const { return vector(p.x, p.y, p.z); }

std::shared_ptr<Sphere> glass_sphere() {
  auto s = std::make_shared<Sphere>();
  Material glass;
  glass.transparency = 1.0;
  glass.refractive_index = 1.5;
  s->set_material(glass);
  return s;
}

}  // namespace toroid
