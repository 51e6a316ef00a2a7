// SPDX-License-Identifier: Apache-2.0
// A scene: shapes and lights, and the recursive shading of rays (RTC
// chapters 7, 8 and 11).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"
#include "toroid/math/color.h"
#include "toroid/render/computations.h"
#include "toroid/render/light.h"
#include "toroid/shapes/shape_bvh.h"

namespace toroid {

class Shape;

// The radiance that arrives along a ray that hits nothing: `color` from
// every direction, or, with `zenith`, a vertical gradient: `color` at and
// below the horizon, blending linearly in the direction's y (unit) to
// `zenith` straight up.
struct Environment {
  Color color{0, 0, 0};
  std::optional<Color> zenith;

  // The radiance arriving from the direction opposite to `direction` (a
  // ray's direction, any length but not zero).
  Color radiance(const Tuple& direction) const {
    if (!zenith) return color;
    const double y = direction.y / magnitude(direction);
    if (!(y > 0)) return color;
    return color * (1 - y) + *zenith * y;
  }
};

struct World {
  std::vector<std::shared_ptr<Shape>> objects;
  // Every light's contribution adds up.
  std::vector<PointLight> lights;
  std::vector<AreaLight> area_lights;
  // What rays that hit nothing see (black by default, as in the book).
  Environment environment;
  // Optional, built by index_objects: the renderer's queries use it while
  // it covers as many objects as `objects` holds, else test every object.
  ShapeBvh index;
};

// Builds world.index over the objects as they are now. Call it again after
// changing the objects or their transforms (the scene loader calls it).
void index_objects(World& world);

// How many bounces color_at follows by default (reflection and refraction).
inline constexpr int kDefaultRemaining = 5;

// The book's test world: a light at (-10, 10, -10), a unit sphere of colour
// (0.8, 1.0, 0.6) (diffuse 0.7, specular 0.2) and a concentric sphere scaled
// by 0.5.
World default_world();

// Replaces the contents of `xs` with every intersection of `ray` with the
// world's objects, sorted by t. Reuse one buffer across rays to avoid
// allocating.
void intersect_world(const World& world, const Ray& ray, Intersections& xs);

// The visible intersection along `ray` (what hit() picks from
// intersect_world's list, up to ties), without building the list.
bool intersect_nearest(const World& world, const Ray& ray, Intersection& hit);

// Whether an object that casts shadows lies between `point` and the light.
bool is_shadowed(const World& world, const Tuple& point, const PointLight& light);
// The bonus chapter's form: whether an object that casts shadows lies
// between `point` and `light_position`.
bool is_shadowed(const World& world, const Tuple& light_position, const Tuple& point);

// The fraction of the light that reaches `point`: 0 or 1 for a point light,
// the fraction of unshadowed samples (light.sample) for an area light.
double intensity_at(const PointLight& light, const Tuple& point, const World& world);
double intensity_at(const AreaLight& light, const Tuple& point, const World& world);

// Surface colour (every light, and the material's emissive colour) plus
// reflected and refracted colour, with `remaining` bounces left.
Color shade_hit(const World& world, const Computations& comps, int remaining = kDefaultRemaining);

// Rays traced so far on the calling thread: every color_at call (camera,
// reflected and refracted rays) and every is_shadowed call (shadow rays)
// adds one. Renderers take differences around a unit of work.
std::uint64_t& rays_traced_on_this_thread();

// The colour seen along `ray`: the environment's if it hits nothing.
Color color_at(const World& world, const Ray& ray, int remaining = kDefaultRemaining);

// color_at for a ray that starts inside `inside` (the book's containers list
// at the ray's start) where that is known: such a ray asks for the nearest
// hit instead of every intersection up to it, as the rays refracted into a
// closed glass shape do. With Containers::unknown() it is color_at.
Color color_at(const World& world, const Ray& ray, int remaining, const Containers& inside);

// What the rays from one eye point start inside, where the book's containers
// list at t = 0 is known without walking each ray's line: the eye lies
// outside the box of every object and each is a closed surface that the
// containers carry (carried_in_containers: a sphere, a cube, a capped
// cylinder or cone, a whole or capped torus), so each ray's line crosses
// each of them an even number of times behind the eye; planes, unbounded,
// are asked per ray: a ray whose line meets one behind the eye starts
// inside it in the book's walk, and is left unknown. Anything else in the
// world (a group, CSG, triangles) leaves every ray unknown, and so does a
// world without glass, whose rays ask for the nearest hit anyway.
class EyeContainers {
 public:
  EyeContainers(const World& world, const Tuple& eye);
  // Inside nothing, or unknown, for a ray that starts at the eye (unknown
  // for any other).
  Containers for_ray(const Ray& ray) const;

 private:
  Tuple eye_;
  bool outside_every_object_ = false;
  std::vector<const Shape*> planes_;
};

// Colour arriving along the reflection of the eye ray; black when the
// material is not reflective or remaining <= 0.
Color reflected_color(const World& world, const Computations& comps, int remaining = kDefaultRemaining);

// Colour arriving through the surface; black when the material is opaque,
// remaining <= 0, or under total internal reflection.
Color refracted_color(const World& world, const Computations& comps, int remaining = kDefaultRemaining);

}  // namespace toroid
