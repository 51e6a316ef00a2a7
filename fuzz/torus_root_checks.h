// SPDX-License-Identifier: Apache-2.0
// What the intersect fuzz targets check of the roots intersect_torus returns
// for a ray, beyond their count: each root finite, the list ascending, and
// each point o + t d on the torus within rounding.
//
// The bound on the distance of o + t d from the surface. The root t of an
// ill-conditioned (grazing) ray may be far from the exact root along the ray,
// so t itself cannot be bounded; the point can. A solver that is backward
// stable returns an exact root of the problem with inputs perturbed by a few
// ulps: o and d by c eps |o| and c eps |d|, R and r by c eps R and c eps r.
// That moves the point o + t d by at most c eps (|o| + |t| |d|) and the
// surface by at most c eps (R + r); rounding t to a double moves the point by
// half an ulp of t times |d|, which the same term covers. Hence
//     dist(o + t d, torus) <= C eps (|o| + |t| |d| + R + r),
// plus, for inputs below the normal range, where doubles are spaced by
// denorm_min rather than relatively, C denorm_min (1 + |d|).
// whatever the conditioning of t (for a grazing ray the point slides along
// the surface, nearly tangentially). The default solver works on the
// factors (rho -+ R)^2 + z^2 - r^2 evaluated from the point, with the origin
// moved exactly (double-double) to the ray's point nearest the centre: a few
// dozen roundings, each relative to one of those magnitudes, that mostly do
// not add up. C = 16: the largest C measured over 4.6 million roots of
// random aimed, grazing (tilts down to 1e-16) and far (to 1e8 sizes) rays,
// R in 1e-3..1e4 and r/R in 1e-4..2, was 1.7. The distance is evaluated in long double (64-bit significand, 11
// more bits than the bound's eps, and an exponent range that does not
// overflow where double would), to both factors of the quartic (the spindle's
// inner lemon is part of the surface).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace toroid::fuzz {

static_assert(std::numeric_limits<long double>::digits >= 64,
              "the residual is measured in long double, which must be wider than double");

inline constexpr double kResidualUlps = 16;

// Distance from o + t d to the torus surface (both factors), in long double.
inline long double torus_surface_distance(double major, double minor, const double o[3], const double d[3], double t) {
  long double p[3];
  for (int i = 0; i < 3; ++i) p[i] = static_cast<long double>(o[i]) + static_cast<long double>(t) * d[i];
  const long double rho = std::hypot(p[0], p[1]);
  const long double R = major, r = minor;
  const long double out = std::abs(std::hypot(rho - R, p[2]) - r);
  const long double in = std::abs(std::hypot(rho + R, p[2]) - r);
  return std::min(out, in);
}

// The bound above for root t.
inline long double torus_residual_bound(double major, double minor, const double o[3], const double d[3], double t) {
  const long double on =
      std::hypot(static_cast<long double>(o[0]), static_cast<long double>(o[1]), static_cast<long double>(o[2]));
  const long double dn =
      std::hypot(static_cast<long double>(d[0]), static_cast<long double>(d[1]), static_cast<long double>(d[2]));
  const long double scale = on + std::abs(static_cast<long double>(t)) * dn + major + minor;
  // Below the normal range doubles are spaced by denorm_min, not by eps
  // relative: the inputs and t are only known to that much.
  const long double spacing = std::numeric_limits<double>::denorm_min() * (1 + dn);
  return kResidualUlps * (std::numeric_limits<double>::epsilon() * scale + spacing);
}

[[noreturn]] inline void fail_roots(const char* what, double major, double minor, const double o[3], const double d[3],
                                    const double* t, int n) {
  std::fprintf(stderr, "intersect_torus(R=%.17g, r=%.17g, o=(%.17g %.17g %.17g), d=(%.17g %.17g %.17g)): %s;", major,
               minor, o[0], o[1], o[2], d[0], d[1], d[2], what);
  for (int i = 0; i < n; ++i) {
    std::fprintf(stderr, " t%d=%.17g", i, t[i]);
    if (std::isfinite(t[i]))
      std::fprintf(stderr, " (distance %.3Lg, bound %.3Lg)", torus_surface_distance(major, minor, o, d, t[i]),
                   torus_residual_bound(major, minor, o, d, t[i]));
  }
  std::fprintf(stderr, "\n");
  std::abort();
}

// Aborts, saying why, unless 0 <= n <= 4 and t[0..n) are finite and
// ascending (equal where a root is double): what every solver promises.
inline void check_torus_root_list(double major, double minor, const double o[3], const double d[3], const double* t,
                                  int n) {
  if (n < 0 || n > 4) fail_roots("root count outside 0..4", major, minor, o, d, t, 0);
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(t[i])) fail_roots("a root is not finite", major, minor, o, d, t, n);
  for (int i = 0; i + 1 < n; ++i)
    if (!(t[i] <= t[i + 1])) fail_roots("the roots are not ascending", major, minor, o, d, t, n);
}

// The same, and each root on the surface within the bound: the default
// solver's promise.
inline void check_torus_roots(double major, double minor, const double o[3], const double d[3], const double* t,
                              int n) {
  check_torus_root_list(major, minor, o, d, t, n);
  for (int i = 0; i < n; ++i)
    if (!(torus_surface_distance(major, minor, o, d, t[i]) <= torus_residual_bound(major, minor, o, d, t[i])))
      fail_roots("a root is off the surface", major, minor, o, d, t, n);
}

}  // namespace toroid::fuzz
