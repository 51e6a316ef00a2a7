#include "toroid/shapes/shape.h"

namespace toroid {

void Shape::set_transform(const Matrix4& m) {
  transform_ = m;
  inverse_ = inverse(m);
  inverse_transpose_ = transpose(inverse_);
  bounds_changed();
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

BoundingBox Shape::parent_space_bounds() const { return ::toroid::transform(bounds(), transform_); }

}  // namespace toroid
