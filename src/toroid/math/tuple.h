// SPDX-License-Identifier: Apache-2.0
// Tuples as in The Ray Tracer Challenge: points (w = 1) and vectors (w = 0) in
// one type, so that a 4x4 matrix transforms both with the same multiply.
#pragma once

#include <cmath>
#include <iosfwd>

namespace toroid {

// The comparison tolerance of the RTC book's scenarios.
inline constexpr double kEpsilon = 1e-5;

inline bool approx_equal(double a, double b, double eps = kEpsilon) { return std::abs(a - b) < eps; }

struct Tuple {
  double x = 0, y = 0, z = 0, w = 0;

  constexpr bool is_point() const { return w == 1.0; }
  constexpr bool is_vector() const { return w == 0.0; }
  constexpr double operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
};

constexpr Tuple point(double x, double y, double z) { return {x, y, z, 1.0}; }
constexpr Tuple vector(double x, double y, double z) { return {x, y, z, 0.0}; }

constexpr Tuple operator+(const Tuple& a, const Tuple& b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
constexpr Tuple operator-(const Tuple& a, const Tuple& b) { return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
constexpr Tuple operator-(const Tuple& a) { return {-a.x, -a.y, -a.z, -a.w}; }
constexpr Tuple operator*(const Tuple& a, double s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
constexpr Tuple operator*(double s, const Tuple& a) { return a * s; }
constexpr Tuple operator/(const Tuple& a, double s) { return {a.x / s, a.y / s, a.z / s, a.w / s}; }

constexpr double dot(const Tuple& a, const Tuple& b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
// Cross product of the xyz parts; the result is a vector.
constexpr Tuple cross(const Tuple& a, const Tuple& b) {
  return vector(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
inline double magnitude(const Tuple& a) { return std::sqrt(dot(a, a)); }
inline Tuple normalize(const Tuple& a) { return a / magnitude(a); }
// Reflects `in` about the normal `n` (n of unit length).
constexpr Tuple reflect(const Tuple& in, const Tuple& n) { return in - n * 2.0 * dot(in, n); }

inline bool approx_equal(const Tuple& a, const Tuple& b, double eps = kEpsilon) {
  return approx_equal(a.x, b.x, eps) && approx_equal(a.y, b.y, eps) && approx_equal(a.z, b.z, eps) &&
         approx_equal(a.w, b.w, eps);
}

std::ostream& operator<<(std::ostream& os, const Tuple& t);

}  // namespace toroid
