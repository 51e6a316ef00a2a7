// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/lighting.h"

#include <cmath>
#include <cstdint>

#include "toroid/render/pattern.h"

namespace toroid {

namespace {

// Diffuse plus specular light from a light of `intensity` in the unit
// direction `lightv` (from the point towards the light).
Color diffuse_specular(const Material& m, const Color& effective, const Color& intensity, const Tuple& lightv,
                       const Tuple& eyev, const Tuple& normalv) {
  const double light_dot_normal = dot(lightv, normalv);
  // Light on the other side of the surface: none.
  if (light_dot_normal < 0) return kBlack;
  const Color diffuse = effective * m.diffuse * light_dot_normal;
  const Tuple reflectv = reflect(-lightv, normalv);
  const double reflect_dot_eye = dot(reflectv, eyev);
  // No power when the material has no highlight: the same result, without
  // its cost.
  if (reflect_dot_eye <= 0 || m.specular == 0) return diffuse;
  return diffuse + intensity * (m.specular * specular_power(reflect_dot_eye, m.shininess));
}

}  // namespace

double specular_power(double x, double shininess) {
  if (!(shininess >= 1 && shininess <= 1024) || shininess != std::floor(shininess)) return std::pow(x, shininess);
  auto n = static_cast<unsigned>(shininess);
  double result = 1, square = x;
  for (;;) {
    if (n & 1) result *= square;
    n >>= 1;
    if (n == 0) return result;
    square *= square;
  }
}

Color surface_color(const Material& m, const Shape& object, const Tuple& point) {
  return m.pattern ? m.pattern->pattern_at_shape(object, point) : m.color;
}

Color lighting(const Material& m, const Shape& object, const PointLight& light, const Tuple& point, const Tuple& eyev,
               const Tuple& normalv, double light_intensity) {
  return lighting_towards(m, surface_color(m, object, point), light, normalize(light.position - point), eyev, normalv,
                          light_intensity);
}

Color lighting_towards(const Material& m, const Color& surface, const PointLight& light, const Tuple& lightv,
                       const Tuple& eyev, const Tuple& normalv, double light_intensity) {
  const Color effective = surface * light.intensity;
  const Color ambient = effective * m.ambient;
  if (light_intensity <= 0) return ambient;
  return ambient + diffuse_specular(m, effective, light.intensity, lightv, eyev, normalv) * light_intensity;
}

Color lighting(const Material& m, const Color& surface, const AreaLight& light, const Tuple& point, const Tuple& eyev,
               const Tuple& normalv, double light_intensity) {
  const Color effective = surface * light.intensity;
  const Color ambient = effective * m.ambient;
  if (light_intensity <= 0) return ambient;
  Color sum = kBlack;
  const std::uint64_t key = light.jitter_key(point);
  for (int v = 0; v < light.vsteps; ++v)
    for (int u = 0; u < light.usteps; ++u)
      sum += diffuse_specular(m, effective, light.intensity, normalize(light.sample(key, u, v) - point), eyev, normalv);
  return ambient + sum * (light_intensity / light.samples);
}

}  // namespace toroid
