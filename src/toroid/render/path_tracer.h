// SPDX-License-Identifier: Apache-2.0
// The path integrator: an unbiased Monte Carlo estimate of the radiance
// along a camera ray, beside the book's Whitted-style renderer (color_at).
//
// - Surfaces scatter by the energy-conserving model that path_material maps
//   the book's keys onto: Lambertian diffuse, a normalized Phong lobe, a
//   mirror and a smooth dielectric (exact Fresnel), mixed by weights that
//   add up to at most 1.
// - Point lights are sampled directly (next-event estimation) only: they are
//   deltas that no scattered ray can hit.
// - Area lights are two-sided Lambertian parallelograms of radiance
//   intensity / area, sampled directly by area and hit by scattered rays;
//   the two estimates are combined by multiple importance sampling with the
//   power heuristic. Camera rays see them too.
// - Emissive surfaces (Material::emissive, both sides) count when a ray
//   hits them; they are not sampled directly, so their weight is 1.
// - Rays that hit nothing see World::environment.
// - Dielectrics: a ray enters when it meets the side the outward normal
//   points to and leaves otherwise; glass inside glass is not tracked (the
//   outside is always refractive index 1), and radiance is not scaled by
//   the index ratio squared (on a closed object entering and leaving cancel).
// - Russian roulette from the fourth vertex on: a path survives with
//   probability min(1, largest channel of its throughput), which is divided
//   out. At most `max_depth` scatterings (0: only emission and the
//   environment seen straight on; 1: direct light; ...).
// - Every random number is a hash of (pixel, sample, vertex, dimension), so
//   an image does not depend on threads or scheduling.
#pragma once

#include <cstdint>

#include "toroid/core/material.h"
#include "toroid/core/ray.h"
#include "toroid/math/color.h"
#include "toroid/render/world.h"

namespace toroid {

// The path integrator's view of a Material at one point, with `base` the
// surface colour there (the pattern's, else Material::color). Weights are
// per channel albedos (what each lobe reflects of light arriving
// perpendicularly) and add up to at most 1 in every channel:
//   diffuse  = max(base, 0) * max(m.diffuse, 0)        (Lambertian, / pi)
//   glossy   = max(m.specular, 0) in every channel     (normalized Phong,
//              f = glossy (n + 2) / (2 pi) cos^n(alpha), n = max(shininess, 0))
//   mirror   = max(m.reflective, 0), or 0 when the material is also
//              transparent: the book's Fresnel pair, which the dielectric's
//              exact Fresnel reflection stands for
//   dielectric = max(m.transparency, 0), index m.refractive_index
// mirror + dielectric is scaled down to 1 when it exceeds 1; diffuse and
// glossy share what is left, 1 - mirror - dielectric, both scaled by one
// factor (keeping the hue) when their largest channel sum exceeds it.
// `ambient` is ignored.
struct PathMaterial {
  Color emission;
  Color diffuse;
  Color glossy;
  double exponent = 0;
  double mirror = 0;
  double dielectric = 0;
  double ior = 1;
};

PathMaterial path_material(const Material& m, const Color& base);

// The key of pixel (x, y)'s sample `s`: every random number of its path is
// a hash of this key, the vertex and the dimension.
std::uint64_t path_seed(int x, int y, int s);

// One path's estimate of the radiance arriving along `ray` (towards its
// origin). Adds one to rays_traced_on_this_thread() per ray it traces
// (path segments and shadow rays). Precondition: max_depth >= 0.
Color trace_path(const World& world, const Ray& ray, int max_depth, std::uint64_t seed);

}  // namespace toroid
