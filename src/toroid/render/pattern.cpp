// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/pattern.h"

#include <cmath>
#include <cstdint>

#include "toroid/shapes/shape.h"

namespace toroid {

void Pattern::set_transform(const Matrix4& m) {
  transform_ = m;
  inverse_ = Affine::from(inverse(m));
  untransformed_ = m == Matrix4::identity();
}

Color Pattern::pattern_at_shape(const Shape& shape, const Tuple& world_point) const {
  return pattern_at_object(shape.world_to_object(world_point));
}

namespace {

// Far below any pattern feature size, far above the rounding noise of a
// surface point (about 1e-16 relative to the scene's coordinates).
constexpr double kPatternEpsilon = 1e-9;

// Whether a whole number (a floor) is even. Below 2^52 in size the integer
// test gives fmod's answer without its cost (a tenth of a striped wall's
// shading); beyond, every double is even and fmod says so (and that
// infinities and NaN are not).
bool is_even(double floored) {
  if (std::abs(floored) < 0x1p52) return (static_cast<std::int64_t>(floored) & 1) == 0;
  return std::fmod(floored, 2.0) == 0.0;
}

}  // namespace

double pattern_floor(double v) { return std::floor(v + kPatternEpsilon); }

Color StripePattern::pattern_at(const Tuple& p) const { return is_even(pattern_floor(p.x)) ? a() : b(); }

Color GradientPattern::pattern_at(const Tuple& p) const {
  const double fraction = p.x - std::floor(p.x);
  return a() + (b() - a()) * fraction;
}

Color RingPattern::pattern_at(const Tuple& p) const {
  return is_even(pattern_floor(std::sqrt(p.x * p.x + p.z * p.z))) ? a() : b();
}

Color CheckersPattern::pattern_at(const Tuple& p) const {
  return is_even(pattern_floor(p.x) + pattern_floor(p.y) + pattern_floor(p.z)) ? a() : b();
}

Color BlendedPattern::pattern_at(const Tuple& p) const {
  return (a_->pattern_at_object(p) + b_->pattern_at_object(p)) * 0.5;
}

}  // namespace toroid
