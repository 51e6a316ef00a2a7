// SPDX-License-Identifier: Apache-2.0
// Constructive solid geometry (RTC chapter 16): the union, intersection or
// difference of two shapes, each of which may be a group of overlapping
// closed shapes (their union).
#pragma once

#include <cstddef>
#include <memory>

#include "toroid/shapes/shape.h"

namespace toroid {

enum class CsgOp { Union, Intersection, Difference };

// The book's rule: whether an intersection survives, given whether it is on
// the left operand (lhit) and whether the ray is inside the left (inl) and
// the right (inr) operand at that point.
bool intersection_allowed(CsgOp op, bool lhit, bool inl, bool inr);

class Csg : public Shape {
 public:
  // Takes shared ownership of both operands and sets their parent.
  Csg(CsgOp op, std::shared_ptr<Shape> left, std::shared_ptr<Shape> right);

  CsgOp operation() const { return op_; }
  const std::shared_ptr<Shape>& left() const { return left_; }
  const std::shared_ptr<Shape>& right() const { return right_; }

  // Union of the operands' boxes in this shape's space; cached.
  BoundingBox bounds() const override { return bounds_; }

  // Tests the box, gathers both operands' intersections after the ones
  // already in xs, sorts just those and keeps those on the CSG surface.
  // No allocation beyond xs's own growth.
  void local_intersect(const Ray& ray, Intersections& xs) const override;
  // CSG has no surface of its own: hits always name a primitive.
  // Throws std::logic_error.
  Tuple local_normal_at(const Tuple& p, const Intersection& hit) const override;

  // Whether `other` is this CSG or one of its descendants.
  bool includes(const Shape* other) const override;
  void divide(std::size_t threshold) override;

  // Keeps, in place and in order, the intersections xs[first...] allowed by
  // the operation and drops the rest. The ray is inside an operand where it
  // is inside any of the operand's closed pieces (its primitives, and the
  // outermost CSG shapes within it, each crossed an even number of times),
  // so that a group of overlapping shapes acts as their union: a crossing
  // inside the operand (one sphere's surface within another) is dropped.
  // The pieces crossed an odd number of times (open surfaces: a mesh's
  // triangles) share one inside flag per operand, flipped at each of their
  // crossings as in the book. Where an operand's pieces do not overlap this
  // is the book's rule. No allocation for up to 32 intersections.
  // Precondition: xs[first...] is sorted by t and every object in it lies
  // within left() or right().
  void filter_intersections(Intersections& xs, std::size_t first = 0) const;

 protected:
  void child_bounds_changed() const override;

 private:
  // filter_intersections where neither operand is a group.
  void filter_one_piece_each(Intersections& xs, std::size_t first) const;

  CsgOp op_;
  std::shared_ptr<Shape> left_, right_;
  mutable BoundingBox bounds_;  // refreshed by child_bounds_changed at setup time
  // Whether each operand is itself a CSG (one closed piece), and whether
  // neither is a group (each is one piece: the book's rule, on a shorter
  // path), known once so that the filter asks no operand's type.
  bool left_is_csg_, right_is_csg_, one_piece_each_;
};

}  // namespace toroid
