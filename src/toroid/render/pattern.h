// SPDX-License-Identifier: Apache-2.0
// Patterns (RTC chapter 10): colours as a function of a point in pattern
// space. A pattern has its own transform, applied after the shape's.
#pragma once

#include <memory>
#include <utility>

#include "toroid/math/affine.h"
#include "toroid/math/color.h"
#include "toroid/math/matrix.h"

namespace toroid {

class Shape;

class Pattern {
 public:
  Pattern() = default;
  virtual ~Pattern() = default;

  const Matrix4& transform() const { return transform_; }
  Matrix4 inverse_transform() const { return inverse_.to_matrix(); }
  // Precondition: is_invertible(m) and m is affine (bottom row 0 0 0 1), as
  // for a shape. Caches the inverse, in affine form (bit-identical products,
  // fewer of them: every shaded point of a patterned surface asks).
  void set_transform(const Matrix4& m);

  // The colour at a point already in this pattern's space.
  virtual Color pattern_at(const Tuple& pattern_point) const = 0;
  // The colour at a point in the space the pattern is attached to (for a
  // material: the shape's object space); applies the pattern's inverse.
  // (An untransformed pattern skips the product by the identity, which
  // gives the same point: every shaded point of a patterned surface asks.)
  Color pattern_at_object(const Tuple& object_point) const {
    return pattern_at(untransformed_ ? object_point : inverse_ * object_point);
  }
  // The colour at a world point on `shape` (through its parents, if any).
  Color pattern_at_shape(const Shape& shape, const Tuple& world_point) const;

 protected:
  Pattern(const Pattern&) = default;
  Pattern& operator=(const Pattern&) = default;

 private:
  Matrix4 transform_ = Matrix4::identity();
  Affine inverse_;
  bool untransformed_ = true;  // transform_ is the identity
};

// floor() that treats values within a hair below an integer as that integer,
// so that surfaces lying exactly on a pattern boundary (a plane at y = 0 with
// checkers) do not speckle with rounding noise.
double pattern_floor(double v);

// The book's two-colour patterns.
class TwoColorPattern : public Pattern {
 public:
  TwoColorPattern(const Color& a, const Color& b) : a_(a), b_(b) {}
  const Color& a() const { return a_; }
  const Color& b() const { return b_; }

 private:
  Color a_, b_;
};

// a where floor(x) is even, b where odd.
class StripePattern : public TwoColorPattern {
 public:
  using TwoColorPattern::TwoColorPattern;
  Color pattern_at(const Tuple& p) const override;
};

// Linear from a at x = 0 to b at x = 1, repeating in each unit of x.
class GradientPattern : public TwoColorPattern {
 public:
  using TwoColorPattern::TwoColorPattern;
  Color pattern_at(const Tuple& p) const override;
};

// Concentric rings around the y axis: a where floor(sqrt(x^2 + z^2)) is even.
class RingPattern : public TwoColorPattern {
 public:
  using TwoColorPattern::TwoColorPattern;
  Color pattern_at(const Tuple& p) const override;
};

// 3D checkers of unit cubes: a where floor(x) + floor(y) + floor(z) is even.
class CheckersPattern : public TwoColorPattern {
 public:
  using TwoColorPattern::TwoColorPattern;
  Color pattern_at(const Tuple& p) const override;
};

// The average of two patterns, each evaluated through its own transform.
class BlendedPattern : public Pattern {
 public:
  // Precondition: a and b are not null.
  BlendedPattern(std::shared_ptr<const Pattern> a, std::shared_ptr<const Pattern> b)
      : a_(std::move(a)), b_(std::move(b)) {}
  Color pattern_at(const Tuple& p) const override;

 private:
  std::shared_ptr<const Pattern> a_, b_;
};

}  // namespace toroid
