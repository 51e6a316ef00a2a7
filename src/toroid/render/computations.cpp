// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/computations.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "toroid/shapes/csg.h"
#include "toroid/shapes/shape.h"

namespace toroid {

namespace {

bool same(const Intersection& a, const Intersection& b) { return a.t == b.t && a.object == b.object; }

// The containers algorithm: walk the sorted intersections, tracking which
// objects the ray is inside (in the order entered), up to the hit. Every
// refracting hit asks: the list of objects lives on the stack while it is
// short (it never holds more objects than xs holds intersections). Sets
// *before, if given, to the list just before the hit.
void refractive_indices(const Intersection& hit, std::span<const Intersection> xs, Computations& comps,
                        Containers* before) {
  constexpr std::size_t kOnStack = 16;
  const Shape* on_stack[kOnStack];
  thread_local std::vector<const Shape*> on_heap;
  const Shape** containers = on_stack;
  if (xs.size() > kOnStack) {
    on_heap.resize(xs.size());
    containers = on_heap.data();
  }
  std::size_t inside = 0;
  const auto innermost = [&] { return inside == 0 ? 1.0 : containers[inside - 1]->material().refractive_index; };
  for (const Intersection& x : xs) {
    const bool is_hit = same(x, hit);
    if (is_hit) {
      comps.n1 = innermost();
      if (before != nullptr) {
        *before = inside <= Containers::kCapacity ? Containers{} : Containers::unknown();
        for (std::size_t i = 0; i < inside && before->known(); ++i) {
          if (!carried_in_containers(*containers[i])) *before = Containers::unknown();
          before->cross(containers[i]);
        }
      }
    }
    std::size_t i = 0;
    while (i < inside && containers[i] != x.object) ++i;
    if (i < inside) {  // leaving it: the others keep their order
      std::copy(containers + i + 1, containers + inside, containers + i);
      --inside;
    } else {
      containers[inside++] = x.object;
    }
    if (is_hit) {
      comps.n2 = innermost();
      return;
    }
  }
}

double max_abs(const Tuple& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

// Half the thinnest finite, non-zero side of the shape's object-space box, in
// world units: a lower bound (Shape::parent_space_half_thickness). 0 when no
// side is finite and non-zero (a plane).
double world_half_thickness(const Shape& shape) {
  // Asked at every hit: a shape at the top level answers from its own inverse.
  if (shape.parent == nullptr) return shape.parent_space_half_thickness();
  const double half = shape.half_thickness();
  if (half == 0) return 0;
  Matrix4 world_to_object = shape.inverse_transform();
  for (const Shape* s = shape.parent; s != nullptr; s = s->parent)
    world_to_object = world_to_object * s->inverse_transform();
  return half / linear_frobenius_norm(world_to_object.m);
}

// Everything but n1 and n2 (left at 1). Built from locals in one go: the
// result lives in the caller's frame, and filling a default-initialised one
// field by field stores most of it twice.
Computations prepare(const Intersection& hit, const Ray& ray) {
  const Tuple point = ray.position(hit.t);
  const Tuple eyev = -ray.direction;
  Tuple normalv = hit.object->normal_at(point, hit);
  const bool inside = dot(normalv, eyev) < 0;
  if (inside) normalv = -normalv;
  const double bias = surface_bias(hit, ray);
  return {.t = hit.t,
          .object = hit.object,
          .point = point,
          .eyev = eyev,
          .normalv = normalv,
          .inside = inside,
          .over_point = point + normalv * bias,
          .under_point = point - normalv * bias,
          .reflectv = reflect(ray.direction, normalv)};
}

}  // namespace

double surface_bias(const Intersection& hit, const Ray& ray) {
  const double magnitude = max_abs(ray.origin) + std::abs(hit.t) * max_abs(ray.direction);
  return std::max(kBiasPerThickness * world_half_thickness(*hit.object), kBiasPerMagnitude * magnitude);
}

Computations prepare_computations(const Intersection& hit, const Ray& ray, const Intersections& xs) {
  Computations comps = prepare(hit, ray);
  refractive_indices(hit, xs, comps, nullptr);
  return comps;
}

Computations prepare_computations(const Intersection& hit, const Ray& ray, const Intersections& xs,
                                  Containers& before) {
  Computations comps = prepare(hit, ray);
  refractive_indices(hit, xs, comps, &before);
  return comps;
}

Computations prepare_computations(const Intersection& hit, const Ray& ray, const Containers& before) {
  Computations comps = prepare(hit, ray);
  comps.n1 = before.innermost_index();
  comps.n2 = before.innermost_index_after(hit.object);
  return comps;
}

bool carried_in_containers(const Shape& shape) {
  if (!shape.closed_surface()) return false;
  for (const Shape* s = shape.parent; s != nullptr; s = s->parent)
    if (dynamic_cast<const Csg*>(s) != nullptr) return false;
  return true;
}

void Containers::cross(const Shape* object) {
  if (!known_) return;
  std::size_t i = 0;
  while (i < count_ && objects_[i] != object) ++i;
  if (i < count_) {  // leaving it: the others keep their order
    std::copy(objects_ + i + 1, objects_ + count_, objects_ + i);
    --count_;
  } else if (count_ < kCapacity) {
    objects_[count_++] = object;
  } else {
    known_ = false;
  }
}

double Containers::innermost_index() const {
  return count_ == 0 ? 1.0 : objects_[count_ - 1]->material().refractive_index;
}

double Containers::innermost_index_after(const Shape* object) const {
  std::size_t i = 0;
  while (i < count_ && objects_[i] != object) ++i;
  if (i == count_) return object->material().refractive_index;  // entering it: it is the innermost
  // Leaving it: the innermost of the others.
  const std::size_t others = count_ - 1;
  if (others == 0) return 1.0;
  return objects_[i == others ? others - 1 : others]->material().refractive_index;
}

Computations prepare_computations(const Intersection& hit, const Ray& ray) {
  Computations comps = prepare(hit, ray);
  // The containers of the list {hit}: none before it, its object after.
  comps.n1 = 1.0;
  comps.n2 = hit.object->material().refractive_index;
  return comps;
}

double schlick(const Computations& comps) {
  double cos = dot(comps.eyev, comps.normalv);
  if (comps.n1 > comps.n2) {
    const double n = comps.n1 / comps.n2;
    const double sin2_t = n * n * (1.0 - cos * cos);
    if (sin2_t > 1.0) return 1.0;
    cos = std::sqrt(1.0 - sin2_t);
  }
  const double r = (comps.n1 - comps.n2) / (comps.n1 + comps.n2);
  const double r0 = r * r;
  // (1 - cos)^5 by three products rather than a call to std::pow (they
  // agree to a few ulps; the call is a large share of a glass hit's cost).
  const double x = 1 - cos;
  const double x2 = x * x;
  return r0 + (1 - r0) * (x2 * x2 * x);
}

}  // namespace toroid
