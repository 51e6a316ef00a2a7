// SPDX-License-Identifier: Apache-2.0
// A pinhole camera (RTC chapter 7): the canvas lies one unit in front of the
// eye, along -z of the camera's space.
#pragma once

#include "toroid/core/canvas.h"
#include "toroid/core/ray.h"
#include "toroid/math/matrix.h"

namespace toroid {

struct World;

class Camera {
 public:
  // hsize x vsize pixels; field_of_view (radians) spans the longer side.
  Camera(int hsize, int vsize, double field_of_view);

  int hsize() const { return hsize_; }
  int vsize() const { return vsize_; }
  double field_of_view() const { return field_of_view_; }
  double pixel_size() const { return pixel_size_; }
  double half_width() const { return half_width_; }
  double half_height() const { return half_height_; }

  // World-to-camera (e.g. view_transform). Precondition: is_invertible(m).
  const Matrix4& transform() const { return transform_; }
  const Matrix4& inverse_transform() const { return inverse_; }
  void set_transform(const Matrix4& m);

  // The ray through the centre of pixel (px, py).
  Ray ray_for_pixel(int px, int py) const { return ray_for_pixel(px, py, 0.5, 0.5); }
  // The ray through canvas position (px + dx, py + dy), dx, dy in [0, 1):
  // sub-pixel samples for anti-aliasing.
  Ray ray_for_pixel(int px, int py, double dx, double dy) const;

 private:
  int hsize_;
  int vsize_;
  double field_of_view_;
  double half_width_ = 0;
  double half_height_ = 0;
  double pixel_size_ = 0;
  Matrix4 transform_ = Matrix4::identity();
  Matrix4 inverse_ = Matrix4::identity();
  Tuple origin_ = point(0, 0, 0);  // inverse_ * point(0, 0, 0): every ray's origin
};

// One ray through the centre of each pixel, serially.
Canvas render(const Camera& camera, const World& world);

}  // namespace toroid
