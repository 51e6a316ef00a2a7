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

#include "toroid/render/intersection.h"
#include "toroid/render/ray.h"
#include "toroid/shapes/bounds.h"

namespace toroid {

class Plane;
class Shape;

class ShapeBvh {
 public:
  ShapeBvh() = default;
  // Indexes the shapes' parent-space boxes as they are now: rebuild after
  // adding, removing or moving shapes. The shapes must outlive the index.
  explicit ShapeBvh(std::span<const std::shared_ptr<Shape>> shapes);

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
  // them; they cost cover.yml 13% of its time).
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
  // Boxes in float, rounded outwards, so that a node takes 32 bytes. Every
  // leaf holds one shape, named by the node itself (no list of shapes
  // beside the nodes: 64 bytes of index per shape, docs/performance.md).
  struct Node {
    float box[6];  // low x, y, z, then high x, y, z
    // A leaf: its shape's address. An interior node: 2 * (index of its
    // second child) + 1; the first child follows the node. Shapes are
    // aligned, so the low bit tells the two apart.
    std::uintptr_t link;
    bool is_leaf() const { return (link & 1) == 0; }
    const Shape* shape() const { return reinterpret_cast<const Shape*>(link); }
    std::uint32_t second_child() const { return static_cast<std::uint32_t>(link >> 1); }
  };
  struct Item;

  static std::size_t split(std::vector<Item>& items, std::size_t begin, std::size_t end, const BoundingBox& centres,
                           bool by_area);
  std::uint32_t build(std::vector<Item>& items, std::size_t begin, std::size_t end, int depth);
  template <typename Stop>
  bool walk(const Ray& ray, double t_min, const double& t_max, Stop&& stop) const;

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

  std::vector<Node> nodes_;
  std::vector<PlanePair> planes_;        // unbounded planes, tested by every query
  const Plane* odd_plane_ = nullptr;     // the last of an odd number of them
  std::vector<const Shape*> unbounded_;  // other unbounded shapes, likewise
  std::size_t size_ = 0;
  int depth_ = 0;
  std::uint64_t serial_ = 0;
  bool any_transparent_ = false;
};

}  // namespace toroid
