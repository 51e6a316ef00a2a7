// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/csg.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "toroid/shapes/group.h"

namespace toroid {

bool intersection_allowed(CsgOp op, bool lhit, bool inl, bool inr) {
  switch (op) {
    case CsgOp::Union: return (lhit && !inr) || (!lhit && !inl);
    case CsgOp::Intersection: return (lhit && inr) || (!lhit && inl);
    case CsgOp::Difference: return (lhit && !inr) || (!lhit && inl);
  }
  return false;
}

Csg::Csg(CsgOp op, std::shared_ptr<Shape> left, std::shared_ptr<Shape> right)
    : op_(op), left_(std::move(left)), right_(std::move(right)) {
  left_->parent = this;
  right_->parent = this;
  child_bounds_changed();
}

void Csg::child_bounds_changed() const {
  BoundingBox b = left_->parent_space_bounds();
  b.merge(right_->parent_space_bounds());
  bounds_ = b;
  bounds_changed();
}

void Csg::local_intersect(const Ray& ray, Intersections& xs) const {
  if (!bounds_.intersects(ray)) return;
  const std::size_t first = xs.size();
  left_->intersect(ray, xs);
  right_->intersect(ray, xs);
  std::sort(xs.begin() + static_cast<std::ptrdiff_t>(first), xs.end(),
            [](const Intersection& a, const Intersection& b) { return a.t < b.t; });
  filter_intersections(xs, first);
}

Tuple Csg::local_normal_at(const Tuple&, const Intersection&) const {
  throw std::logic_error("local_normal_at called on a CSG shape: CSG has no surface of its own");
}

bool Csg::includes(const Shape* other) const { return is_within(other, *this); }

void Csg::divide(std::size_t threshold) {
  left_->divide(threshold);
  right_->divide(threshold);
}

void Csg::filter_intersections(Intersections& xs, std::size_t first) const {
  bool inl = false;
  bool inr = false;
  std::size_t kept = first;
  for (std::size_t i = first; i < xs.size(); ++i) {
    const Intersection x = xs[i];
    // Whether x lies on the left operand: climb from its object towards this.
    bool lhit = false;
    for (const Shape* s = x.object; s != nullptr && s != this; s = s->parent)
      if (s == left_.get()) {
        lhit = true;
        break;
      }
    if (intersection_allowed(op_, lhit, inl, inr)) xs[kept++] = x;
    if (lhit) {
      inl = !inl;
    } else {
      inr = !inr;
    }
  }
  xs.resize(kept);
}

}  // namespace toroid
