// SPDX-License-Identifier: Apache-2.0
// A shape with a surface of its own and at most MaxHits intersections along
// any ray: four for most (sphere, plane, cube, cylinder, cone, triangle),
// more for a capped partial torus. Derived lists them once, into a fixed
// array, with
//   int find_hits(const Ray& local_ray, Intersection hits[kMaxHits]) const;
// (every intersection, any t, in the order local_intersect lists them;
// returns how many), and the renderer's queries (nearest hit, shadow test)
// read them from there instead of from a growing list. The template calls
// find_hits directly: one virtual call per shape and query, not two. The
// capacity is a template parameter so that the four-hit shapes keep arrays
// of four, and the arrays are left uninitialised: find_hits writes the first
// n, and only those are read.
#pragma once

#include "toroid/shapes/shape.h"

namespace toroid {

inline constexpr int kMaxPrimitiveHits = 4;

template <typename Derived, int MaxHits = kMaxPrimitiveHits>
class Primitive : public Shape {
 public:
  static constexpr int kMaxHits = MaxHits;

  void local_intersect(const Ray& local_ray, Intersections& xs) const final {
    HitSlots slots;
    append(slots.at, self().find_hits(local_ray, slots.at), xs);
  }
  bool local_intersect_nearest(const Ray& local_ray, double t_max, Intersection& hit) const override {
    HitSlots slots;
    return nearest_in(slots.at, self().find_hits(local_ray, slots.at), t_max, hit);
  }
  bool local_blocks(const Ray& local_ray, double t_max) const override {
    HitSlots slots;
    return any_in(slots.at, self().find_hits(local_ray, slots.at), t_max);
  }

  // Shape's, with Derived's half_thickness called directly.
  double parent_space_half_thickness() const override { return half_in_parent_space(self().Derived::half_thickness()); }

  // The parent-space queries: the ray into object space, then Derived's
  // local query called directly (one virtual call per query, not two).
  // Derived may override these again (a sphere under a similarity
  // transform answers in its parent's space).
  void intersect(const Ray& ray, Intersections& xs) const override {
    self().Derived::local_intersect(to_object_space(ray), xs);
  }
  bool intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const override {
    return self().Derived::local_intersect_nearest(to_object_space(ray), t_max, hit);
  }
  bool blocks(const Ray& ray, double t_max) const override {
    return casts_shadow && self().Derived::local_blocks(to_object_space(ray), t_max);
  }

 protected:
  // Room for find_hits's answers without constructing them (Intersection's
  // members have initialisers, which an array would run on every call).
  union HitSlots {
    HitSlots() {}
    Intersection at[kMaxHits];
  };

  // What each query makes of the first n hits: all of them appended (one
  // push_back per hit: a range insert's general path costs more than the
  // sphere's own arithmetic), the nearest with 0 <= t < t_max, or whether
  // there is one.
  static void append(const Intersection* hits, int n, Intersections& xs) {
    for (int i = 0; i < n; ++i) xs.push_back(hits[i]);
  }
  static bool nearest_in(const Intersection* hits, int n, double t_max, Intersection& hit) {
    bool found = false;
    for (int i = 0; i < n; ++i)
      if (hits[i].t >= 0 && hits[i].t < t_max) {
        hit = hits[i];
        t_max = hits[i].t;
        found = true;
      }
    return found;
  }
  static bool any_in(const Intersection* hits, int n, double t_max) {
    for (int i = 0; i < n; ++i)
      if (hits[i].t >= 0 && hits[i].t < t_max) return true;
    return false;
  }

 private:
  const Derived& self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace toroid
