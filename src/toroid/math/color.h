// SPDX-License-Identifier: Apache-2.0
// Linear RGB colour; components are unbounded until the canvas clamps them.
#pragma once

#include <iosfwd>

#include "toroid/math/tuple.h"

namespace toroid {

struct Color {
  double r = 0, g = 0, b = 0;
};

constexpr Color operator+(const Color& a, const Color& b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
constexpr Color operator-(const Color& a, const Color& b) { return {a.r - b.r, a.g - b.g, a.b - b.b}; }
constexpr Color operator*(const Color& a, double s) { return {a.r * s, a.g * s, a.b * s}; }
constexpr Color operator*(double s, const Color& a) { return a * s; }
constexpr Color operator/(const Color& a, double s) { return {a.r / s, a.g / s, a.b / s}; }
// Hadamard (Schur) product: blends a light's colour with a surface's.
constexpr Color operator*(const Color& a, const Color& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
constexpr Color& operator+=(Color& a, const Color& b) { return a = a + b; }

inline constexpr Color kBlack{0, 0, 0};
inline constexpr Color kWhite{1, 1, 1};

inline bool approx_equal(const Color& a, const Color& b, double eps = kEpsilon) {
  return approx_equal(a.r, b.r, eps) && approx_equal(a.g, b.g, eps) && approx_equal(a.b, b.b, eps);
}

std::ostream& operator<<(std::ostream& os, const Color& c);

}  // namespace toroid
