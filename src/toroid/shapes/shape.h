// The shape base (RTC chapter 9): a transform, a material and an optional
// parent group. Subclasses intersect and shade in their own object space.
#pragma once

#include <cstddef>

#include "toroid/math/matrix.h"
#include "toroid/render/intersection.h"
#include "toroid/render/material.h"
#include "toroid/render/ray.h"
#include "toroid/shapes/bounds.h"

namespace toroid {

class Group;

class Shape {
 public:
  Shape() = default;
  Shape(const Shape&) = delete;
  Shape& operator=(const Shape&) = delete;
  virtual ~Shape() = default;

  const Matrix4& transform() const { return transform_; }
  const Matrix4& inverse_transform() const { return inverse_; }
  // Precondition: is_invertible(m). Caches the inverse and its transpose.
  void set_transform(const Matrix4& m);

  Material material;
  // Shapes with casts_shadow == false are skipped by shadow rays (YAML `shadow: false`).
  bool casts_shadow = true;
  const Shape* parent = nullptr;

  // Appends the intersections of a ray given in the parent's space.
  void intersect(const Ray& ray, Intersections& xs) const { local_intersect(::toroid::transform(ray, inverse_), xs); }

  // Normal at a world-space point; `hit` carries u/v for smooth triangles.
  Tuple normal_at(const Tuple& world_point, const Intersection& hit = {}) const;

  Tuple world_to_object(const Tuple& world_point) const;
  Tuple normal_to_world(const Tuple& object_normal) const;

  // Box in this shape's own object space.
  virtual BoundingBox bounds() const = 0;
  // Box in the parent's space (object bounds through this shape's transform).
  BoundingBox parent_space_bounds() const;

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

 protected:
  // Told by a child (see bounds_changed) that its box may have moved.
  virtual void child_bounds_changed() const {}

 private:
  Matrix4 transform_ = Matrix4::identity();
  Matrix4 inverse_ = Matrix4::identity();
  Matrix4 inverse_transpose_ = Matrix4::identity();
};

}  // namespace toroid
