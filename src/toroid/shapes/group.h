// SPDX-License-Identifier: Apache-2.0
// A group of shapes sharing one transform (RTC chapter 14), with a cached
// bounding box and the bonus chapter's bounding volume hierarchy (divide).
#pragma once

#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

#include "toroid/shapes/shape.h"

namespace toroid {

using ShapeList = std::vector<std::shared_ptr<Shape>>;

class Group : public Shape {
 public:
  // Takes shared ownership and sets child->parent. A shape has one parent:
  // adding it to a second group re-parents it.
  void add_child(std::shared_ptr<Shape> child);

  const ShapeList& children() const { return children_; }
  bool empty() const { return children_.empty(); }
  std::size_t size() const { return children_.size(); }

  // Union of the children's boxes in this group's space; cached.
  BoundingBox bounds() const override { return bounds_; }

  // Tests the bounding box first, then appends every child's intersections
  // to xs, unsorted.
  void local_intersect(const Ray& ray, Intersections& xs) const override;
  // Skip the box when it starts beyond t_max; each hit shortens t_max.
  bool local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const override;
  bool local_blocks(const Ray& ray, double t_max) const override;
  // Groups have no surface of their own: hits always name a primitive.
  // Throws std::logic_error.
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;

  // Whether `other` is this group or a descendant (walks other's parents).
  bool includes(const Shape* other) const override;

  // Bonus chapter: removes the children that fit wholly in the left or the
  // right half of this group's box (split()) and returns them as {left, right}.
  std::pair<ShapeList, ShapeList> partition_children();
  // Adds a new group holding `children` as a child of this one.
  void make_subgroup(ShapeList children);
  // Builds the hierarchy: when this group has at least `threshold` children,
  // partitions them into subgroups; then divides every child. Beyond the
  // book, several children that straddle the split get a subgroup too.
  void divide(std::size_t threshold) override;

 protected:
  void child_bounds_changed() const override;

 private:
  // The steps of add_child, partition_children and make_subgroup without
  // telling the parent: divide leaves the box unchanged, and re-telling every
  // ancestor at each step would make building a large BVH quadratic.
  void attach(std::shared_ptr<Shape> child);
  std::pair<ShapeList, ShapeList> take_partition();
  static std::shared_ptr<Group> subgroup_of(ShapeList children);
  void recompute_bounds() const;

  ShapeList children_;
  // Mutable so that a child, which only holds a const parent pointer, can
  // have it refreshed (setup time only, never while rendering).
  mutable BoundingBox bounds_;
};

// Whether `shape` is `ancestor` or lies somewhere below it (follows parents).
bool is_within(const Shape* shape, const Shape& ancestor);

}  // namespace toroid
