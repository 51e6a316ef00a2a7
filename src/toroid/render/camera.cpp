// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/camera.h"

#include <cmath>

#include "toroid/render/world.h"

namespace toroid {

Camera::Camera(int hsize, int vsize, double field_of_view)
    : hsize_(hsize), vsize_(vsize), field_of_view_(field_of_view) {
  const double half_view = std::tan(field_of_view / 2);
  const double aspect = static_cast<double>(hsize) / static_cast<double>(vsize);
  if (aspect >= 1) {
    half_width_ = half_view;
    half_height_ = half_view / aspect;
  } else {
    half_width_ = half_view * aspect;
    half_height_ = half_view;
  }
  pixel_size_ = half_width_ * 2 / hsize;
}

void Camera::set_transform(const Matrix4& m) {
  transform_ = m;
  inverse_ = inverse(m);
  origin_ = inverse_ * point(0, 0, 0);
}

Ray Camera::ray_for_pixel(int px, int py, double dx, double dy) const {
  // Offsets from the canvas edge to the sample, then to world space on the
  // canvas at z = -1 (the camera looks towards -z; +x is to the left).
  const double xoffset = (px + dx) * pixel_size_;
  const double yoffset = (py + dy) * pixel_size_;
  const double world_x = half_width_ - xoffset;
  const double world_y = half_height_ - yoffset;
  const Tuple pixel = inverse_ * point(world_x, world_y, -1);
  return Ray{origin_, normalize(pixel - origin_)};
}

Canvas render(const Camera& camera, const World& world) {
  Canvas image(camera.hsize(), camera.vsize());
  for (int y = 0; y < camera.vsize(); ++y)
    for (int x = 0; x < camera.hsize(); ++x) image.write_pixel(x, y, color_at(world, camera.ray_for_pixel(x, y)));
  return image;
}

}  // namespace toroid
