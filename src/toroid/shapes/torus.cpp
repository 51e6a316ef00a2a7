// SPDX-License-Identifier: Apache-2.0
#include "toroid/shapes/torus.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

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

// Whether phi (in [-pi, pi]) or phi +- 2 pi lies in the sweep's phi range.
bool in_phi_range(const TorusSweep& s, double phi) {
  const auto in = [&](double a) { return a >= s.phi_min && a <= s.phi_max; };
  return in(phi) || in(phi + TorusSweep::kTwoPi) || in(phi - TorusSweep::kTwoPi);
}

// A phi cap whose cone is this flat (|tan phi| below it) is taken as its
// plane z = 0, an annulus: the cone's two nappes then lie closer together
// than the roots' rounding can tell apart. The cap moves by at most 1e-10
// minor at the tube.
constexpr double kFlatCone = 1e-10;

// The roots of a t^2 + 2 b t + c = 0 given sqrt(b^2 - a c) (computed by the
// caller without cancellation), the stable way; non-finite ones (a = 0)
// dropped. Returns how many.
int quadratic_roots(double a, double b, double c, double sqrt_disc, double t[2]) {
  const double q = -(b + std::copysign(sqrt_disc, b));
  // q = 0: b = 0 and a c = 0, a degenerate equation or a double root at t =
  // 0 (a ray that starts on the cone and grazes it): no crossing.
  if (q == 0) return 0;
  int n = 0;
  const double t0 = q / a, t1 = c / q;
  if (std::isfinite(t0)) t[n++] = t0;
  if (std::isfinite(t1)) t[n++] = t1;
  return n;
}

}  // namespace

bool TorusSweep::valid() const {
  return std::isfinite(theta_max) && std::isfinite(phi_min) && std::isfinite(phi_max) && theta_max > 0 &&
         theta_max <= kTwoPi && phi_min >= -kTwoPi && phi_max <= kTwoPi && phi_min < phi_max &&
         phi_max - phi_min <= kTwoPi;
}

void Torus::set_sweep(const TorusSweep& sweep) {
  assert(sweep.valid());
  if (sweep.whole()) {
    partial_ = nullptr;
  } else {
    partial_ = std::make_unique<const Partial>(Partial{sweep,
                                                       std::cos(sweep.theta_max),
                                                       std::sin(sweep.theta_max),
                                                       {std::cos(sweep.phi_min), std::cos(sweep.phi_max)},
                                                       {std::sin(sweep.phi_min), std::sin(sweep.phi_max)}});
  }
  update_flags();
  bounds_changed();
}

void Torus::set_spindle(SpindleSurface s) {
  spindle_ = s;
  update_flags();
  bounds_changed();
}

void Torus::set_caps(bool on) {
  caps_ = on;
  update_flags();
  bounds_changed();
}

void Torus::update_flags() {
  keeps_all_ = sweep().whole() && spindle_ == SpindleSurface::Whole;
  capped_ = caps_ && partial_ && minor_ <= major_;
}

bool Torus::keeps(const Tuple& surface_point) const {
  if (keeps_all_) return true;
  const double p[3] = {surface_point.x, surface_point.y, surface_point.z};
  if (spindle_ == SpindleSurface::Outer && on_torus_lemon(major_, minor_, p)) return false;
  if (!partial_) return true;
  const TorusSweep& s = partial_->sweep;
  double theta, phi;
  torus_angles(major_, minor_, p, &theta, &phi);
  if (theta > s.theta_max) return false;
  return in_phi_range(s, phi);
}

BoundingBox Torus::bounds() const {
  // Points are rho_s (cos theta, sin theta) with rho_s = R + r cos phi
  // (negative on a spindle's lemon) and z = r sin phi: x and y are bilinear
  // in rho_s and (cos theta, sin theta), so the corners of their ranges bound
  // them exactly; z depends on phi alone.
  const TorusSweep& s = sweep();
  TrigRange phi = trig_range(s.phi_min, s.phi_max);
  // The caps of a phi cut reach in to the tube's centre circle.
  if (capped_) phi.include(0, 0);
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
  double centre[3], half[3];
  for (int i = 0; i < 3; ++i) {
    const double a = m.m[i][0], b = m.m[i][1], c = m.m[i][2];
    centre[i] = m.m[i][3];
    half[i] = major_ * std::hypot(a, b) + minor_ * std::sqrt(a * a + b * b + c * c);
  }
  // Padded: the box must hold every hit the solver reports, a grazing one included.
  return padded_box(centre, half);
}

double Torus::half_thickness() const { return partial_ ? Shape::half_thickness() : minor_; }

bool Torus::may_meet(const Ray& ray, double t_min, double t_max) const {
  if (solver_ == TorusSolver::Default) return true;
  const AnnularCylinder washer{major_ - minor_, major_ + minor_, minor_};
  return washer.may_meet(ray.origin, ray.direction, t_min, t_max);
}

int Torus::find_hits(const Ray& ray, Intersection hits[kMaxHits]) const {
  const int n = tube_hits(ray, hits);
  return capped_ ? add_cap_hits(ray, hits, n) : n;
}

int Torus::tube_hits(const Ray& ray, Intersection hits[kMaxTubeHits]) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // The washer holds the whole solid torus, so the caps too.
  if (!may_meet(ray, -kInf, kInf)) return 0;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  double t[4];
  const int n = intersect_torus(major_, minor_, o, d, t, solver_);
  int kept = 0;
  for (int i = 0; i < n; ++i)
    if (keeps_all_ || keeps(ray.position(t[i]))) hits[kept++] = {t[i], this};
  return kept;
}

int Torus::add_cap_hits(const Ray& ray, Intersection hits[kMaxHits], int n) const {
  const Partial& cut = *partial_;
  const TorusSweep& s = cut.sweep;
  const double R = major_, r = minor_;
  const Tuple& o = ray.origin;
  const Tuple& d = ray.direction;
  const auto add = [&](double t, TorusFace face) {
    hits[n++] = {t, this, static_cast<double>(static_cast<int>(face)), 0};
  };
  const auto theta_in = [&](const Tuple& p) {
    if (s.theta_max >= TorusSweep::kTwoPi) return true;
    const double q[3] = {p.x, p.y, p.z};
    double theta, phi;
    torus_angles(R, r, q, &theta, &phi);
    return theta <= s.theta_max;
  };

  if (s.theta_max < TorusSweep::kTwoPi) {
    // The disc of radius r about (R cos a, R sin a, 0) in the meridian plane
    // at angle a, whose normal is (-sin a, cos a, 0); a point of the plane
    // lies `along` from the disc's centre away from the axis, and at z.
    const bool phi_cut = s.phi_max - s.phi_min < TorusSweep::kTwoPi;
    const auto disc = [&](double c, double sn, TorusFace face) {
      const double nd = c * d.y - sn * d.x;
      if (nd == 0) return;  // the ray lies in the plane or parallel to it
      const double t = -(c * o.y - sn * o.x) / nd;
      const Tuple p = ray.position(t);
      const double along = c * p.x + sn * p.y - R;
      if (along * along + p.z * p.z > r * r) return;
      if (phi_cut && !in_phi_range(s, std::atan2(p.z, along))) return;
      add(t, face);
    };
    disc(1, 0, TorusFace::ThetaStart);
    disc(cut.cos_theta_max, cut.sin_theta_max, TorusFace::ThetaEnd);
  }

  if (s.phi_max - s.phi_min < TorusSweep::kTwoPi) {
    // The cap at phi is the segment from the tube's centre (rho, z) = (R, 0)
    // out to (R + r cos phi, r sin phi), swept around the axis: the points
    // whose distance `along` = (rho - R) cos phi + z sin phi lies in [0, r]
    // on the cone (rho - R) sin phi = z cos phi. Squared, the cone's equation
    // is a quadratic in t whose roots lie on it or on its mirror nappe
    // (rho -> -rho), told apart by a sign; written in the steep or the flat
    // form so that the discriminant has no cancellation.
    const double P = d.x * d.x + d.y * d.y, Q = o.x * d.x + o.y * d.y, S = o.x * o.x + o.y * o.y;
    const double cross = o.x * d.y - o.y * d.x;
    const auto cone = [&](double c, double sn, TorusFace face) {
      const auto keep = [&](double t) {
        const Tuple p = ray.position(t);
        const double along = (std::hypot(p.x, p.y) - R) * c + p.z * sn;
        if (along >= 0 && along <= r && theta_in(p)) add(t, face);
      };
      double t[2];
      if (std::abs(sn) > std::abs(c)) {
        // rho = w, with w = R + (cos / sin) z linear in t: w^2 = rho^2, and
        // the cone's own nappe has w >= 0 (rho >= R - r / sqrt 2 > 0 on it).
        // (The mirror nappe's points lie outside the range of `along` here;
        // in the flat form they do not.)
        const double m = c / sn, w0 = R + m * o.z, e = m * d.z;
        const double wx = w0 * d.x - e * o.x, wy = w0 * d.y - e * o.y;
        const double disc = wx * wx + wy * wy - cross * cross;
        if (disc < 0) return;
        const int k = quadratic_roots(e * e - P, w0 * e - Q, w0 * w0 - S, std::sqrt(disc), t);
        for (int i = 0; i < k; ++i)
          if (w0 + t[i] * e >= 0) keep(t[i]);
      } else if (std::abs(sn) >= kFlatCone * std::abs(c)) {
        // u = k rho, with u = z + k R linear in t (k = tan phi): u^2 = k^2
        // rho^2, and the cone's own nappe has u of the sign of k.
        const double k = sn / c, u0 = o.z + k * R;
        const double wx = u0 * d.x - d.z * o.x, wy = u0 * d.y - d.z * o.y;
        const double disc = wx * wx + wy * wy - k * k * cross * cross;
        if (disc < 0) return;
        const int m = quadratic_roots(d.z * d.z - k * k * P, u0 * d.z - k * k * Q, u0 * u0 - k * k * S,
                                      std::abs(k) * std::sqrt(disc), t);
        for (int i = 0; i < m; ++i)
          if ((u0 + t[i] * d.z) * k >= 0) keep(t[i]);
      } else if (d.z != 0) {
        keep(-o.z / d.z);  // the annulus in z = 0
      }
    };
    cone(cut.cos_phi[0], cut.sin_phi[0], TorusFace::PhiMin);
    cone(cut.cos_phi[1], cut.sin_phi[1], TorusFace::PhiMax);
  }

  // Insertion sort: a few hits, the tube's already in order.
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && hits[j].t < hits[j - 1].t; --j) std::swap(hits[j], hits[j - 1]);
  return n;
}

bool Torus::nearest_root(const Ray& ray, double t_max, double& t) const {
  // Most rays that reach a torus's box miss the torus, or meet it beyond
  // t_max (a nearer hit, the light): they are turned away cheaply.
  if (!may_meet(ray, kBelowZero, t_max)) return false;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  return intersect_torus_nearest(major_, minor_, o, d, kBelowZero, t_max, &t, solver_);
}

bool Torus::local_intersect_nearest(const Ray& ray, double t_max, Intersection& hit) const {
  if (!keeps_all_) return Primitive::local_intersect_nearest(ray, t_max, hit);
  double t;
  if (!nearest_root(ray, t_max, t)) return false;
  hit = {t, this};
  return true;
}

bool Torus::local_blocks(const Ray& ray, double t_max) const {
  if (!keeps_all_) return Primitive::local_blocks(ray, t_max);
  if (!may_meet(ray, kBelowZero, t_max)) return false;
  const double o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const double d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  return torus_blocks(major_, minor_, o, d, kBelowZero, t_max, solver_);
}

Tuple Torus::cap_normal(const Tuple& p, TorusFace face) const {
  if (face == TorusFace::ThetaStart) return vector(0, -1, 0);
  if (face == TorusFace::ThetaEnd) return vector(-partial_->sin_theta_max, partial_->cos_theta_max, 0);
  // A phi cap: along the tube's circle at the point's theta, away from the
  // swept phi range (towards lower phi at phi_min, higher at phi_max).
  const int i = face == TorusFace::PhiMax;
  const double sign = i ? 1.0 : -1.0;
  const double rho = std::hypot(p.x, p.y);
  const double cx = rho > 0 ? p.x / rho : 1.0, cy = rho > 0 ? p.y / rho : 0.0;
  const double radial = -sign * partial_->sin_phi[i];
  return vector(radial * cx, radial * cy, sign * partial_->cos_phi[i]);
}

Tuple Torus::local_normal_at(const Tuple& p, const Intersection& hit) const {
  if (capped_ && face_of(hit) != TorusFace::Tube) return cap_normal(p, face_of(hit));
  const double q[3] = {p.x, p.y, p.z};
  double n[3];
  torus_normal(major_, minor_, q, n);
  return vector(n[0], n[1], n[2]);
}

}  // namespace toroid
