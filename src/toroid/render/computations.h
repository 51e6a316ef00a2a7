// SPDX-License-Identifier: Apache-2.0
// The state of a hit that shading needs (RTC chapters 7, 8 and 11).
#pragma once

#include <cstddef>
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

// Whether a ray that crosses `shape` can carry its containers on (below):
// the shape bounds a solid (Shape::closed_surface) and is no part of a CSG
// shape, whose crossings the book's algorithm counts by the primitive hit.
bool carried_in_containers(const Shape& shape);

// The objects a ray is inside where it starts, in the order it entered them:
// the containers list of the book's algorithm at the ray's origin. A ray
// spawned at a hit starts inside what its parent was inside before the hit
// (reflection), or that with the hit's object crossed (refraction), so it
// can carry the list instead of every intersection along its line. For
// shapes that bound a solid, the list the book's algorithm builds from the
// new ray's line holds the same objects: whether the origin is inside one
// is the parity of its crossings behind the origin. The list is unknown
// once it would hold another shape (a plane, a triangle, a CSG's
// primitive: whether the book's list holds one depends on the line) or
// more than kCapacity, and for a ray whose origin nobody worked out (a
// camera ray).
class Containers {
 public:
  static constexpr std::size_t kCapacity = 8;

  // Inside nothing.
  Containers() = default;
  static Containers unknown() {
    Containers c;
    c.known_ = false;
    return c;
  }

  bool known() const { return known_; }
  std::size_t size() const { return count_; }
  const Shape* operator[](std::size_t i) const { return objects_[i]; }

  // The containers algorithm's step at an intersection with `object`: leaves
  // it if inside it (the others keep their order), else enters it (the list
  // turns unknown if full). Precondition: carried_in_containers(*object).
  void cross(const Shape* object);
  // The refractive index of the innermost object, 1 when inside none.
  // Precondition: known().
  double innermost_index() const;
  // The same after cross(object), which need not fit.
  double innermost_index_after(const Shape* object) const;

 private:
  const Shape* objects_[kCapacity];
  std::size_t count_ = 0;
  bool known_ = true;
};

// `xs` holds every intersection of `ray` with the world, sorted by t (n1 and
// n2 come from the objects that contain the hit), and `hit` is one of them.
// Precondition: hit.object is not null.
Computations prepare_computations(const Intersection& hit, const Ray& ray, const Intersections& xs);
// The same, also setting `before` to the objects the ray is inside just
// before the hit (unknown if more than Containers::kCapacity).
Computations prepare_computations(const Intersection& hit, const Ray& ray, const Intersections& xs, Containers& before);
// n1 and n2 of a hit on a ray that starts inside `before` (known), where
// `hit` is the ray's first intersection at t >= 0.
Computations prepare_computations(const Intersection& hit, const Ray& ray, const Containers& before);
// As if xs held `hit` alone.
Computations prepare_computations(const Intersection& hit, const Ray& ray);

// The distance over_point and under_point lie from the hit `ray` makes at
// `hit` (world units). Precondition: hit.object is not null.
double surface_bias(const Intersection& hit, const Ray& ray);

// Schlick's approximation of the Fresnel reflectance: the fraction of light
// reflected (1 under total internal reflection).
double schlick(const Computations& comps);

}  // namespace toroid
