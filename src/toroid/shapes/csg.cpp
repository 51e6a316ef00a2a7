// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/csg.h"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "toroid/shapes/group.h"

namespace toroid {

namespace {

// One closed piece of an operand along a ray: a primitive, or the outermost
// CSG between a primitive and the CSG being filtered (its surface is what
// that CSG kept, closed when its operands are).
struct Piece {
  const Shape* shape;
  std::uint32_t hits;  // how many of the list's intersections lie on it
  bool left;           // whether it is in the left operand
  bool inside;         // whether the ray is inside it, so far along the list
};

// Room for n elements: N in the object (no allocation for the usual few
// hits), more from the heap.
template <typename T, std::size_t N>
class Scratch {
 public:
  explicit Scratch(std::size_t n) : data_(inline_) {
    if (n > N) {
      heap_.resize(n);
      data_ = heap_.data();
    }
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  T& operator[](std::size_t i) { return data_[i]; }

 private:
  T inline_[N];
  std::vector<T> heap_;
  T* data_;
};

constexpr std::size_t kInlineHits = 32;

}  // namespace

bool intersection_allowed(CsgOp op, bool lhit, bool inl, bool inr) {
  switch (op) {
    case CsgOp::Union: return (lhit && !inr) || (!lhit && !inl);
    case CsgOp::Intersection: return (lhit && inr) || (!lhit && inl);
    case CsgOp::Difference: return (lhit && !inr) || (!lhit && inl);
  }
  return false;
}

Csg::Csg(CsgOp op, std::shared_ptr<Shape> left, std::shared_ptr<Shape> right)
    : op_(op),
      left_(std::move(left)),
      right_(std::move(right)),
      left_is_csg_(dynamic_cast<const Csg*>(left_.get()) != nullptr),
      right_is_csg_(dynamic_cast<const Csg*>(right_.get()) != nullptr),
      one_piece_each_(dynamic_cast<const Group*>(left_.get()) == nullptr &&
                      dynamic_cast<const Group*>(right_.get()) == nullptr) {
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

// The book's rule: one flag per operand, flipped at each of its crossings.
void Csg::filter_one_piece_each(Intersections& xs, std::size_t first) const {
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

bool Csg::includes(const Shape* other) const { return is_within(other, *this); }

void Csg::divide(std::size_t threshold) {
  left_->divide(threshold);
  right_->divide(threshold);
}

void Csg::filter_intersections(Intersections& xs, std::size_t first) const {
  if (one_piece_each_) {
    filter_one_piece_each(xs, first);
    return;
  }
  const std::size_t n = xs.size() - first;
  Scratch<Piece, kInlineHits> pieces(n);            // the distinct pieces, first seen first
  Scratch<std::uint32_t, kInlineHits> piece_of(n);  // each intersection's piece
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // Climb from the intersection's primitive to the operand it lies in,
    // noting the outermost CSG on the way.
    const Shape* piece = xs[first + i].object;
    const Shape* s = piece;
    if (s != nullptr)
      while (s->parent != nullptr && s->parent != this) {
        s = s->parent;
        if (s->parent != this && dynamic_cast<const Csg*>(s) != nullptr) piece = s;
      }
    const bool lhit = s != nullptr && s == left_.get();
    if ((lhit && left_is_csg_) || (s != nullptr && s == right_.get() && right_is_csg_)) piece = s;
    std::size_t k = 0;
    while (k < count && pieces[k].shape != piece) ++k;
    if (k == count) pieces[count++] = Piece{piece, 0, lhit, false};
    ++pieces[k].hits;
    piece_of[i] = static_cast<std::uint32_t>(k);
  }
  // An operand is inside while the ray is inside any of its pieces, so that
  // overlapping children of a group act as their union (the book keeps one
  // flag per operand and flips it at every crossing, which takes the second
  // of two overlapping spheres' entries for an exit). A piece crossed an
  // even number of times toggles its own state; one crossed an odd number
  // of times (a triangle of a mesh, a plane) is a part of an open surface,
  // and those share one flag per operand that flips at each of their
  // crossings, as in the book. A crossing that leaves its operand's state as
  // it was lies inside the operand (a sphere's surface within another
  // sphere of the group) and is dropped; the others are judged by the
  // book's rule. Where the pieces of an operand do not overlap, at most one
  // of its states is set at a time, every crossing changes it, and this is
  // the book's rule.
  bool open_inside[2] = {false, false};  // indexed by lhit
  int closed_inside[2] = {0, 0};         // how many closed pieces the ray is inside, by lhit
  const auto inside = [&](bool left) { return open_inside[left] || closed_inside[left] > 0; };
  std::size_t kept = first;
  for (std::size_t i = 0; i < n; ++i) {
    Piece& p = pieces[piece_of[i]];
    const bool inl = inside(true), inr = inside(false);
    if (p.hits % 2 != 0) {
      open_inside[p.left] = !open_inside[p.left];
    } else {
      p.inside = !p.inside;
      closed_inside[p.left] += p.inside ? 1 : -1;
    }
    const bool crosses = inside(p.left) != (p.left ? inl : inr);
    if (crosses && intersection_allowed(op_, p.left, inl, inr)) xs[kept++] = xs[first + i];
  }
  xs.resize(kept);
}

}  // namespace toroid
