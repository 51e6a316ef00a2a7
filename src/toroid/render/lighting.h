// SPDX-License-Identifier: Apache-2.0
// Phong reflection (RTC chapters 6, 8 and 10, and the bonus chapter's area
// lights).
#pragma once

#include "toroid/core/material.h"
#include "toroid/math/color.h"
#include "toroid/math/tuple.h"
#include "toroid/render/light.h"

namespace toroid {

class Shape;

// The colour of `point` on `object` lit by `light`, seen along `eyev` (unit,
// towards the eye) with surface normal `normalv` (unit). The surface colour
// is the material's pattern at the point when it has one, else its colour.
// `light_intensity` in [0, 1] is the fraction of the light that reaches the
// point (0: in shadow, ambient only; between: a partly covered area light).
Color lighting(const Material& material, const Shape& object, const PointLight& light, const Tuple& point,
               const Tuple& eyev, const Tuple& normalv, double light_intensity);

// x^shininess, the highlight's power, for x in [0, 1]. A whole exponent from
// 1 to 1024 (the book's 200; most scenes' shininess) by squaring: at most
// 2 log2(n) products, each rounded, so within about n ulps of std::pow's
// value (the highlight's last bits, not its 8-bit code) at a third of its
// cost; any other exponent by std::pow.
double specular_power(double x, double shininess);

// The material's colour at `point` on `object`: its pattern there when it has
// one, else its colour. The same for every light, so shade_hit finds it once.
Color surface_color(const Material& material, const Shape& object, const Tuple& point);

// lighting, given the point's surface_color and lightv = normalize(light.position
// - point), which shade_hit has computed already (the colour once for all its
// lights; lightv to skip the shadow ray of a light behind the surface).
Color lighting_towards(const Material& material, const Color& surface, const PointLight& light, const Tuple& lightv,
                       const Tuple& eyev, const Tuple& normalv, double light_intensity);

// The book's form: in_shadow == true means no light reaches the point.
inline Color lighting(const Material& material, const Shape& object, const PointLight& light, const Tuple& point,
                      const Tuple& eyev, const Tuple& normalv, bool in_shadow = false) {
  return lighting(material, object, light, point, eyev, normalv, in_shadow ? 0.0 : 1.0);
}

// An area light: ambient once, plus the diffuse and specular light of every
// sample (light.sample(light.jitter_key(point), u, v)) averaged, times
// light_intensity; `surface` is the point's surface_color.
Color lighting(const Material& material, const Color& surface, const AreaLight& light, const Tuple& point,
               const Tuple& eyev, const Tuple& normalv, double light_intensity);

inline Color lighting(const Material& material, const Shape& object, const AreaLight& light, const Tuple& point,
                      const Tuple& eyev, const Tuple& normalv, double light_intensity) {
  return lighting(material, surface_color(material, object, point), light, point, eyev, normalv, light_intensity);
}

}  // namespace toroid
