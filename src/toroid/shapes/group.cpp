// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/group.h"

#include <stdexcept>

namespace toroid {

bool is_within(const Shape* shape, const Shape& ancestor) {
  for (const Shape* s = shape; s != nullptr; s = s->parent)
    if (s == &ancestor) return true;
  return false;
}

void Group::attach(std::shared_ptr<Shape> child) {
  child->parent = this;
  bounds_.merge(child->parent_space_bounds());
  children_.push_back(std::move(child));
}

void Group::add_child(std::shared_ptr<Shape> child) {
  attach(std::move(child));
  bounds_changed();
}

void Group::local_intersect(const Ray& ray, Intersections& xs) const {
  if (!bounds_.intersects(ray)) return;
  for (const auto& child : children_) child->intersect(ray, xs);
}

bool Group::local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
  if (!bounds_.intersects(ray, t_max)) return false;
  bool found = false;
  for (const auto& child : children_)
    if (child->intersect_nearest(ray, t_max, hit)) {
      found = true;
      t_max = hit.t;
    }
  return found;
}

bool Group::local_blocks(const Ray& ray, double t_max) const {
  if (!bounds_.intersects(ray, t_max)) return false;
  for (const auto& child : children_)
    if (child->blocks(ray, t_max)) return true;
  return false;
}

Tuple Group::local_normal_at(const Tuple&, const Intersection&) const {
  throw std::logic_error("local_normal_at called on a group: groups have no surface");
}

bool Group::includes(const Shape* other) const { return is_within(other, *this); }

void Group::recompute_bounds() const {
  BoundingBox b;
  for (const auto& child : children_) b.merge(child->parent_space_bounds());
  bounds_ = b;
}

void Group::child_bounds_changed() const {
  recompute_bounds();
  bounds_changed();
}

// Leaves bounds_ as it was (now too large until the caller fixes it).
std::pair<ShapeList, ShapeList> Group::take_partition() {
  const auto [left_box, right_box] = bounds_.split();
  ShapeList left, right, rest;
  for (auto& child : children_) {
    const BoundingBox b = child->parent_space_bounds();
    if (left_box.contains_box(b)) {
      left.push_back(std::move(child));
    } else if (right_box.contains_box(b)) {
      right.push_back(std::move(child));
    } else {
      rest.push_back(std::move(child));
    }
  }
  children_ = std::move(rest);
  return {std::move(left), std::move(right)};
}

std::pair<ShapeList, ShapeList> Group::partition_children() {
  auto parts = take_partition();
  recompute_bounds();
  bounds_changed();
  return parts;
}

std::shared_ptr<Group> Group::subgroup_of(ShapeList children) {
  auto sub = std::make_shared<Group>();
  for (auto& child : children) sub->attach(std::move(child));
  return sub;
}

void Group::make_subgroup(ShapeList children) { add_child(subgroup_of(std::move(children))); }

void Group::divide(std::size_t threshold) {
  if (threshold <= children_.size()) {
    const std::size_t count = children_.size();
    const BoundingBox box = bounds_;
    auto [left, right] = take_partition();
    if (left.size() == count || right.size() == count || children_.size() == count) {
      // Nothing separates them (all in one degenerate half, or all across
      // the split): a subgroup of everything would only recurse forever, so
      // keep them here.
      if (children_.empty()) children_ = left.empty() ? std::move(right) : std::move(left);
    } else {
      // Beyond the book: the children that straddle the split stay here in
      // the book's version, and in a large mesh every ray that enters this
      // box tests them all. When there are several, they go into a subgroup
      // of their own too (a thin slab that divides well) -- unless every
      // child straddles (identical triangles, say): that subgroup would be
      // this group again and the recursion would never end.
      if (children_.size() > 1 && children_.size() >= threshold && children_.size() < count) {
        ShapeList straddling = std::move(children_);
        children_.clear();
        attach(subgroup_of(std::move(straddling)));
      }
      if (!left.empty()) attach(subgroup_of(std::move(left)));
      if (!right.empty()) attach(subgroup_of(std::move(right)));
    }
    // The same shapes lie below this group, so its box is unchanged.
    bounds_ = box;
  }
  for (const auto& child : children_) child->divide(threshold);
}

}  // namespace toroid
