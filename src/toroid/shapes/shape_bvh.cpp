// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/shape_bvh.h"

#include <atomic>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

// SSE2 (every x86-64) for the two-box and two-plane tests; the scalar code
// otherwise, or when built with TOROID_SIMD=OFF (the sanitizer run in CI
// does, so that both are tested).
#if defined(__SSE2__) && !defined(TOROID_NO_SIMD)
#define TOROID_SSE2 1
#include <emmintrin.h>
#endif

#include "toroid/core/bounds.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/plane.h"
#include "toroid/shapes/shape.h"

namespace toroid {
namespace {

// Leaves hold one shape each: a shape test (a torus above all) costs far
// more than a box test, and the leaf's box is then the shape's own, so a
// missed box saves a whole shape test (CHANGELOG.md compares larger leaves).
// Above this depth the hierarchy is split by the surface area heuristic,
// below it at the median: at most 32 + 32 levels for 2^32 shapes, however
// unevenly the heuristic splits (nested shapes of growing sizes can make it
// peel them off one at a time), so the walk's stack has a bound.
constexpr int kAreaSplitDepth = 32;
constexpr int kStackSize = kAreaSplitDepth + 32;
// build()'s name for the root's own node (root_) as a parent.
constexpr std::size_t kRoot = static_cast<std::size_t>(-1);

float round_down(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) > x ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}

float round_up(double x) {
  const float f = static_cast<float>(x);
  return static_cast<double>(f) < x ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// Puts `b` into a node as its child's box, in float, rounded outwards.
template <typename Node>
void set_child_box(Node& n, int child, const BoundingBox& b) {
  const double low[3] = {b.min.x, b.min.y, b.min.z}, high[3] = {b.max.x, b.max.y, b.max.z};
  for (int a = 0; a < 3; ++a) {
    n.box[4 * a + child] = round_down(low[a]);
    n.box[4 * a + 2 + child] = round_up(high[a]);
  }
}

bool is_bounded(const BoundingBox& b) {
  return std::isfinite(b.min.x) && std::isfinite(b.min.y) && std::isfinite(b.min.z) && std::isfinite(b.max.x) &&
         std::isfinite(b.max.y) && std::isfinite(b.max.z);
}

// The ray with 1 / direction, computed once per query, and where the
// query starts: t = 0 (a ray) or -infinity (the whole line).
struct SlabRay {
  double origin[3];
  double inv[3];
  // Where in a node's boxes the side of each slab that the ray meets first
  // (near) and last (far) is (for child 0; child 1's follows): the high
  // side first when inv < 0.
  int near[3], far[3];
  double t_min;
  SlabRay(const Ray& r, double from)
      : origin{r.origin.x, r.origin.y, r.origin.z},
        inv{1.0 / r.direction.x, 1.0 / r.direction.y, 1.0 / r.direction.z},
        t_min(from) {
    for (int a = 0; a < 3; ++a) {
      const int high_first = inv[a] < 0;  // no branches: the sign is a coin toss from ray to ray
      near[a] = 4 * a + 2 * high_first;
      far[a] = 4 * a + 2 - 2 * high_first;
    }
  }
};

// Whether `s` or a shape below it refracts.
bool has_transparent(const Shape& s) {
  if (s.material().transparency > 0) return true;
  if (const auto* g = dynamic_cast<const Group*>(&s))
    for (const auto& child : g->children())
      if (has_transparent(*child)) return true;
  if (const auto* c = dynamic_cast<const Csg*>(&s)) return has_transparent(*c->left()) || has_transparent(*c->right());
  return false;
}

}  // namespace

struct ShapeBvh::Item {
  BoundingBox box;
  double centre[3];
  const Shape* shape;
};

namespace {

// Where the ray enters the box of the node's `child`, when it meets it at
// some r.t_min <= t <= t_max (for t_min = 0, the test of
// BoundingBox::intersects). Clips [t_min, t_max] by the three slabs; as in
// detail::clip_slab, a NaN bound (0 * inf: the origin on a slab plane of a
// parallel ray) leaves the interval as it was, because comparisons with NaN
// fail.
template <typename Node>
[[gnu::always_inline]] inline bool enters(const Node& n, int child, const SlabRay& r, double t_max, double& entry) {
  double tmin = r.t_min, tmax = t_max;
  for (int a = 0; a < 3; ++a) {
    const double t0 = (static_cast<double>(n.box[r.near[a] + child]) - r.origin[a]) * r.inv[a];
    const double t1 = (static_cast<double>(n.box[r.far[a] + child]) - r.origin[a]) * r.inv[a];
    tmin = t0 > tmin ? t0 : tmin;
    tmax = t1 < tmax ? t1 : tmax;
  }
  if (!(tmin <= tmax)) return false;
  entry = tmin;
  return true;
}

#if defined(TOROID_SSE2)
// Two floats side by side, child 0's and child 1's, as two doubles (exact).
__m128d load_pair(const float* p) {
  return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p))));
}
#endif

// enters() for both children of a node, one in each lane of an SSE2 register
// (every x86-64 has it): the same operations in the same order, so the same
// answers bit for bit, in fewer instructions (a walk tests both children of
// a node). MAXPD and MINPD are the scalar code's `t0 > tmin ? t0 : tmin`
// and `t1 < tmax ? t1 : tmax`, NaN included: they return the second operand
// when a comparison fails.
template <typename Node>
[[gnu::always_inline]] inline void enters_both(const Node& n, const SlabRay& r, double t_max, bool met[2],
                                               double entry[2]) {
#if defined(TOROID_SSE2)
  __m128d tmin = _mm_set1_pd(r.t_min), tmax = _mm_set1_pd(t_max);
  for (int axis = 0; axis < 3; ++axis) {
    const __m128d origin = _mm_set1_pd(r.origin[axis]), inv = _mm_set1_pd(r.inv[axis]);
    const __m128d near = load_pair(&n.box[r.near[axis]]);
    const __m128d far = load_pair(&n.box[r.far[axis]]);
    tmin = _mm_max_pd(_mm_mul_pd(_mm_sub_pd(near, origin), inv), tmin);
    tmax = _mm_min_pd(_mm_mul_pd(_mm_sub_pd(far, origin), inv), tmax);
  }
  const int le = _mm_movemask_pd(_mm_cmple_pd(tmin, tmax));
  met[0] = (le & 1) != 0;
  met[1] = (le & 2) != 0;
  _mm_storeu_pd(entry, tmin);
#else
  met[0] = enters(n, 0, r, t_max, entry[0]);
  met[1] = enters(n, 1, r, t_max, entry[1]);
#endif
}

}  // namespace

ShapeBvh::ShapeBvh(std::span<const std::shared_ptr<Shape>> shapes) : ShapeBvh(shapes, {}) {}

ShapeBvh::ShapeBvh(std::span<const std::shared_ptr<Shape>> shapes, std::span<const Tuple> point_lights)
    : size_(shapes.size()) {
  static_assert(sizeof(Node) == 64, "the index costs 64 bytes per shape (docs/performance.md, memory)");
  static std::atomic<std::uint64_t> next_serial{1};
  serial_ = next_serial++;
  std::vector<Item> items;
  items.reserve(shapes.size());
  for (const auto& s : shapes) {
    if (has_transparent(*s)) any_transparent_ = true;
    const BoundingBox b = s->parent_space_bounds();
    if (b.empty()) continue;  // nothing to hit (an empty group)
    if (!is_bounded(b)) {
      if (const auto* p = dynamic_cast<const Plane*>(s.get()))
        add_plane(*p);
      else
        unbounded_.push_back(s.get());
      continue;
    }
    Item it{b, {(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, (b.min.z + b.max.z) / 2}, s.get()};
    items.push_back(it);
  }
  if (items.empty()) return;
  const bool small = items.size() >= 3 && items.size() <= kSmallIndex;
  // Light buffers pay where a shadow ray would walk a hierarchy.
  const bool light_buffers = items.size() > kSmallIndex && !point_lights.empty();
  if (small || light_buffers) {
    // The leaves' boxes as build() gives them, in the order indexed.
    std::vector<Node>& pairs = small ? small_ : leaves_;
    for (std::size_t i = 0; i < items.size(); i += 2) {
      Node n{};  // an odd last node's second link stays 0
      for (std::size_t c = 0; c < 2 && i + c < items.size(); ++c) {
        set_child_box(n, static_cast<int>(c), items[i + c].box);
        n.link[c] = reinterpret_cast<std::uintptr_t>(items[i + c].shape);
      }
      pairs.push_back(n);
    }
  }
  if (light_buffers) {
    for (const Tuple& light : point_lights) add_light_buffer(items, light);
    // The leaves' boxes serve the buffers alone: none kept, none needed.
    if (std::none_of(light_buffers_.begin(), light_buffers_.end(), [](const LightBuffer& lb) { return lb.cells > 0; }))
      std::vector<Node>().swap(leaves_);
  }
  nodes_.reserve(items.size() - 1);
  root_.link[0] = build(items, 0, items.size(), 0, kRoot, 0);
  has_root_ = true;
  two_shapes_ = items.size() == 2;  // one interior node, whose children are the two leaves
  nodes_.shrink_to_fit();
}

namespace {

double half_area(const BoundingBox& b) {
  const double dx = b.max.x - b.min.x, dy = b.max.y - b.min.y, dz = b.max.z - b.min.z;
  return dx * dy + dy * dz + dz * dx;
}

}  // namespace

// Where to split items[begin, end): the surface area heuristic over 16 bins
// of the centres on each axis (a ray meets a box about in proportion to its
// area, so the split minimising area x count on both sides is the one
// queries cross least); the median on the widest axis when every centre
// falls in one bin, or when by_area is false.
std::size_t ShapeBvh::split(std::vector<Item>& items, std::size_t begin, std::size_t end, const BoundingBox& centres,
                            bool by_area) {
  constexpr int kBins = 16;
  const double lo[3] = {centres.min.x, centres.min.y, centres.min.z};
  const double hi[3] = {centres.max.x, centres.max.y, centres.max.z};
  double best_cost = std::numeric_limits<double>::infinity();
  int best_axis = -1, best_bin = 0;
  for (int axis = 0; by_area && axis < 3; ++axis) {
    const double extent = hi[axis] - lo[axis];
    if (!(extent > 0)) continue;
    BoundingBox box[kBins];
    std::size_t count[kBins] = {};
    for (std::size_t i = begin; i < end; ++i) {
      const int b = std::min(kBins - 1, static_cast<int>(kBins * (items[i].centre[axis] - lo[axis]) / extent));
      box[b].merge(items[i].box);
      ++count[b];
    }
    // Sweep from the right, then from the left: cost of splitting after bin k.
    double right_cost[kBins];
    BoundingBox acc;
    std::size_t n = 0;
    for (int k = kBins - 1; k > 0; --k) {
      acc.merge(box[k]);
      n += count[k];
      right_cost[k - 1] = n ? half_area(acc) * static_cast<double>(n) : 0.0;
    }
    acc = BoundingBox();
    n = 0;
    for (int k = 0; k < kBins - 1; ++k) {
      acc.merge(box[k]);
      n += count[k];
      if (n == 0 || n == end - begin) continue;
      const double cost = half_area(acc) * static_cast<double>(n) + right_cost[k];
      if (cost < best_cost) best_cost = cost, best_axis = axis, best_bin = k;
    }
  }
  if (best_axis >= 0) {
    const int axis = best_axis;
    const double extent = hi[axis] - lo[axis];
    const auto first_right = std::partition(
        items.begin() + static_cast<std::ptrdiff_t>(begin), items.begin() + static_cast<std::ptrdiff_t>(end),
        [&](const Item& it) {
          return std::min(kBins - 1, static_cast<int>(kBins * (it.centre[axis] - lo[axis]) / extent)) <= best_bin;
        });
    const auto mid = static_cast<std::size_t>(first_right - items.begin());
    if (mid > begin && mid < end) return mid;
  }
  // Median on the widest axis.
  const int axis = hi[0] - lo[0] >= hi[1] - lo[1] && hi[0] - lo[0] >= hi[2] - lo[2] ? 0
                   : hi[1] - lo[1] >= hi[2] - lo[2]                                 ? 1
                                                                                    : 2;
  const std::size_t mid = begin + (end - begin) / 2;
  std::nth_element(items.begin() + static_cast<std::ptrdiff_t>(begin), items.begin() + static_cast<std::ptrdiff_t>(mid),
                   items.begin() + static_cast<std::ptrdiff_t>(end),
                   [axis](const Item& a, const Item& b) { return a.centre[axis] < b.centre[axis]; });
  return mid;
}

void ShapeBvh::add_plane(const Plane& p) {
  if (odd_plane_ == nullptr) {
    odd_plane_ = &p;
    return;
  }
  PlanePair pair;
  for (int j = 0; j < 4; ++j) {
    pair.row[j][0] = odd_plane_->inverse_affine().m[1][j];
    pair.row[j][1] = p.inverse_affine().m[1][j];
  }
  pair.plane[0] = odd_plane_;
  pair.plane[1] = &p;
  planes_.push_back(pair);
  odd_plane_ = nullptr;
}

// Plane::find_hits for a ray in the planes' parent space, two planes at a
// time: the object-space y of the ray's origin and direction summed as
// Affine::row sums them (bit for bit what the whole transform gives), then
// Plane::hit_at. With SSE2 (every x86-64) both lanes in one register: the
// same operations, so the same t, with one division for two planes.
template <typename Visit>
bool ShapeBvh::visit_planes(const Ray& ray, Visit&& visit) const {
  const Tuple& o = ray.origin;
  const Tuple& d = ray.direction;
  // One plane alone: its own row of its inverse.
  const auto hit_alone = [&](const Plane& p, double& t) {
    const Affine& a = p.inverse_affine();
    return Plane::hit_at(a.row(1, o), a.row(1, d), t);
  };
#if defined(TOROID_SSE2)
  const __m128d ox = _mm_set1_pd(o.x), oy = _mm_set1_pd(o.y), oz = _mm_set1_pd(o.z), ow = _mm_set1_pd(o.w);
  const __m128d dx = _mm_set1_pd(d.x), dy = _mm_set1_pd(d.y), dz = _mm_set1_pd(d.z), dw = _mm_set1_pd(d.w);
  const __m128d sign = _mm_set1_pd(-0.0);
#endif
  for (const PlanePair& pair : planes_) {
    double t[2];
    bool met[2];
#if defined(TOROID_SSE2)
    const __m128d r0 = _mm_load_pd(pair.row[0]), r1 = _mm_load_pd(pair.row[1]), r2 = _mm_load_pd(pair.row[2]),
                  r3 = _mm_load_pd(pair.row[3]);
    const auto height = [&](__m128d x, __m128d y, __m128d z, __m128d w) {
      return _mm_add_pd(_mm_add_pd(_mm_add_pd(_mm_mul_pd(r0, x), _mm_mul_pd(r1, y)), _mm_mul_pd(r2, z)),
                        _mm_mul_pd(r3, w));
    };
    const __m128d origin_y = height(ox, oy, oz, ow), direction_y = height(dx, dy, dz, dw);
    // Plane::hit_at: parallel (|direction_y| < kEpsilon) misses, else
    // t = -origin_y / direction_y.
    const int parallel = _mm_movemask_pd(_mm_cmplt_pd(_mm_andnot_pd(sign, direction_y), _mm_set1_pd(kEpsilon)));
    _mm_storeu_pd(t, _mm_div_pd(_mm_xor_pd(origin_y, sign), direction_y));
    met[0] = (parallel & 1) == 0;
    met[1] = (parallel & 2) == 0;
#else
    for (int i = 0; i < 2; ++i) met[i] = hit_alone(*pair.plane[i], t[i]);
#endif
    for (int i = 0; i < 2; ++i)
      if (met[i] && visit(t[i], pair.plane[i])) return true;
  }
  double t;
  return odd_plane_ != nullptr && hit_alone(*odd_plane_, t) && visit(t, odd_plane_);
}

std::uintptr_t ShapeBvh::build(std::vector<Item>& items, std::size_t begin, std::size_t end, int depth,
                               std::size_t parent, int child) {
  depth_ = std::max(depth_, depth);
  BoundingBox box, centres;
  for (std::size_t i = begin; i < end; ++i) {
    box.merge(items[i].box);
    centres.add_point(point(items[i].centre[0], items[i].centre[1], items[i].centre[2]));
  }
  set_child_box(parent == kRoot ? root_ : nodes_[parent], child, box);
  if (end - begin == 1) {
    static_assert(alignof(Shape) > 1, "a leaf's link needs its low bit clear");
    return reinterpret_cast<std::uintptr_t>(items[begin].shape);
  }
  // Shapes whose centres coincide are split too (split() falls back on the
  // median): one shape per leaf.
  const std::size_t mid = split(items, begin, end, centres, depth < kAreaSplitDepth);
  const std::size_t index = nodes_.size();
  nodes_.push_back({});
  const std::uintptr_t first = build(items, begin, mid, depth + 1, index, 0);
  const std::uintptr_t second = build(items, mid, end, depth + 1, index, 1);
  nodes_[index].link[0] = first;
  nodes_[index].link[1] = second;
  return (static_cast<std::uintptr_t>(index) << 1) | 1;
}

// Walks the boxes the ray enters at some t_min <= t <= t_max, nearer child
// first, and calls stop(shape) for the shapes in their leaves, until it
// returns true (then so does walk). `t_max` is read again at every step:
// the caller's callback shortens it as hits come closer, and boxes waiting
// on the stack beyond it are skipped. With `any_order`, an index of two
// shapes calls stop for both, in the order they were indexed, once the ray
// enters their common box: the box of each costs about as much as a test
// of a sphere or a plane, and the common box turns away the rays that miss
// both (the queries whose answer does not depend on which shapes are asked
// first, beyond ties: the nearest hit and the shadow test).
template <typename Stop>
bool ShapeBvh::walk(const Ray& ray, double t_min, const double& t_max, bool any_order, Stop&& stop) const {
  // The root's own box first, even though its children's lie inside it:
  // most rays that miss everything miss it, and one box costs less than
  // two.
  if (!has_root_) return false;
  const SlabRay r(ray, t_min);
  double entry;
  if (!enters(root_, 0, r, t_max, entry)) return false;
  if (any_order && two_shapes_) {
    const Node& n = nodes_[0];
    return stop(reinterpret_cast<const Shape*>(n.link[0])) || stop(reinterpret_cast<const Shape*>(n.link[1]));
  }
  struct Pending {
    std::uintptr_t link;
    double entry;
  } stack[kStackSize];
  int depth = 0;
  std::uintptr_t current = root_.link[0];
  for (;;) {
    if (is_leaf(current)) {
      if (stop(reinterpret_cast<const Shape*>(current))) return true;
    } else {
      const Node& n = nodes_[current >> 1];
      std::uintptr_t a = n.link[0], b = n.link[1];
      bool met[2];
      double entry[2];
      enters_both(n, r, t_max, met, entry);
      const bool hit_a = met[0], hit_b = met[1];
      double ea = entry[0], eb = entry[1];
      if (hit_a && hit_b) {
        if (eb < ea) {
          std::swap(a, b);
          std::swap(ea, eb);
        }
        stack[depth++] = {b, eb};
        current = a;
        continue;
      }
      if (hit_a || hit_b) {
        current = hit_a ? a : b;
        continue;
      }
    }
    do {
      if (depth == 0) return false;
      --depth;
    } while (stack[depth].entry > t_max);
    current = stack[depth].link;
  }
}

// walk() for an index with small_: every leaf's box, two at a time, then
// the shapes whose box the ray enters, nearest entry first (the order
// indexed among equal entries), while the entry is within t_max, which
// stop() may shorten. It skips the interior nodes' boxes, which a small
// scene's rays mostly all enter (a room's walls have boxes as large as the
// room, and its camera is inside them).
template <typename Stop>
bool ShapeBvh::walk_small(const Ray& ray, const double& t_max, Stop&& stop) const {
  const SlabRay r(ray, 0);
  double root_entry;
  if (!enters(root_, 0, r, t_max, root_entry)) return false;
  struct Entered {
    double entry;
    const Shape* shape;
  } entered[kSmallIndex];
  int n = 0;
  for (const Node& node : small_) {
    bool met[2];
    double at[2];
    enters_both(node, r, t_max, met, at);
    for (int c = 0; c < 2; ++c) {
      if (!met[c] || node.link[c] == 0) continue;
      int i = n++;
      for (; i > 0 && entered[i - 1].entry > at[c]; --i) entered[i] = entered[i - 1];
      entered[i] = {at[c], reinterpret_cast<const Shape*>(node.link[c])};
    }
  }
  for (int i = 0; i < n && entered[i].entry <= t_max; ++i)
    if (stop(entered[i].shape)) return true;
  return false;
}

bool ShapeBvh::intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
  bool found = false;
  auto try_shape = [&](const Shape* s) {
    if (s->intersect_nearest(ray, t_max, hit)) {
      found = true;
      t_max = hit.t;
    }
    return false;  // look on: a nearer hit may follow
  };
  visit_planes(ray, [&](double t, const Plane* p) {
    if (t >= 0 && t < t_max) {
      hit = {t, p};
      t_max = t;
      found = true;
    }
    return false;
  });
  for (const Shape* s : unbounded_) try_shape(s);
  if (small_.empty())
    walk(ray, 0, t_max, true, try_shape);
  else
    walk_small(ray, t_max, try_shape);
  return found;
}

// blocks(): the planes, the other unbounded shapes, then `bounded`, which
// is handed the test of one bounded shape and asks it of those it chooses.
template <typename Bounded>
bool ShapeBvh::blocks_with(const Ray& ray, double t_max, const Shape** blocker, Bounded&& bounded) const {
  auto blocked_by = [&](const Shape* s) {
    if (!s->blocks(ray, t_max)) return false;
    if (blocker) *blocker = s;
    return true;
  };
  const bool plane_blocks = visit_planes(ray, [&](double t, const Plane* p) {
    if (!(t >= 0 && t < t_max && p->casts_shadow)) return false;
    if (blocker) *blocker = p;
    return true;
  });
  if (plane_blocks) return true;
  for (const Shape* s : unbounded_)
    if (blocked_by(s)) return true;
  return bounded(blocked_by);
}

bool ShapeBvh::blocks(const Ray& ray, double t_max, const Shape** blocker) const {
  return blocks_with(ray, t_max, blocker, [&](auto& blocked_by) {
    return small_.empty() ? walk(ray, 0, t_max, true, blocked_by) : walk_small(ray, t_max, blocked_by);
  });
}

const Intersection* ShapeBvh::intersect_up_to_hit(const Ray& ray, Intersections& xs) const {
  xs.clear();
  // The hit as hit() would pick it from the list: the first of the least
  // t >= 0, found as the list grows.
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t found = kNone;
  double t_hit = BoundingBox::kInf;
  const auto consider = [&](std::size_t i) {
    const double t = xs[i].t;
    if (t >= 0 && (found == kNone || t < t_hit)) found = i, t_hit = t;
  };
  auto add_shape = [&](const Shape* s) {
    const std::size_t first = xs.size();
    s->intersect(ray, xs);
    for (std::size_t i = first; i < xs.size(); ++i) consider(i);
    return false;
  };
  visit_planes(ray, [&](double t, const Plane* p) {
    xs.push_back({t, p});
    consider(xs.size() - 1);
    return false;
  });
  for (const Shape* s : unbounded_) add_shape(s);
  walk(ray, 0, t_hit, false, add_shape);
  return found == kNone ? nullptr : &xs[found];
}

namespace {

// How far beyond a box's directions its cells reach, in the faces' units
// (w = 1): far above the rounding of a shadow ray's direction.
constexpr double kLightBufferMargin = 1e-6;
// The most a light buffer may hold: entries per shape on average, and bytes.
constexpr std::size_t kLightBufferEntriesPerShape = 128;
constexpr std::size_t kLightBufferBytes = std::size_t{64} << 20;

// A direction's cell in a light buffer of `cells` per side of a face: the
// face of the axis where |q| is largest (2 axis, +1 for its negative side),
// then q's other two coordinates over that one, from -1 to 1, cut into
// `cells` each. Returns -1 for a direction that is zero or not finite.
int light_cell(const double q[3], int cells) {
  const double ax = std::abs(q[0]), ay = std::abs(q[1]), az = std::abs(q[2]);
  const int axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
  const double w = std::abs(q[axis]);
  if (!(w > 0 && w < std::numeric_limits<double>::infinity())) return -1;
  const double scale = 0.5 * cells / w;
  const auto to_cell = [&](double x) {
    const double c = (x + w) * scale;  // (x / w + 1) * cells / 2
    return std::clamp(static_cast<int>(c), 0, cells - 1);
  };
  const int face = 2 * axis + (q[axis] < 0);
  return (face * cells + to_cell(q[(axis + 1) % 3])) * cells + to_cell(q[(axis + 2) % 3]);
}

}  // namespace

// Each shape goes into every cell that some direction from the light to its
// box may fall in, widened by kLightBufferMargin (far more than the rounding
// of the shadow rays' directions and of the slab test); a box that holds
// the light, or nearly touches it, into every cell.
void ShapeBvh::add_light_buffer(const std::vector<Item>& items, const Tuple& light) {
  LightBuffer lb;
  const double at[3] = {light.x, light.y, light.z};
  std::copy(at, at + 3, lb.light);
  lb.cells = std::clamp(static_cast<int>(8 * std::sqrt(static_cast<double>(items.size()))), 8, 128);
  const int n = lb.cells;
  // The farthest box corner sets `reach`, and how near a box may come
  // before it goes into every cell.
  double farthest = 0;
  for (const Item& it : items)
    farthest = std::max({farthest, std::abs(it.box.min.x - at[0]), std::abs(it.box.max.x - at[0]),
                         std::abs(it.box.min.y - at[1]), std::abs(it.box.max.y - at[1]), std::abs(it.box.min.z - at[2]),
                         std::abs(it.box.max.z - at[2])});
  lb.reach = 1e6 * farthest;
  const double near = 1e-6 * farthest;
  // Calls add(cell, w) for every cell of shape k's, with w where its box
  // begins along the face's axis.
  const auto for_each_cell = [&](std::size_t k, auto&& add) {
    const BoundingBox& b = items[k].box;
    const double lo[3] = {b.min.x - at[0], b.min.y - at[1], b.min.z - at[2]};
    const double hi[3] = {b.max.x - at[0], b.max.y - at[1], b.max.z - at[2]};
    // The box's distance from the light in the maximum norm. A face's
    // directions (its pyramid) reach points whose distance is their w, so
    // the box's part in the pyramid lies at w >= the distance.
    double distance = 0;
    for (int a = 0; a < 3; ++a) distance = std::max({distance, lo[a], -hi[a]});
    const bool near_light = distance <= near;
    for (int face = 0; face < 6; ++face) {
      const int axis = face / 2;
      const double sign = face % 2 == 0 ? 1.0 : -1.0;
      const double w_lo = std::max(std::min(sign * lo[axis], sign * hi[axis]), distance);
      const double w_hi = std::max(sign * lo[axis], sign * hi[axis]);
      int range[2][2] = {{0, n - 1}, {0, n - 1}};
      if (!near_light) {
        if (w_hi < w_lo) continue;  // no part of the box in the pyramid
        // u = x / w over the box's part lies between the values at its
        // corners (monotone in x, and in w > 0).
        for (int i = 0; i < 2; ++i) {
          const int a = (axis + 1 + i) % 3;
          const double u_lo = std::min(lo[a] / w_lo, lo[a] / w_hi) - kLightBufferMargin;
          const double u_hi = std::max(hi[a] / w_lo, hi[a] / w_hi) + kLightBufferMargin;
          range[i][0] = static_cast<int>(std::clamp(std::floor((u_lo + 1) * 0.5 * n), 0.0, n - 1.0));
          range[i][1] = static_cast<int>(std::clamp(std::floor((u_hi + 1) * 0.5 * n), 0.0, n - 1.0));
          if (u_hi < -1 || u_lo > 1) range[i][1] = range[i][0] - 1;  // beside the face
        }
      }
      for (int i = range[0][0]; i <= range[0][1]; ++i)
        for (int j = range[1][0]; j <= range[1][1]; ++j)
          add(static_cast<std::size_t>((face * n + i) * n + j), near_light ? 0.0 : w_lo);
    }
  };
  // Counted, then placed, then each cell sorted by w.
  const std::size_t cell_count = static_cast<std::size_t>(6 * n * n);
  lb.first.assign(cell_count + 1, 0);
  for (std::size_t k = 0; k < items.size(); ++k) for_each_cell(k, [&](std::size_t c, double) { ++lb.first[c + 1]; });
  for (std::size_t c = 0; c < cell_count; ++c) lb.first[c + 1] += lb.first[c];
  // A light whose cells would hold too much keeps no buffer: its shadow rays
  // walk the index. Too much is more than the walk would test: many shapes
  // near the light, each in many cells; or shapes that fill few cells, many
  // to a cell (a light far from them all), more on average than the
  // hierarchy has levels (a cell's boxes are tested one at a time in turn,
  // the walk's two at a time, a level at a time).
  const std::size_t entries = lb.first[cell_count];
  std::size_t filled = 0;
  for (std::size_t c = 0; c < cell_count; ++c) filled += lb.first[c + 1] > lb.first[c];
  if (entries > kLightBufferEntriesPerShape * items.size() ||
      entries * sizeof(LightBuffer::Entry) > kLightBufferBytes ||
      static_cast<double>(entries) > std::log2(static_cast<double>(items.size())) * static_cast<double>(filled)) {
    light_buffers_.push_back({});
    return;
  }
  lb.leaf.resize(entries);
  std::vector<std::uint32_t> next(lb.first.begin(), lb.first.end() - 1);
  for (std::size_t k = 0; k < items.size(); ++k)
    for_each_cell(k, [&](std::size_t c, double w) {
      lb.leaf[next[c]++] = {round_down(w), static_cast<std::uint32_t>(k)};
    });
  for (std::size_t c = 0; c < cell_count; ++c)
    std::sort(lb.leaf.begin() + lb.first[c], lb.leaf.begin() + lb.first[c + 1],
              [](const LightBuffer::Entry& x, const LightBuffer::Entry& y) { return x.w < y.w; });
  light_buffers_.push_back(std::move(lb));
}

bool ShapeBvh::blocks_towards_light(std::size_t light, const Tuple& position, const Ray& ray, double t_max,
                                    const Shape** blocker) const {
  if (light >= light_buffers_.size()) return blocks(ray, t_max, blocker);
  const LightBuffer& lb = light_buffers_[light];
  if (lb.cells == 0 || position.x != lb.light[0] || position.y != lb.light[1] || position.z != lb.light[2])
    return blocks(ray, t_max, blocker);
  // The direction from the light to the ray's origin, and the origin's
  // distance from the light along the face's axis (the largest |q|).
  const double q[3] = {-ray.direction.x, -ray.direction.y, -ray.direction.z};
  const double w = std::max({std::abs(q[0]), std::abs(q[1]), std::abs(q[2])});
  const int cell = w <= lb.reach ? light_cell(q, lb.cells) : -1;
  if (cell < 0) return blocks(ray, t_max, blocker);
  const SlabRay r(ray, 0);
  const auto c = static_cast<std::size_t>(cell);
  // The shadow ray's points lie at most that far from the light: boxes that
  // begin beyond it are left.
  const double w_origin = (1 + 1e-9) * w;
  return blocks_with(ray, t_max, blocker, [&](auto& blocked_by) {
    for (std::uint32_t i = lb.first[c]; i < lb.first[c + 1] && lb.leaf[i].w <= w_origin; ++i) {
      const std::uint32_t k = lb.leaf[i].leaf;
      const Node& pair = leaves_[k / 2];
      const int child = static_cast<int>(k % 2);
      double entry;
      if (enters(pair, child, r, t_max, entry) && blocked_by(reinterpret_cast<const Shape*>(pair.link[child])))
        return true;
    }
    return false;
  });
}

std::size_t ShapeBvh::bytes() const {
  std::size_t light_buffers = 0;
  for (const LightBuffer& lb : light_buffers_)
    light_buffers += lb.first.capacity() * sizeof(std::uint32_t) + lb.leaf.capacity() * sizeof(LightBuffer::Entry);
  return (nodes_.capacity() + small_.capacity() + leaves_.capacity()) * sizeof(Node) +
         planes_.capacity() * sizeof(PlanePair) + unbounded_.capacity() * sizeof(const Shape*) + light_buffers;
}

}  // namespace toroid
