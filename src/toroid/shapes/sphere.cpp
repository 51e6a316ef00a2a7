// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/sphere.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace toroid {

Tuple Sphere::local_normal_at(const Tuple& p, const Intersection&) const { return vector(p.x, p.y, p.z); }

void Sphere::transform_changed() {
  // The inverse's linear part L is a similarity when its rows are
  // orthogonal and of one length, 1 / radius (L L^T = I / radius^2), to
  // within a few roundings (a rotation by a rounded angle is orthogonal to
  // within a few eps): then the unit sphere maps onto the sphere of that
  // radius about the image of its centre.
  const Affine& inv = inverse_affine();
  parent_space_half_ = Primitive::parent_space_half_thickness();
  double gram[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      gram[i][j] = inv.m[i][0] * inv.m[j][0] + inv.m[i][1] * inv.m[j][1] + inv.m[i][2] * inv.m[j][2];
  const double k = gram[0][0];
  const double tolerance = 64 * std::numeric_limits<double>::epsilon() * k;
  similarity_ = k > 0 && std::isfinite(k);
  for (int i = 0; i < 3 && similarity_; ++i)
    for (int j = 0; j < 3; ++j)
      if (std::abs(gram[i][j] - (i == j ? k : 0.0)) > tolerance) similarity_ = false;
  if (!similarity_) return;
  const Matrix4 forward = transform();
  centre_ = point(forward.m[0][3], forward.m[1][3], forward.m[2][3]);
  radius_ = 1 / std::sqrt(k);
  radius2_ = radius_ * radius_;
  inverse_radius_ = 1 / radius_;
}

bool Sphere::intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
  if (!similarity_) return Primitive::intersect_nearest(ray, t_max, hit);
  HitSlots slots;
  return nearest_in(slots.at, hits_in_parent_space(ray, slots.at, true), t_max, hit);
}

bool Sphere::blocks(const Ray& ray, double t_max) const {
  if (!similarity_) return Primitive::blocks(ray, t_max);
  HitSlots slots;
  return casts_shadow && any_in(slots.at, hits_in_parent_space(ray, slots.at, true), t_max);
}

void Sphere::intersect(const Ray& ray, Intersections& xs) const {
  if (!similarity_) return Primitive::intersect(ray, xs);
  HitSlots slots;
  append(slots.at, hits_in_parent_space(ray, slots.at, false), xs);
}

Tuple Sphere::normal_at(const Tuple& world_point, const Intersection& hit) const {
  if (!similarity_ || parent != nullptr) return Shape::normal_at(world_point, hit);
  return (world_point - centre_) * inverse_radius_;
}

BoundingBox Sphere::parent_space_bounds() const {
  if (!similarity_) return Shape::parent_space_bounds();
  const double centre[3] = {centre_.x, centre_.y, centre_.z};
  const double half[3] = {radius_, radius_, radius_};
  return padded_box(centre, half);
}

std::shared_ptr<Sphere> glass_sphere() {
  auto s = std::make_shared<Sphere>();
  Material glass;
  glass.transparency = 1.0;
  glass.refractive_index = 1.5;
  s->set_material(glass);
  return s;
}

}  // namespace toroid
