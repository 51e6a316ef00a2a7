// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/world.h"

#include <cmath>
#include <cstdint>
#include <limits>

#include "toroid/math/transform.h"
#include "toroid/render/lighting.h"
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

void index_objects(World& world) { world.index = ShapeBvh(world.objects); }

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

// Whether an object that casts shadows lies on the shadow ray from `point`
// along the unit `direction` before `distance` (the light). `light` names
// the light for the shadow cache.
bool shadow_ray_blocked(const World& world, const Tuple& point, const Tuple& direction, double distance,
                        const Tuple* light) {
  ++rays_traced_on_this_thread();
  const Ray ray{point, direction};
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
    Slot& slot = slots[(reinterpret_cast<std::uintptr_t>(light) * 0x9E3779B97F4A7C15u) >> 62];
    if (slot.light != light) slot = {light, nullptr};
    if (slot.blocker) {
      if (slot.blocker->blocks(ray, distance)) return true;
      slot.blocker = nullptr;
    }
    return world.index.blocks(ray, distance, &slot.blocker);
  }
  for (const auto& object : world.objects)
    if (object->blocks(ray, distance)) return true;
  return false;
}

}  // namespace

bool is_shadowed(const World& world, const Tuple& light_position, const Tuple& point) {
  const Tuple to_light = light_position - point;
  const double distance = magnitude(to_light);
  return shadow_ray_blocked(world, point, to_light / distance, distance, &light_position);
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

Color shade_hit(const World& world, const Computations& comps, int remaining) {
  const Material& m = comps.object->material();
  Color surface = kBlack;
  for (const PointLight& light : world.lights) {
    // The direction to the light is lighting's lightv and the shadow ray's
    // direction alike (normalize, written out for the distance).
    const Tuple to_light = light.position - comps.over_point;
    const double distance = magnitude(to_light);
    const Tuple lightv = to_light / distance;
    // A light behind the surface lights nothing, shadowed or not (lighting's
    // own test, on the same vector): spare its shadow ray.
    const bool faces_light = dot(lightv, comps.normalv) >= 0;
    const bool shadowed = faces_light && shadow_ray_blocked(world, comps.over_point, lightv, distance, &light.position);
    surface += lighting_towards(m, *comps.object, light, comps.over_point, lightv, comps.eyev, comps.normalv,
                                shadowed ? 0.0 : 1.0);
  }
  for (const AreaLight& light : world.area_lights) {
    // A light wholly behind the surface lights nothing: spare its shadow rays.
    const double visible =
        light.in_front_of(comps.over_point, comps.normalv) ? intensity_at(light, comps.over_point, world) : 0.0;
    surface += lighting(m, *comps.object, light, comps.over_point, comps.eyev, comps.normalv, visible);
  }
  // Emission: an exact no-op for the default black (x + 0 == x), skipped.
  if (m.emissive.r != 0 || m.emissive.g != 0 || m.emissive.b != 0) surface += m.emissive;
  const Color reflected = reflected_color(world, comps, remaining);
  const Color refracted = refracted_color(world, comps, remaining);
  if (m.reflective > 0 && m.transparency > 0) {
    const double reflectance = schlick(comps);
    return surface + reflected * reflectance + refracted * (1 - reflectance);
  }
  return surface + reflected + refracted;
}

Color color_at(const World& world, const Ray& ray, int remaining) {
  ++rays_traced_on_this_thread();
  if (indexed(world) && !world.index.any_transparent()) {
    // Nothing refracts, so n1 and n2 go unread: the nearest hit is enough.
    // (Asking for the nearest hit first and for the list only when it
    // refracts costs more than it saves on scenes with much glass.)
    Intersection nearest;
    if (!intersect_nearest(world, ray, nearest)) return world.environment.radiance(ray.direction);
    return shade_hit(world, prepare_computations(nearest, ray), remaining);
  }
  // Refraction needs n1 and n2, from every intersection along the ray up
  // to the hit (the containers algorithm). One buffer per thread, reused
  // across rays. Recursion is safe: the intersections are consumed by
  // prepare_computations before shade_hit can cast (and so overwrite them
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
  // Only a refracting hit reads n1 and n2 (refracted_color, schlick): the
  // list is cut at the hit, sorted, and the containers walked, for those
  // alone.
  if (h->object->material().transparency == 0) return shade_hit(world, prepare_computations(*h, ray), remaining);
  const Intersection found = *h;
  std::erase_if(xs, [&found](const Intersection& x) { return x.t > found.t; });
  sort_intersections(xs);
  return shade_hit(world, prepare_computations(found, ray, xs), remaining);
}

Color reflected_color(const World& world, const Computations& comps, int remaining) {
  const double reflective = comps.object->material().reflective;
  if (remaining <= 0 || reflective == 0) return kBlack;
  const Ray reflect_ray{comps.over_point, comps.reflectv};
  return color_at(world, reflect_ray, remaining - 1) * reflective;
}

Color refracted_color(const World& world, const Computations& comps, int remaining) {
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
  return color_at(world, refract_ray, remaining - 1) * transparency;
}

}  // namespace toroid
