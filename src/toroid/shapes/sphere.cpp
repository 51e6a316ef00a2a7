// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/sphere.h"

#include <cmath>
#include <utility>

namespace toroid {

int Sphere::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  const Tuple sphere_to_ray = ray.origin - point(0, 0, 0);
  const double a = dot(ray.direction, ray.direction);
  const double b = 2 * dot(ray.direction, sphere_to_ray);
  const double c = dot(sphere_to_ray, sphere_to_ray) - 1;
  const double discriminant = b * b - 4 * a * c;
  if (discriminant < 0) return 0;
  // Numerically stable form: no cancellation between -b and sqrt(disc).
  const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
  double t0 = q / a;
  double t1 = q != 0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  hits[0] = {t0, this};
  hits[1] = {t1, this};
  return 2;
}

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
