// SPDX-License-Identifier: Apache-2.0
// A flat bounding volume hierarchy over a list of shapes that share one
// space (the world's top level), for the renderer's two queries: the nearest
// hit and "is anything in the way" (shadow rays). The book's Group::divide
// builds its hierarchy out of groups inside the scene graph; this one sits
// beside the scene graph, so shapes keep their parents and the world its
// list. Shapes whose box is unbounded are kept aside and always tested;
// planes among them by their height alone (one row of the inverse
// transform, not the whole ray: every ray tests every floor and wall).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "toroid/core/bounds.h"
#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"

namespace toroid {

class Plane;
class Shape;

class ShapeBvh {
 public:
  ShapeBvh() = default;
  // Indexes the shapes' parent-space boxes as they are now: rebuild after
  // adding, removing or moving shapes. The shapes must outlive the index.
  explicit ShapeBvh(std::span<const std::shared_ptr<Shape>> shapes);
  // The same, with a light buffer for each point light at `point_lights`
  // (see blocks_towards_light).
  ShapeBvh(std::span<const std::shared_ptr<Shape>> shapes, std::span<const Tuple> point_lights);

  // How many shapes it indexes (bounded and unbounded).
  std::size_t size() const { return size_; }
  // Different for every index built (0 for an empty one): lets per-thread
  // caches of shape pointers tell that the index they came from is gone.
  std::uint64_t serial() const { return serial_; }

  // Shape::intersect_nearest over every indexed shape.
  bool intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const;
  // Shape::blocks over every indexed shape; sets *blocker (when given) to
  // the indexed shape that blocks.
  bool blocks(const Ray& ray, double t_max, const Shape** blocker = nullptr) const;

  // blocks() for a shadow ray from ray.origin towards the point light at
  // `position`, the constructor's light number `light`: ray.direction is
  // `position` minus the origin, and t_max at most 1. The same answer, from
  // the light buffer (Haines and Greenberg 1986) where the index has one:
  // the directions from the light, cut into cells on the six faces of a
  // cube around it, each listing the shapes whose box some direction of the
  // cell meets. A shadow ray tests the boxes of its cell's shapes alone,
  // rather than walking the hierarchy from its root.
  // A light that has moved since (or was not given) is answered by blocks().
  bool blocks_towards_light(std::size_t light, const Tuple& position, const Ray& ray, double t_max,
                            const Shape** blocker = nullptr) const;

  // Whether some indexed shape, or a shape below one, is transparent (has
  // refraction): then shading needs intersect_up_to_hit.
  bool any_transparent() const { return any_transparent_; }
  // Replaces xs with the intersections, in no particular order, of the
  // shapes whose box the ray meets (t >= 0) before the nearest hit (t >= 0):
  // every intersection up to the hit of the shapes around and ahead of the
  // origin, negative t included, which is what the containers algorithm
  // (prepare_computations) reads, and perhaps some beyond the hit (drop
  // those before sorting: a room's walls put six intersections on every
  // line). Shapes wholly behind the origin are left out: a closed surface
  // there is entered and left, and changes no container (the book lists
  // them, at a cost and to no effect).
  // Returns the hit in xs, the one hit(xs) names, or nullptr when there is
  // none.
  const Intersection* intersect_up_to_hit(const Ray& ray, Intersections& xs) const;

  // Levels of nodes below the root (0 for one shape or none): at most 64,
  // the bound of the walk's stack.
  int depth() const { return depth_; }

  // Memory the index holds (nodes and the unbounded shapes' lists), for the
  // memory report.
  std::size_t bytes() const;

 private:
  // An interior node: the boxes of its two children, in float, rounded
  // outwards, laid out so that one load gives one side of one slab for both
  // children (the walk tests the two at once), and a link to each child. A
  // link is a leaf's shape (its address: shapes are aligned, so the low bit
  // is clear) or 2 * (index of an interior node) + 1. Every leaf holds one
  // shape, and there is one interior node fewer than shapes: 64 bytes of
  // index per shape (docs/performance.md).
  struct Node {
    float box[12];  // box[4 * axis + 2 * side + child]: side 0 low, 1 high
    std::uintptr_t link[2];
  };
  static bool is_leaf(std::uintptr_t link) { return (link & 1) == 0; }
  struct Item;

  static std::size_t split(std::vector<Item>& items, std::size_t begin, std::size_t end, const BoundingBox& centres,
                           bool by_area);
  // Builds the hierarchy of items[begin, end) and returns its link; puts its
  // box in `child` of `parent`.
  std::uintptr_t build(std::vector<Item>& items, std::size_t begin, std::size_t end, int depth, std::size_t parent,
                       int child);
  template <typename Stop>
  bool walk(const Ray& ray, double t_min, const double& t_max, bool any_order, Stop&& stop) const;
  template <typename Stop>
  bool walk_small(const Ray& ray, const double& t_max, Stop&& stop) const;
  template <typename Bounded>
  bool blocks_with(const Ray& ray, double t_max, const Shape** blocker, Bounded&& bounded) const;

  // Unbounded planes, two at a time, by the one row of each one's inverse
  // transform that gives a point's object-space height (copied here: every
  // query tests every plane and reads nothing else of it). An odd plane out
  // is tested alone, last (the order decides ties).
  struct PlanePair {
    alignas(16) double row[4][2];  // row[j][lane]: column j of the inverse's y row
    const Plane* plane[2];
  };
  void add_plane(const Plane& p);
  // Calls visit(t, plane) for every plane the ray's line meets, in the
  // order they were indexed, until it returns true (then so does this).
  template <typename Visit>
  bool visit_planes(const Ray& ray, Visit&& visit) const;

  std::vector<Node> nodes_;  // interior nodes
  // The root's box and link, as child 0 of a node of its own (child 1
  // unused); has_root_ is false when nothing bounded is indexed.
  Node root_{};
  bool has_root_ = false;
  bool two_shapes_ = false;  // two bounded shapes: see walk
  // An index of 3 to kSmallIndex bounded shapes also keeps their leaves'
  // boxes two to a node, in the order the shapes were indexed (an odd last
  // node's second link is 0), for walk_small.
  static constexpr std::size_t kSmallIndex = 8;
  std::vector<Node> small_;
  // The light buffers: the leaves' boxes two to a node in the order the
  // shapes were indexed (as small_ holds them), and per point light the
  // shapes of each cell, by their place in that order.
  struct LightBuffer {
    double light[3] = {};
    int cells = 0;  // per side of a face; 0 where the light has no buffer
    // Directions longer than this (from shading points far beyond every
    // box, whose rounding could move a ray across a cell) walk the index.
    double reach = 0;
    // A shape of a cell: where its box begins along the face's axis (w,
    // rounded down), and its place among the leaves.
    struct Entry {
      float w;
      std::uint32_t leaf;
    };
    std::vector<std::uint32_t> first;  // cell c's shapes: leaf[first[c]] to leaf[first[c + 1] - 1], by w
    std::vector<Entry> leaf;
  };
  void add_light_buffer(const std::vector<Item>& items, const Tuple& light);
  std::vector<Node> leaves_;
  std::vector<LightBuffer> light_buffers_;
  std::vector<PlanePair> planes_;        // unbounded planes, tested by every query
  const Plane* odd_plane_ = nullptr;     // the last of an odd number of them
  std::vector<const Shape*> unbounded_;  // other unbounded shapes, likewise
  std::size_t size_ = 0;
  int depth_ = 0;
  std::uint64_t serial_ = 0;
  bool any_transparent_ = false;
};

}  // namespace toroid
