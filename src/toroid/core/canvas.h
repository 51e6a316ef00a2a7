// SPDX-License-Identifier: Apache-2.0
// A width x height grid of linear colours (RTC chapter 2) and its PPM form.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "toroid/math/color.h"

namespace toroid {

class Canvas {
 public:
  // Every pixel starts black. Precondition: width, height >= 0.
  Canvas(int width, int height);

  int width() const { return width_; }
  int height() const { return height_; }

  // Precondition: 0 <= x < width, 0 <= y < height (y grows downwards).
  Color pixel_at(int x, int y) const { return pixels_[index(x, y)]; }
  void write_pixel(int x, int y, const Color& c) { pixels_[index(x, y)] = c; }

  // Row-major pixels, top row first: for image writers.
  const std::vector<Color>& pixels() const { return pixels_; }

 private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }

  int width_;
  int height_;
  std::vector<Color> pixels_;
};

// Plain PPM ("P3", maximum 255) exactly as the book specifies: each component
// clamped to [0, 1], scaled by 255 and rounded (no gamma); lines of at most
// 70 characters; a new line for every canvas row; a trailing newline.
std::string canvas_to_ppm(const Canvas& canvas);

}  // namespace toroid
