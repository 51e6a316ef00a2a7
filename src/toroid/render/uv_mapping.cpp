// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/uv_mapping.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "toroid/torus/surface.h"

namespace toroid {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// a mod m in [0, m), also for negative a.
double wrap(double a, double m) {
  const double r = std::fmod(a, m);
  return r < 0 ? r + m : r;
}

// An angle in (-pi, 2 pi) as turns in [0, 1): -pi and pi both give 0.5, and
// nothing rounds up to 1.
double turns(double angle) {
  double t = angle / kTwoPi;
  if (t < 0) t += 1;
  return t < 1 ? t : 0.0;
}

// The book's u around the y axis: 0 at -z, 0.25 at +x, 0.5 at +z.
double u_around_y(const Tuple& p) {
  const double raw_u = std::atan2(p.x, p.z) / kTwoPi;
  return wrap(1 - (raw_u + 0.5), 1.0);
}

}  // namespace

UvCoord spherical_map(const Tuple& p) {
  const double radius = magnitude(vector(p.x, p.y, p.z));
  const double phi = std::acos(std::clamp(p.y / radius, -1.0, 1.0));
  return {u_around_y(p), 1 - phi / std::numbers::pi};
}

UvCoord planar_map(const Tuple& p) { return {wrap(p.x, 1.0), wrap(p.z, 1.0)}; }

UvCoord cylindrical_map(const Tuple& p) { return {u_around_y(p), wrap(p.y, 1.0)}; }

UvCoord toroidal_map(double major, double minor, const Tuple& p) {
  // The torus's own parameters (torus_angles, shared with partial tori):
  // exact on the spindle's lemon too, whose points belong to the tube
  // around the centre circle's far side.
  const double q[3] = {p.x, p.y, p.z};
  double theta = 0, phi = 0;
  torus_angles(major, minor, q, &theta, &phi);
  return {turns(theta), turns(phi)};
}

CubeFace face_from_point(const Tuple& p) {
  const double coord = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  if (coord == p.x) return CubeFace::Right;
  if (coord == -p.x) return CubeFace::Left;
  if (coord == p.y) return CubeFace::Up;
  if (coord == -p.y) return CubeFace::Down;
  if (coord == p.z) return CubeFace::Front;
  return CubeFace::Back;
}

// Each face maps its [-1, 1] square to [0, 1], repeating outside it.
UvCoord cube_uv_front(const Tuple& p) { return {wrap(p.x + 1, 2.0) / 2, wrap(p.y + 1, 2.0) / 2}; }
UvCoord cube_uv_back(const Tuple& p) { return {wrap(1 - p.x, 2.0) / 2, wrap(p.y + 1, 2.0) / 2}; }
UvCoord cube_uv_left(const Tuple& p) { return {wrap(p.z + 1, 2.0) / 2, wrap(p.y + 1, 2.0) / 2}; }
UvCoord cube_uv_right(const Tuple& p) { return {wrap(1 - p.z, 2.0) / 2, wrap(p.y + 1, 2.0) / 2}; }
UvCoord cube_uv_up(const Tuple& p) { return {wrap(p.x + 1, 2.0) / 2, wrap(1 - p.z, 2.0) / 2}; }
UvCoord cube_uv_down(const Tuple& p) { return {wrap(p.x + 1, 2.0) / 2, wrap(p.z + 1, 2.0) / 2}; }

UvCoord cube_uv(CubeFace face, const Tuple& p) {
  switch (face) {
    case CubeFace::Left: return cube_uv_left(p);
    case CubeFace::Right: return cube_uv_right(p);
    case CubeFace::Front: return cube_uv_front(p);
    case CubeFace::Back: return cube_uv_back(p);
    case CubeFace::Up: return cube_uv_up(p);
    case CubeFace::Down: return cube_uv_down(p);
  }
  return {};
}

Tuple spherical_point(UvCoord uv) {
  const double theta = (0.5 - uv.u) * kTwoPi;  // inverts u = 1 - (theta / 2pi + 0.5)
  const double phi = (1 - uv.v) * std::numbers::pi;
  return point(std::sin(phi) * std::sin(theta), std::cos(phi), std::sin(phi) * std::cos(theta));
}

Tuple cube_point(CubeFace face, UvCoord uv) {
  const double a = 2 * uv.u - 1, b = 2 * uv.v - 1;
  switch (face) {
    case CubeFace::Left: return point(-1, b, a);
    case CubeFace::Right: return point(1, b, -a);
    case CubeFace::Front: return point(a, b, 1);
    case CubeFace::Back: return point(-a, b, -1);
    case CubeFace::Up: return point(a, 1, -b);
    case CubeFace::Down: return point(a, -1, b);
  }
  return point(0, 0, 0);
}

}  // namespace toroid
