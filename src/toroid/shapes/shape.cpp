#include "toroid/shapes/shape.h"

#include <algorithm>

namespace toroid {

void Shape::set_transform(const Matrix4& m) {
  transform_ = m;
  inverse_ = inverse(m);
  inverse_transpose_ = transpose(inverse_);
}

Tuple Shape::world_to_object(const Tuple& world_point) const {
  const Tuple p = parent ? parent->world_to_object(world_point) : world_point;
  return inverse_ * p;
}

Tuple Shape::normal_to_world(const Tuple& object_normal) const {
  Tuple n = inverse_transpose_ * object_normal;
  n.w = 0;
  n = normalize(n);
  return parent ? parent->normal_to_world(n) : n;
}

Tuple Shape::normal_at(const Tuple& world_point, const Intersection& hit) const {
  return normal_to_world(local_normal_at(world_to_object(world_point), hit));
}

BoundingBox Shape::parent_space_bounds() const {
  const BoundingBox b = bounds();
  BoundingBox r;
  // Transform all eight corners; the box of the results bounds the shape.
  for (int i = 0; i < 8; ++i) {
    const Tuple c = transform_ * point(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y,
                                       i & 4 ? b.max.z : b.min.z);
    r.min = point(std::min(r.min.x, c.x), std::min(r.min.y, c.y), std::min(r.min.z, c.z));
    r.max = point(std::max(r.max.x, c.x), std::max(r.max.y, c.y), std::max(r.max.z, c.z));
  }
  return r;
}

}  // namespace toroid
