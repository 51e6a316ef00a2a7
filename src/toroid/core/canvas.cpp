// SPDX-License-Identifier: Apache-2.0
#include "toroid/core/canvas.h"

#include <algorithm>
#include <cmath>

namespace toroid {

Canvas::Canvas(int width, int height)
    : width_(width),
      height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), kBlack) {}

namespace {

int to_byte(double component) { return static_cast<int>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0)); }

constexpr std::size_t kMaxPpmLine = 70;

}  // namespace

std::string canvas_to_ppm(const Canvas& canvas) {
  std::string ppm = "P3\n" + std::to_string(canvas.width()) + " " + std::to_string(canvas.height()) + "\n255\n";
  for (int y = 0; y < canvas.height(); ++y) {
    std::size_t line_length = 0;
    for (int x = 0; x < canvas.width(); ++x) {
      const Color c = canvas.pixel_at(x, y);
      for (const double component : {c.r, c.g, c.b}) {
        const std::string token = std::to_string(to_byte(component));
        if (line_length == 0) {
          ppm += token;
          line_length = token.size();
        } else if (line_length + 1 + token.size() > kMaxPpmLine) {
          ppm += '\n';
          ppm += token;
          line_length = token.size();
        } else {
          ppm += ' ';
          ppm += token;
          line_length += 1 + token.size();
        }
      }
    }
    ppm += '\n';
  }
  return ppm;
}

}  // namespace toroid
