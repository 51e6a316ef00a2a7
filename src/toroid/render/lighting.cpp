#include "toroid/render/lighting.h"

#include <cmath>

#include "toroid/render/pattern.h"

namespace toroid {

Color lighting(const Material& m, const Shape& object, const PointLight& light, const Tuple& point,
               const Tuple& eyev, const Tuple& normalv, double light_intensity) {
  const Color surface = m.pattern ? m.pattern->pattern_at_shape(object, point) : m.color;
  const Color effective_color = surface * light.intensity;
  const Color ambient = effective_color * m.ambient;
  if (light_intensity <= 0) return ambient;

  const Tuple lightv = normalize(light.position - point);
  const double light_dot_normal = dot(lightv, normalv);
  // Light on the other side of the surface: only ambient.
  if (light_dot_normal < 0) return ambient;

  const Color diffuse = effective_color * m.diffuse * light_dot_normal;
  Color specular = kBlack;
  const Tuple reflectv = reflect(-lightv, normalv);
  const double reflect_dot_eye = dot(reflectv, eyev);
  // (No pow when the material has no highlight: same result, a tenth of the time of a shaded point.)
  if (reflect_dot_eye > 0 && m.specular != 0)
    specular = light.intensity * (m.specular * std::pow(reflect_dot_eye, m.shininess));
  return ambient + (diffuse + specular) * light_intensity;
}

}  // namespace toroid
