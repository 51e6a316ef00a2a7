// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/torus.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid {

namespace {

// The queries' interval is open: just below 0 admits t = 0, as hit() does.
constexpr double kBelowZero = -std::numeric_limits<double>::denorm_min();

// Extremes of cos and sin over the angles [lo, hi]: at the ends or at the
// multiples of pi/2 inside, whose values are taken exactly.
struct TrigRange {
  double cos_min, cos_max, sin_min, sin_max;
  void include(double c, double s) {
    cos_min = std::min(cos_min, c), cos_max = std::max(cos_max, c);
    sin_min = std::min(sin_min, s), sin_max = std::max(sin_max, s);
  }
};

TrigRange trig_range(double lo, double hi) {
  TrigRange t{std::cos(lo), std::cos(lo), std::sin(lo), std::sin(lo)};
  t.include(std::cos(hi), std::sin(hi));
  constexpr double kQuarter = std::numbers::pi / 2;
  static constexpr double kCos[4] = {1, 0, -1, 0}, kSin[4] = {0, 1, 0, -1};
  for (long k = static_cast<long>(std::ceil(lo / kQuarter)); k * kQuarter <= hi; ++k) {
    const long q = ((k % 4) + 4) % 4;
    t.include(kCos[q], kSin[q]);
  }
  return t;
}

}  // namespace

bool TorusSweep::valid() const {
  return std::isfinite(theta_max) && std::isfinite(phi_min) && std::isfinite(phi_max) && theta_max > 0 &&
         theta_max <= kTwoPi && phi_min >= -kTwoPi && phi_max <= kTwoPi && phi_min < phi_max &&
         phi_max - phi_min <= kTwoPi;
}

void Torus::set_sweep(const TorusSweep& sweep) {
  assert(sweep.valid());
  partial_ = sweep.whole() ? nullptr : std::make_unique<const TorusSweep>(sweep);
  keeps_all_ = sweep.whole() && spindle_ == SpindleSurface::Whole;
  bounds_changed();
}

void Torus::set_spindle(SpindleSurface s) {
  spindle_ = s;
  keeps_all_ = sweep().whole() && spindle_ == SpindleSurface::Whole;
  bounds_changed();
}

bool Torus::keeps(const Tuple& surface_point) const {
  if (keeps_all_) return true;
  const double p[3] = {surface_point.x, surface_point.y, surface_point.z};
  if (spindle_ == SpindleSurface::Outer && on_torus_lemon(major_, minor_, p)) return false;
  if (!partial_) return true;
  const TorusSweep& s = *partial_;
  double theta, phi;
  torus_angles(major_, minor_, p, &theta, &phi);
  if (theta > s.theta_max) return false;
  const auto in = [&](double a) { return a >= s.phi_min && a <= s.phi_max; };
  return in(phi) || in(phi + TorusSweep::kTwoPi) || in(phi - TorusSweep::kTwoPi);
}

BoundingBox Torus::bounds() const {
  // Points are rho_s (cos theta, sin theta) with rho_s = R + r cos phi
  // (negative on a spindle's lemon) and z = r sin phi: x and y are bilinear
  // in rho_s and (cos theta, sin theta), so the corners of their ranges bound
  // them exactly; z depends on phi alone.
  const TorusSweep& s = sweep();
  const TrigRange phi = trig_range(s.phi_min, s.phi_max);
  const TrigRange theta = trig_range(0, s.theta_max);
  double rho_lo = major_ + minor_ * phi.cos_min, rho_hi = major_ + minor_ * phi.cos_max;
  if (spindle_ == SpindleSurface::Outer) rho_lo = std::max(rho_lo, 0.0), rho_hi = std::max(rho_hi, 0.0);
  const auto span = [&](double lo, double hi) {
    const double c[4] = {rho_lo * lo, rho_lo * hi, rho_hi * lo, rho_hi * hi};
    return std::minmax({c[0], c[1], c[2], c[3]});
  };
  const auto [x_lo, x_hi] = span(theta.cos_min, theta.cos_max);
  const auto [y_lo, y_hi] = span(theta.sin_min, theta.sin_max);
  return {point(x_lo, y_lo, minor_ * phi.sin_min), point(x_hi, y_hi, minor_ * phi.sin_max)};
}

BoundingBox Torus::parent_space_bounds() const {
  if (partial_) return Shape::parent_space_bounds();
  // The solid torus is every point within r of the centre circle (the
  // circle plus a ball of radius r), with the spindle's lemon inside it. On
  // a parent axis whose row of the forward transform is (a, b, c, d), the
  // circle reaches d +- R |(a, b)| and the ball adds r |(a, b, c)|.
  const Matrix4 m = transform();
  double lo[3], hi[3];
  for (int i = 0; i < 3; ++i) {
    const double a = m.m[i][0], b = m.m[i][1], c = m.m[i][2], d = m.m[i][3];
    const double half = major_ * std::hypot(a, b) + minor_ * std::sqrt(a * a + b * b + c * c);
    // Outwards by far more than the rounding above, and than a grazing
    // root's error: the box must hold every hit the solver reports.
    const double pad = 1e-9 * (std::abs(d) + half);
    lo[i] = d - half - pad;
    hi[i] = d + half + pad;
  }
  return {point(lo[0], lo[1], lo[2]), point(hi[0], hi[1], hi[2])};
}

double Torus::half_thickness() const { return partial_ ? Shape::half_thickness() : minor_; }

AnnularCylinder Torus::washer() const { return {major_ - minor_, major_ + minor_, minor_}; }

int Torus::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (!washer().may_meet(ray.origin, ray.direction, -kInf, kInf)) return 0;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  double t[4];
  const int n = intersect_torus(major_, minor_, o, d, t, solver_);
  int kept = 0;
  for (int i = 0; i < n; ++i)
    if (keeps_all_ || keeps(ray.position(t[i]))) hits[kept++] = {t[i], this};
  return kept;
}

bool Torus::nearest_root(const Ray& ray, double t_max, double& t) const {
  // Most rays that reach a torus's box miss the torus, or meet it beyond
  // t_max (a nearer hit, the light): the washer turns them away cheaply.
  if (!washer().may_meet(ray.origin, ray.direction, kBelowZero, t_max)) return false;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  return intersect_torus_nearest(major_, minor_, o, d, kBelowZero, t_max, &t, solver_);
}

bool Torus::local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
  if (!keeps_all_) return Primitive<Torus>::local_intersect_nearest(ray, t_max, hit);
  double t;
  if (!nearest_root(ray, t_max, t)) return false;
  hit = {t, this};
  return true;
}

bool Torus::local_blocks(const Ray& ray, double t_max) const {
  if (!keeps_all_) return Primitive<Torus>::local_blocks(ray, t_max);
  if (!washer().may_meet(ray.origin, ray.direction, kBelowZero, t_max)) return false;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  return torus_blocks(major_, minor_, o, d, kBelowZero, t_max, solver_);
}

Tuple Torus::local_normal_at(const Tuple& p, const Intersection&) const {
  const double q[3] = {p.x, p.y, p.z};
  double n[3];
  torus_normal(major_, minor_, q, n);
  return vector(n[0], n[1], n[2]);
}

}  // namespace toroid
