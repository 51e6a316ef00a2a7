// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/uv_pattern.h"

#include <cmath>

namespace toroid {

Color UvCheckers::uv_pattern_at(double u, double v) const {
  const double sum = std::floor(u * width_) + std::floor(v * height_);
  return std::fmod(sum, 2.0) == 0.0 ? a_ : b_;
}

Color UvAlignCheck::uv_pattern_at(double u, double v) const {
  if (v > 0.8) {
    if (u < 0.2) return ul_;
    if (u > 0.8) return ur_;
  } else if (v < 0.2) {
    if (u < 0.2) return bl_;
    if (u > 0.8) return br_;
  }
  return main_;
}

namespace {

// round(t * (n - 1)) kept inside 0..n-1, NaN included (as 0).
int nearest_index(double t, int n) {
  const double i = std::round(t * (n - 1));
  if (!(i > 0)) return 0;
  return i >= n - 1 ? n - 1 : static_cast<int>(i);
}

}  // namespace

Color UvImage::uv_pattern_at(double u, double v) const {
  const int x = nearest_index(u, canvas_->width());
  const int y = nearest_index(1.0 - v, canvas_->height());  // row 0 is the top
  return canvas_->pixel_at(x, y);
}

}  // namespace toroid
