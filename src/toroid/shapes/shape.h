// SPDX-License-Identifier: Apache-2.0
// The shape base (RTC chapter 9): a transform, a material and an optional
// parent group. Subclasses intersect and shade in their own object space.
#pragma once

#include <cstddef>
#include <memory>
#include <utility>

#include "toroid/core/bounds.h"
#include "toroid/core/intersection.h"
#include "toroid/core/material.h"
#include "toroid/core/ray.h"
#include "toroid/core/shared_material.h"
#include "toroid/math/affine.h"
#include "toroid/math/matrix.h"

namespace toroid {

class Group;

class Shape {
  // The object-to-parent transform's inverse, first: the data members are
  // ordered so that the one-byte flag comes last, and a subclass's small
  // field fits in the tail padding (a scene may hold many thousands of
  // shapes; see docs/performance.md).
  Affine inverse_;
  SharedMaterial material_;

 public:
  Shape() = default;
  Shape(const Shape&) = delete;
  Shape& operator=(const Shape&) = delete;
  virtual ~Shape() = default;

  // Only the inverse is stored, in affine form (memory: a scene may hold
  // many thousands of shapes); transform() recomputes the forward matrix
  // from it, for setup-time uses (bounds).
  Matrix4 transform() const { return inverse(inverse_.to_matrix()); }
  Matrix4 inverse_transform() const { return inverse_.to_matrix(); }
  const Affine& inverse_affine() const { return inverse_; }
  // Precondition: is_invertible(m) and m is affine (bottom row 0 0 0 1).
  void set_transform(const Matrix4& m);

  // The material is held by a counted pointer (8 bytes instead of its 96):
  // shapes made without one share one process-wide default, and the scene
  // loader gives shapes with equal materials one block (docs/performance.md).
  const Material& material() const { return *material_; }
  const SharedMaterial& shared_material() const { return material_; }
  // A new block holding a copy of m, this shape's alone.
  void set_material(const Material& m) { material_ = SharedMaterial(m); }
  // Shares m's block with its other holders.
  void set_material(SharedMaterial m) { material_ = std::move(m); }

  const Shape* parent = nullptr;
  // Shapes with casts_shadow == false are skipped by shadow rays (YAML `shadow: false`).
  bool casts_shadow = true;

  // The queries take a ray in the parent's space. By default they move it
  // into object space and ask the local_ queries below; a shape that can
  // answer in its parent's space (a sphere under a similarity transform)
  // overrides them. Primitive overrides all three, so that a primitive
  // costs one virtual call per query.

  // Appends the intersections of the ray.
  virtual void intersect(const Ray& ray, Intersections& xs) const { local_intersect(to_object_space(ray), xs); }
  // The renderer's queries. The nearest intersection with 0 <= t < t_max:
  // when there is one, sets `hit` and returns true (the same one that hit()
  // picks from intersect's list, up to ties).
  virtual bool intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
    return local_intersect_nearest(to_object_space(ray), t_max, hit);
  }
  // Whether a shape that casts shadows meets the ray at some 0 <= t < t_max
  // (shadow rays: any blocker will do).
  virtual bool blocks(const Ray& ray, double t_max) const {
    return casts_shadow && local_blocks(to_object_space(ray), t_max);
  }

  // Normal at a world-space point; `hit` carries u/v for smooth triangles.
  // Virtual so that a shape whose normal is the same everywhere (a plane)
  // can answer without the transforms.
  virtual Tuple normal_at(const Tuple& world_point, const Intersection& hit = {}) const;

  // world_point is a point (w = 1).
  Tuple world_to_object(const Tuple& world_point) const;
  Tuple normal_to_world(const Tuple& object_normal) const;
  // One step of normal_to_world: an object-space normal in the parent's
  // space, normalised.
  Tuple normal_to_parent(const Tuple& object_normal) const {
    // normalize() less its division of w (0 / length is 0).
    const Tuple n = inverse_.transpose_times(object_normal);
    const double length = magnitude(n);
    return vector(n.x / length, n.y / length, n.z / length);
  }

  // Box in this shape's own object space.
  virtual BoundingBox bounds() const = 0;
  // Box in the parent's space: object bounds through this shape's transform
  // (the corners of bounds(), transformed), or tighter where a shape knows
  // better (a rotated torus).
  virtual BoundingBox parent_space_bounds() const;
  // Half the thinnest finite, non-zero side of bounds() (0 when there is
  // none, as for a plane): the scale of the shape, for the surface bias.
  // Shapes that know it without building their box override it.
  virtual double half_thickness() const;
  // half_thickness() in the parent's space, a lower bound: divided by the
  // Frobenius norm of the inverse's linear part (a length shrinks at most by
  // the largest stretch of the parent-to-object map). Asked at every hit of
  // a top-level shape (the surface bias); primitives answer with one call.
  virtual double parent_space_half_thickness() const;

  // Whether the shape's surface bounds a solid: every line crosses it an even
  // number of times, so that whether a point lies inside is the parity of
  // the crossings on either side of it (a sphere, a cube, a whole or capped
  // torus, a closed finite cylinder or cone; not a plane, a triangle, an
  // open tube). The renderer carries the list of such shapes a ray is
  // inside to the rays it spawns (render/computations.h, Containers).
  virtual bool closed_surface() const { return false; }

  // CSG: whether `other` is this shape or one of its descendants.
  virtual bool includes(const Shape* other) const { return other == this; }

  // BVH (bonus chapter): groups split their children into a hierarchy of
  // subgroups with at most about `threshold` children each; CSG divides its
  // operands; primitives have nothing to divide.
  virtual void divide(std::size_t threshold) { (void)threshold; }

  // Groups and CSG cache their bounds. Call this after changing something that
  // moves this shape's box (cylinder minimum, ...) once it has a parent;
  // set_transform and Group::add_child call it themselves. Setup time only.
  void bounds_changed() const {
    if (parent) parent->child_bounds_changed();
  }

  virtual void local_intersect(const Ray& local_ray, Intersections& xs) const = 0;
  virtual Tuple local_normal_at(const Tuple& local_point, const Intersection& hit) const = 0;
  // intersect_nearest and blocks in object space. The defaults filter
  // local_intersect's list; shapes override them where they can stop early
  // (groups prune their boxes, the torus asks for its nearest root only).
  virtual bool local_intersect_nearest(const Ray& local_ray, double t_max, Intersection& hit) const;
  virtual bool local_blocks(const Ray& local_ray, double t_max) const;

 protected:
  // Told by a child (see bounds_changed) that its box may have moved.
  virtual void child_bounds_changed() const {}
  // `half` (a half thickness in object space) in the parent's space, as
  // parent_space_half_thickness gives it.
  double half_in_parent_space(double half) const { return half == 0 ? 0 : half / linear_frobenius_norm(inverse_.m); }
  // Told by set_transform, after the new inverse is in place.
  virtual void transform_changed() {}

  [[gnu::always_inline]] Ray to_object_space(const Ray& ray) const {
    return {inverse_.times_point(ray.origin), inverse_.times_vector(ray.direction)};
  }
};

}  // namespace toroid
