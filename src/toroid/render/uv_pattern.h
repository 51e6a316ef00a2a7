// SPDX-License-Identifier: Apache-2.0
// Two-dimensional patterns (RTC bonus chapter "Texture Mapping"): a colour
// for each (u, v) in [0, 1] x [0, 1], u to the right, v upwards. A mapping
// (uv_mapping.h) turns a point on a shape into (u, v); texture_map.h joins the
// two into a Pattern.
#pragma once

#include <memory>

#include "toroid/core/canvas.h"
#include "toroid/math/color.h"

namespace toroid {

class UvPattern {
 public:
  UvPattern() = default;
  UvPattern(const UvPattern&) = delete;
  UvPattern& operator=(const UvPattern&) = delete;
  virtual ~UvPattern() = default;

  virtual Color uv_pattern_at(double u, double v) const = 0;
};

// width x height squares, a in the bottom-left one.
class UvCheckers : public UvPattern {
 public:
  // Precondition: width, height > 0.
  UvCheckers(double width, double height, const Color& a, const Color& b)
      : width_(width), height_(height), a_(a), b_(b) {}
  Color uv_pattern_at(double u, double v) const override;

 private:
  double width_, height_;
  Color a_, b_;
};

// The book's alignment test: `main` everywhere but a 0.2 x 0.2 square of a
// different colour in each corner (upper left, upper right, bottom left,
// bottom right), so a mapping's orientation shows at a glance.
class UvAlignCheck : public UvPattern {
 public:
  UvAlignCheck(const Color& main, const Color& ul, const Color& ur, const Color& bl, const Color& br)
      : main_(main), ul_(ul), ur_(ur), bl_(bl), br_(br) {}
  Color uv_pattern_at(double u, double v) const override;

 private:
  Color main_, ul_, ur_, bl_, br_;
};

// An image: u = 0..1 runs over the columns' centres left to right, v = 0..1
// over the rows' centres bottom to top, nearest pixel (the book's sampling).
class UvImage : public UvPattern {
 public:
  // Precondition: canvas is not null and not empty.
  explicit UvImage(std::shared_ptr<const Canvas> canvas) : canvas_(std::move(canvas)) {}
  const Canvas& canvas() const { return *canvas_; }
  Color uv_pattern_at(double u, double v) const override;

 private:
  std::shared_ptr<const Canvas> canvas_;
};

}  // namespace toroid
