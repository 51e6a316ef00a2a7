// The state of a hit that shading needs (RTC chapters 7, 8 and 11).
#pragma once

#include "toroid/math/tuple.h"
#include "toroid/render/intersection.h"
#include "toroid/render/ray.h"

namespace toroid {

class Shape;

// How far over_point and under_point lie from the surface, along the normal:
// enough to escape the rounding noise of the hit point ("acne"). The one place
// to change when this becomes scale-aware.
inline constexpr double kShadowBias = kEpsilon;

struct Computations {
  double t = 0;
  const Shape* object = nullptr;
  Tuple point;      // on the surface
  Tuple eyev;       // unit, towards the eye
  Tuple normalv;    // unit, facing the eye (flipped when inside)
  bool inside = false;
  Tuple over_point;   // point + normalv * kShadowBias: start of shadow and reflection rays
  Tuple under_point;  // point - normalv * kShadowBias: start of refraction rays
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

// Schlick's approximation of the Fresnel reflectance: the fraction of light
// reflected (1 under total internal reflection).
double schlick(const Computations& comps);

}  // namespace toroid
