// SPDX-License-Identifier: Apache-2.0
// The state of a hit that shading needs (RTC chapters 7, 8 and 11).
#pragma once

#include <limits>

#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"
#include "toroid/math/tuple.h"

namespace toroid {

class Shape;

// How far over_point and under_point lie from the surface, along the normal
// (see surface_bias): a small fraction of the hit object's thickness, and
// never less than a safe multiple of the hit point's rounding error.
//  - kBiasPerThickness: times the object's half thickness in world units
//    (half the thinnest finite side of its object-space box, shrunk by every
//    transform down to it). A unit sphere gets 1.15e-5, about the book's
//    EPSILON; a torus R = 1e-3, r = 1e-6 gets 1e-11, far below its tube.
//  - kBiasPerMagnitude: times |origin| + t |direction| (largest components),
//    the scale of the rounding of origin + t direction; it takes over far
//    from the origin (at 1e12 the coordinates round to 1e-4) and on shapes
//    with no finite thickness (planes).
inline constexpr double kBiasPerThickness = 2e-5;
inline constexpr double kBiasPerMagnitude = 16 * std::numeric_limits<double>::epsilon();

struct Computations {
  double t = 0;
  const Shape* object = nullptr;
  Tuple point;    // on the surface
  Tuple eyev;     // unit, towards the eye
  Tuple normalv;  // unit, facing the eye (flipped when inside)
  bool inside = false;
  Tuple over_point;   // point + normalv * surface_bias: start of shadow and reflection rays
  Tuple under_point;  // point - normalv * surface_bias: start of refraction rays
  Tuple reflectv;
  double n1 = 1.0;  // refractive index of the medium the ray leaves
  double n2 = 1.0;  // refractive index of the medium the ray enters
};

// `xs` holds every intersection of `ray` with the world, sorted by t (n1 and
// n2 come from the objects that contain the hit), and `hit` is one of them.
// Precondition: hit.object is not null.
Computations prepare_computations(const Intersection& hit, const Ray& ray, const Intersections& xs);
// As if xs held `hit` alone.
Computations prepare_computations(const Intersection& hit, const Ray& ray);

// The distance over_point and under_point lie from the hit `ray` makes at
// `hit` (world units). Precondition: hit.object is not null.
double surface_bias(const Intersection& hit, const Ray& ray);

// Schlick's approximation of the Fresnel reflectance: the fraction of light
// reflected (1 under total internal reflection).
double schlick(const Computations& comps);

}  // namespace toroid
