// SPDX-License-Identifier: Apache-2.0
// The convex hull test of the default solver's window queries (the nearest
// root and the shadow test, intersect.cpp): a ray that starts outside the
// torus's convex hull and moves away from it meets no point of the torus.
// Internal: not installed.
//
// The hull, of a torus of any kind, is the tube's section swept round the
// axis with the hole filled: the slab |z| <= r, and within it the points
// with rho <= R + sqrt(r^2 - z^2). Two planes that hold the hull behind them
// give the test:
//   - a face of the slab, z = +-r: a ray that starts beyond it and does not
//     turn back towards it never enters the slab;
//   - from a point q with rho > R outside the tube, the tangent plane at the
//     tube point nearest q, whose normal is q - c (c the point of the centre
//     circle below q): the hull lies behind it, so a ray whose direction has
//     a positive component along q - c only moves away.
// A renderer's shadow and reflected rays leave a torus this way wherever
// they start on the tube's outer half, and so do rays refracted out of it.
//
// Each test has a margin of 2^-30 of the scale of the numbers it is made
// of (|origin|, |t_min d|, R + r), far above their rounding (a few eps of
// that scale), so a ray that passes stays more than 2^-31 of that scale
// away from the torus, while every root the solver reports lies within a
// few eps of it of the surface (fuzz/torus_root_checks.h): no root the
// search could find lies on such a ray, and the test changes no answer,
// only its cost.
#pragma once

#include <cmath>
#include <limits>

#include "toroid/math/device.h"

namespace toroid {

// The window's start as the tests compute with it: a start nearer 0 than
// the least normal double is taken as 0. Such a start (-denorm_min, a
// renderer's way to count a root at t = 0) moves q by less than 2^-874
// (|d| < 2^200), far below the margins, and a product with a subnormal
// result costs many processors a microcode assist on every query.
[[gnu::always_inline]] TOROID_HD inline double hull_test_start(double t_min) {
  return std::abs(t_min) < 0x1p-1022 ? 0.0 : t_min;
}

// The scale of the numbers a hull test is made of (|origin|, |t_min d|,
// R + r), or 0 where a torus size or |d|^2 lies outside the range where the
// products below stay normal (the solver's range): the tests are then unsure.
[[gnu::always_inline]] TOROID_HD inline double hull_test_scale(double major, double minor, const double origin[3],
                                                               const double d[3], double dd, double t_min) {
  const double size = major + minor;
  if (!(size > 0x1p-100 && size < 0x1p100 && dd > 0x1p-400 && dd < 0x1p400)) return 0;
  return std::abs(origin[0]) + std::abs(origin[1]) + std::abs(origin[2]) +
         std::abs(t_min) * (std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2])) + major + minor;
}

// Whether the ray o + t d, for every t >= t_min, stays outside the convex
// hull of the torus (major, minor) with a margin; false where unsure
// (within the margins, for a non-finite point at t_min, and for a torus size
// or |d|^2 outside the range where the products below stay normal: the
// solver's range, 2^-100..2^100 and 2^-400..2^400).
[[gnu::always_inline]] TOROID_HD inline bool ray_leaves_hull(double major, double minor, const double origin[3],
                                                             const double d[3], double t_min) {
  t_min = hull_test_start(t_min);
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = origin[i] + t_min * d[i];
  // The tube's plane needs q.d >= -R |d| (c.d >= -R |d|), and so does the
  // slab's where rho <= R: a ray aimed at the torus, as a camera's is,
  // leaves here, the common case at the cost of two dot products.
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double qd = (origin[0] * d[0] + origin[1] * d[1] + origin[2] * d[2]) + t_min * dd;
  if (qd < 0 && qd * qd >= major * major * dd) return false;
  const double scale = hull_test_scale(major, minor, origin, d, dd, t_min);
  if (scale == 0) return false;
  const double margin = 0x1p-30 * scale;
  // Beyond a face of the slab, not turning back towards it.
  if (std::abs(q[2]) - minor > margin && (q[2] > 0 ? d[2] >= 0 : d[2] <= 0)) return true;
  // Outside the tube's outer half, moving away from its tangent plane:
  // (q - c).d > 0, times rho. rho is beyond R by more than its rounding, so
  // the nearest point of the hull does lie on the outer half.
  const double rho = std::sqrt(q[0] * q[0] + q[1] * q[1]);
  const double a = rho - major;
  if (!(a > margin)) return false;
  const double gap = a * a + q[2] * q[2] - minor * minor;
  const double away = a * (q[0] * d[0] + q[1] * d[1]) + rho * (q[2] * d[2]);
  const double d_sum = std::abs(d[0]) + std::abs(d[1]) + std::abs(d[2]);
  return gap > margin * scale && away > margin * rho * d_sum;
}

// Whether the ray o + t d, for every t >= t_min, stays outside a ring
// torus (minor < major) by leaving through its hole: a ray that leaves the
// tube's inner half (reflected there, or refracted out) and rises or falls
// out of the slab |z| <= r nearer the axis than it started. Where rho < R,
// h_out = (R - rho)^2 + z^2 - r^2 grows as rho falls and as |z| grows; from
// a start q outside the tube with rho < R, |z| grows along the ray (q_z d_z
// >= 0), and rho^2, a convex quadratic along it, is at most its value at q
// if it is at the slab's face, and so all the way there: h_out stays at or
// above its value at q, positive with the margin, until the ray leaves the
// slab, beyond which the torus has no point. Margins as ray_leaves_hull's
// (2^-30 of the scale on h at q, 2^-40 on rho^2 at the face), far above
// their rounding; false where unsure and for a torus size or |d|^2 outside
// the solver's range.
[[gnu::always_inline]] TOROID_HD inline bool ray_leaves_through_hole(double major, double minor, const double origin[3],
                                                                     const double d[3], double t_min) {
  t_min = hull_test_start(t_min);
  double q[3];
  for (int i = 0; i < 3; ++i) q[i] = origin[i] + t_min * d[i];
  if (!(minor < major) || d[2] == 0 || q[2] * d[2] < 0) return false;
  const double rho2 = q[0] * q[0] + q[1] * q[1];
  if (!(rho2 < major * major)) return false;
  const double scale = hull_test_scale(major, minor, origin, d, d[0] * d[0] + d[1] * d[1] + d[2] * d[2], t_min);
  if (scale == 0) return false;
  const double a = major - std::sqrt(rho2);
  if (!(a * a + q[2] * q[2] - minor * minor > 0x1p-30 * scale * scale)) return false;
  // Where the ray meets the face it moves towards (at q already, if beyond
  // it), or later: q_z carries the rounding of o_z + t_min d_z, a few eps of
  // their size, which moves the crossing by that over |d_z| (a ray almost
  // parallel to the face crosses it far from where the rounded q_z says).
  // rho^2 is convex along the ray, so it stays below its larger end value
  // on the longer stretch too.
  const double face = (d[2] > 0 ? minor : -minor) - q[2];
  const double s_rounded = std::fmax(0.0, face / d[2]);
  const double s =
      s_rounded + 4 * std::numeric_limits<double>::epsilon() *
                      ((std::abs(origin[2]) + std::abs(t_min * d[2]) + minor) / std::abs(d[2]) + s_rounded);
  const double x = q[0] + s * d[0], y = q[1] + s * d[1];
  return x * x + y * y <= rho2 - 0x1p-40 * scale * scale;
}

}  // namespace toroid
