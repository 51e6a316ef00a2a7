// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/world.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "toroid/math/transform.h"
#include "toroid/render/lighting.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/shape.h"
#include "toroid/shapes/sphere.h"

namespace toroid {

World default_world() {
  World w;
  w.lights.push_back(PointLight{point(-10, 10, -10), Color{1, 1, 1}});
  auto s1 = std::make_shared<Sphere>();
  Material m1;
  m1.color = Color{0.8, 1.0, 0.6};
  m1.diffuse = 0.7;
  m1.specular = 0.2;
  s1->set_material(m1);
  auto s2 = std::make_shared<Sphere>();
  s2->set_transform(scaling(0.5, 0.5, 0.5));
  w.objects.push_back(std::move(s1));
  w.objects.push_back(std::move(s2));
  return w;
}

void intersect_world(const World& world, const Ray& ray, Intersections& xs) {
  xs.clear();
  for (const auto& object : world.objects) object->intersect(ray, xs);
  sort_intersections(xs);
}

void index_objects(World& world) {
  std::vector<Tuple> point_lights;
  for (const PointLight& light : world.lights) point_lights.push_back(light.position);
  world.index = ShapeBvh(world.objects, point_lights);
}

namespace {
bool indexed(const World& world) { return !world.objects.empty() && world.index.size() == world.objects.size(); }
}  // namespace

bool intersect_nearest(const World& world, const Ray& ray, Intersection& hit) {
  constexpr double kNoLimit = std::numeric_limits<double>::infinity();
  if (indexed(world)) return world.index.intersect_nearest(ray, kNoLimit, hit);
  bool found = false;
  double t_max = kNoLimit;
  for (const auto& object : world.objects)
    if (object->intersect_nearest(ray, t_max, hit)) {
      found = true;
      t_max = hit.t;
    }
  return found;
}

std::uint64_t& rays_traced_on_this_thread() {
  thread_local std::uint64_t count = 0;
  return count;
}

bool is_shadowed(const World& world, const Tuple& point, const PointLight& light) {
  return is_shadowed(world, light.position, point);
}

namespace {

// Whether an object that casts shadows lies between `point` and the light
// at `light` (whose address also names it for the shadow cache). The ray
// goes along light - point, not normalised: the light is at t = 1, and the
// walk need not wait for a square root and a division. `point_light` is the
// light's place in world.lights, for the index's light buffer, or -1.
bool shadow_ray_blocked(const World& world, const Tuple& point, const Tuple& light, std::ptrdiff_t point_light = -1) {
  ++rays_traced_on_this_thread();
  const Ray ray{point, light - point};
  constexpr double t_light = 1;
  // Any blocker between the point and the light will do. Neighbouring shadow
  // rays towards one light tend to be blocked by the same object (POV-Ray's
  // shadow cache): try the last blocker of this thread's rays towards this
  // light first, and forget it once it misses (a stale blocker costs a test
  // on every ray). Lights are told apart by the position's address, in a few
  // slots; the answer is the same whatever the cache holds.
  if (indexed(world)) {
    struct Slot {
      const Tuple* light = nullptr;
      const Shape* blocker = nullptr;
    };
    thread_local std::uint64_t cached_index = 0;
    thread_local Slot slots[4];
    if (cached_index != world.index.serial()) {
      cached_index = world.index.serial();
      for (Slot& slot : slots) slot = {};
    }
    Slot& slot = slots[(reinterpret_cast<std::uintptr_t>(&light) * 0x9E3779B97F4A7C15u) >> 62];
    if (slot.light != &light) slot = {&light, nullptr};
    if (slot.blocker) {
      if (slot.blocker->blocks(ray, t_light)) return true;
      slot.blocker = nullptr;
    }
    return point_light >= 0 ? world.index.blocks_towards_light(static_cast<std::size_t>(point_light), light, ray,
                                                               t_light, &slot.blocker)
                            : world.index.blocks(ray, t_light, &slot.blocker);
  }
  for (const auto& object : world.objects)
    if (object->blocks(ray, t_light)) return true;
  return false;
}

}  // namespace

bool is_shadowed(const World& world, const Tuple& light_position, const Tuple& point) {
  return shadow_ray_blocked(world, point, light_position);
}

double intensity_at(const PointLight& light, const Tuple& point, const World& world) {
  return is_shadowed(world, light.position, point) ? 0.0 : 1.0;
}

double intensity_at(const AreaLight& light, const Tuple& point, const World& world) {
  int lit = 0;
  const std::uint64_t key = light.jitter_key(point);
  for (int v = 0; v < light.vsteps; ++v)
    for (int u = 0; u < light.usteps; ++u)
      if (!is_shadowed(world, light.sample(key, u, v), point)) ++lit;
  return static_cast<double>(lit) / light.samples;
}

namespace {

Color trace(const World& world, const Ray& ray, int remaining, const Containers& inside);

// Colour arriving along the reflection of the eye ray, which starts inside
// what the eye ray was inside before the hit.
Color reflected(const World& world, const Computations& comps, int remaining, const Containers& before) {
  const double reflective = comps.object->material().reflective;
  if (remaining <= 0 || reflective == 0) return kBlack;
  const Ray reflect_ray{comps.over_point, comps.reflectv};
  return trace(world, reflect_ray, remaining - 1, before) * reflective;
}

// Colour arriving through the surface: the refracted ray starts inside
// what the eye ray was inside before the hit, with the hit's object crossed.
Color refracted(const World& world, const Computations& comps, int remaining, const Containers& before) {
  const double transparency = comps.object->material().transparency;
  if (remaining <= 0 || transparency == 0) return kBlack;
  // Snell's law: n1 sin(i) = n2 sin(t).
  const double n_ratio = comps.n1 / comps.n2;
  const double cos_i = dot(comps.eyev, comps.normalv);
  const double sin2_t = n_ratio * n_ratio * (1 - cos_i * cos_i);
  if (sin2_t > 1) return kBlack;  // total internal reflection
  const double cos_t = std::sqrt(1.0 - sin2_t);
  const Tuple direction = comps.normalv * (n_ratio * cos_i - cos_t) - comps.eyev * n_ratio;
  const Ray refract_ray{comps.under_point, direction};
  Containers after = before;
  after.cross(comps.object);  // (known only for a hit on a shape carried_in_containers)
  return trace(world, refract_ray, remaining - 1, after) * transparency;
}

// shade_hit, for a ray that started inside `before` (or unknown).
Color shade(const World& world, const Computations& comps, int remaining, const Containers& before) {
  const Material& m = comps.object->material();
  const Color base_color = surface_color(m, *comps.object, comps.over_point);
  Color surface = kBlack;
  for (std::size_t i = 0; i < world.lights.size(); ++i) {
    const PointLight& light = world.lights[i];
    // lighting's lightv; the shadow ray goes along light - point itself
    // (shadow_ray_blocked), so that it need not wait for this division.
    const Tuple lightv = normalize(light.position - comps.over_point);
    // A light behind the surface lights nothing, shadowed or not (lighting's
    // own test, on the same vector): spare its shadow ray.
    const bool faces_light = dot(lightv, comps.normalv) >= 0;
    const bool shadowed =
        faces_light && shadow_ray_blocked(world, comps.over_point, light.position, static_cast<std::ptrdiff_t>(i));
    surface += lighting_towards(m, base_color, light, lightv, comps.eyev, comps.normalv, shadowed ? 0.0 : 1.0);
  }
  for (const AreaLight& light : world.area_lights) {
    // A light wholly behind the surface lights nothing: spare its shadow rays.
    const double visible =
        light.in_front_of(comps.over_point, comps.normalv) ? intensity_at(light, comps.over_point, world) : 0.0;
    surface += lighting(m, base_color, light, comps.over_point, comps.eyev, comps.normalv, visible);
  }
  // Emission: an exact no-op for the default black (x + 0 == x), skipped.
  if (m.emissive.r != 0 || m.emissive.g != 0 || m.emissive.b != 0) surface += m.emissive;
  const Color reflected_part = reflected(world, comps, remaining, before);
  const Color refracted_part = refracted(world, comps, remaining, before);
  if (m.reflective > 0 && m.transparency > 0) {
    const double reflectance = schlick(comps);
    return surface + reflected_part * reflectance + refracted_part * (1 - reflectance);
  }
  return surface + reflected_part + refracted_part;
}

Color trace(const World& world, const Ray& ray, int remaining, const Containers& inside) {
  ++rays_traced_on_this_thread();
  const bool refraction = !indexed(world) || world.index.any_transparent();
  if (!refraction || inside.known()) {
    // The nearest hit is enough: nothing refracts, so n1 and n2 go unread,
    // or the ray carries the objects it starts inside, and n1 and n2 follow
    // from those and the hit's object.
    Intersection nearest;
    if (!intersect_nearest(world, ray, nearest)) return world.environment.radiance(ray.direction);
    if (!refraction) return shade(world, prepare_computations(nearest, ray), remaining, inside);
    // Only refracting hits pass the list on (the rays spawned at others
    // start from an unknown list: on the cheap shapes the list along the
    // line costs no more than the nearest hit). n1 and n2 of a refracting
    // plane, triangle or CSG primitive come from the book's list along
    // this ray, below.
    if (nearest.object->material().transparency == 0)
      return shade(world, prepare_computations(nearest, ray), remaining, Containers::unknown());
    if (carried_in_containers(*nearest.object))
      return shade(world, prepare_computations(nearest, ray, inside), remaining, inside);
  }
  // A ray that starts in an unknown place (a camera ray), or refracts at a
  // shape whose crossings cannot be carried: n1 and n2 from every
  // intersection along the ray up to the hit (the containers algorithm),
  // negative t included. One buffer per thread, reused across rays.
  // Recursion is safe: the intersections are consumed by
  // prepare_computations before shade can cast (and so overwrite them
  // with) the next ray.
  thread_local Intersections xs;
  const Intersection* h = nullptr;
  if (indexed(world)) {
    h = world.index.intersect_up_to_hit(ray, xs);
  } else {
    intersect_world(world, ray, xs);
    h = hit(xs);
  }
  if (h == nullptr) return world.environment.radiance(ray.direction);
  // Only a refracting hit reads n1 and n2 (refracted_color, schlick), and
  // passes the containers on: the list is cut at the hit, sorted, and the
  // containers walked, for those alone.
  if (h->object->material().transparency == 0)
    return shade(world, prepare_computations(*h, ray), remaining, Containers::unknown());
  const Intersection found = *h;
  std::erase_if(xs, [&found](const Intersection& x) { return x.t > found.t; });
  sort_intersections(xs);
  Containers before;
  const Computations comps = prepare_computations(found, ray, xs, before);
  return shade(world, comps, remaining, carried_in_containers(*found.object) ? before : Containers::unknown());
}

}  // namespace

Color shade_hit(const World& world, const Computations& comps, int remaining) {
  return shade(world, comps, remaining, Containers::unknown());
}

Color color_at(const World& world, const Ray& ray, int remaining) {
  return trace(world, ray, remaining, Containers::unknown());
}

Color color_at(const World& world, const Ray& ray, int remaining, const Containers& inside) {
  return trace(world, ray, remaining, inside);
}

EyeContainers::EyeContainers(const World& world, const Tuple& eye) : eye_(eye) {
  // Without glass every ray asks for the nearest hit already (trace).
  if (indexed(world) && !world.index.any_transparent()) return;
  for (const auto& object : world.objects) {
    if (dynamic_cast<const Plane*>(object.get()) != nullptr) {
      planes_.push_back(object.get());
      continue;
    }
    if (!carried_in_containers(*object)) return;
    const BoundingBox box = object->parent_space_bounds();
    if (box.contains_point(eye) || !(box.min.x <= box.max.x)) return;  // (an empty or NaN box: unsure)
  }
  outside_every_object_ = true;
}

Containers EyeContainers::for_ray(const Ray& ray) const {
  if (!outside_every_object_ || ray.origin.x != eye_.x || ray.origin.y != eye_.y || ray.origin.z != eye_.z)
    return Containers::unknown();
  thread_local Intersections xs;
  for (const Shape* plane : planes_) {
    xs.clear();
    plane->intersect(ray, xs);
    for (const Intersection& x : xs)
      if (!(x.t > 0)) return Containers::unknown();
  }
  return Containers{};
}

Color reflected_color(const World& world, const Computations& comps, int remaining) {
  return reflected(world, comps, remaining, Containers::unknown());
}

Color refracted_color(const World& world, const Computations& comps, int remaining) {
  return refracted(world, comps, remaining, Containers::unknown());
}

}  // namespace toroid
