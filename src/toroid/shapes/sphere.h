// SPDX-License-Identifier: Apache-2.0
// Unit sphere at the origin (RTC chapter 5).
#pragma once

#include <cmath>
#include <memory>
#include <utility>

#include "toroid/shapes/primitive.h"

namespace toroid {

class Sphere : public Primitive<Sphere> {
 public:
  BoundingBox bounds() const override { return {point(-1, -1, -1), point(1, 1, 1)}; }
  // Half of bounds()'s side, without building the box: asked at every hit.
  double half_thickness() const override { return 1.0; }
  // Kept from set_transform: asked at every hit.
  double parent_space_half_thickness() const override { return parent_space_half_; }
  bool closed_surface() const override { return true; }
  // Inline: the renderer's three queries each inline it, and the sphere's
  // arithmetic is cheaper than a call and the zeroing of an unread array.
  int find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
    return hits_about_centre(ray.origin, ray.direction, 1.0, hits, false);
  }
  // The queries that look ahead (t >= 0) skip a sphere the ray leaves from
  // outside before the square root (hits_about_centre).
  bool local_intersect_nearest(const Ray& local_ray, double t_max, Intersection& hit) const override {
    HitSlots slots;
    return nearest_in(slots.at, hits_about_centre(local_ray.origin, local_ray.direction, 1.0, slots.at, true), t_max,
                      hit);
  }
  bool local_blocks(const Ray& local_ray, double t_max) const override {
    HitSlots slots;
    return any_in(slots.at, hits_about_centre(local_ray.origin, local_ray.direction, 1.0, slots.at, true), t_max);
  }
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;

  // Under a similarity transform (rotations, mirrors, one scale for all
  // three axes, translations) the sphere is a sphere in its parent's space
  // too, of centre `centre()` and radius `radius()`: the queries test the
  // ray there, without moving it into object space, and a sphere at the
  // top level takes its normal there (the point less the centre), without
  // the transforms. Other transforms take the book's way.
  bool intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const override;
  bool blocks(const Ray& ray, double t_max) const override;
  void intersect(const Ray& ray, Intersections& xs) const override;
  Tuple normal_at(const Tuple& world_point, const Intersection& hit = {}) const override;
  // Under a similarity: that sphere's box, padded (padded_box).
  BoundingBox parent_space_bounds() const override;
  bool similarity() const { return similarity_; }
  const Tuple& centre() const { return centre_; }
  double radius() const { return radius_; }

 protected:
  void transform_changed() override;

 private:
  // The hits of the line origin + t direction with the sphere of squared
  // radius radius2 about the origin, both t's (ascending). With
  // `ahead_only`, none where the origin is outside (c > 0) and the line
  // leaves the centre (b > 0): both t's would come out negative (q < 0
  // below, so q / a < 0 and c / q < 0), and the queries that read only
  // t >= 0 are spared the square root and the divisions (shadow rays
  // leaving a sphere, or pointing away from one, are the common case).
  int hits_about_centre(const Tuple& o, const Tuple& d, double radius2, Intersection hits[kMaxHits],
                        bool ahead_only) const {
    // The book's a, b and c, with dot products of xyz alone: the w terms
    // are 0 * 0 (b's + 0 is kept: it turns a sum of -0 into +0, and b's
    // sign picks the root).
    const double a = d.x * d.x + d.y * d.y + d.z * d.z;
    const double b = 2 * (d.x * o.x + d.y * o.y + d.z * o.z + 0.0);
    const double c = o.x * o.x + o.y * o.y + o.z * o.z - radius2;
    if (ahead_only && b > 0 && c > 0) return 0;
    const double discriminant = b * b - 4 * a * c;
    if (discriminant < 0) return 0;
    // Numerically stable form: no cancellation between -b and sqrt(disc).
    const double q = -0.5 * (b + std::copysign(std::sqrt(discriminant), b));
    double t0 = q / a;
    double t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    hits[0] = {t0, this};
    hits[1] = {t1, this};
    return 2;
  }
  // The hits of a parent-space ray, under a similarity transform.
  int hits_in_parent_space(const Ray& ray, Intersection hits[kMaxHits], bool ahead_only) const {
    const Tuple o = ray.origin - centre_;
    return hits_about_centre(o, ray.direction, radius2_, hits, ahead_only);
  }

  Tuple centre_ = point(0, 0, 0);
  double radius_ = 1, radius2_ = 1, inverse_radius_ = 1;
  double parent_space_half_ = 1 / std::sqrt(3.0);  // Shape's expression, for the identity
  bool similarity_ = true;
};

// A unit sphere of glass: transparency 1, refractive index 1.5 (RTC chapter 11).
std::shared_ptr<Sphere> glass_sphere();

}  // namespace toroid
