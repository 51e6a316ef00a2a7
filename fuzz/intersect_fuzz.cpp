// SPDX-License-Identifier: Apache-2.0
// Fuzz target: intersect_torus on any torus (major, minor > 0) and any ray,
// every solver, and the roots checked as in torus_root_checks.h: 0..4,
// finite, ascending, each on the surface within rounding; the window queries'
// hull test never passing a ray that meets the torus; where the processor
// runs the default solver's AVX2 copy, its answers against the baseline's.
//
// Input: one mode byte, then up to seven doubles (little-endian bytes,
// missing ones 0): R, r, and five ray parameters. Random rays seldom touch a
// torus, so besides raw rays the modes aim rays at the surface:
//   mode % 3 == 0  raw: origin (a, b, c), direction (e, f, a*b) -- the
//                  direction's last component reuses bytes;
//   mode % 3 == 1  aimed: from the origin (c, e, f) at the point at height
//                  `b` (in units of r, any sign) above the surface point of
//                  angles (a, a*7): through or just past the surface;
//   mode % 3 == 2  grazing: through the surface point of angles (a, e), in a
//                  tangent direction tilted by `b` radians into the surface,
//                  from `c` tube sizes before it (near-tangent pairs).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>

#include "toroid/torus/hull.h"
#include "toroid/torus/intersect.h"
#include "toroid/torus/solver_copies.h"
#include "torus_root_checks.h"

namespace {

bool finite3(const double v[3]) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

// The rounding of the roots, in t: a few ulps of |o| + |t d| + R + r, and a
// few subnormal steps (t itself is no finer than those). Whether a root
// within it of a window's end lies inside is not decided by any query.
struct RootRounding {
  double R, r, len, o_len;
  RootRounding(double major, double minor, const double o[3], const double d[3])
      : R(major), r(minor), len(std::hypot(d[0], d[1], d[2])), o_len(std::hypot(o[0], o[1], o[2])) {}
  double operator()(double ti) const {
    return std::max(0x1p-40 * (o_len + std::abs(ti) * len + R + r) / len,
                    16 * std::numeric_limits<double>::denorm_min());
  }
};

// Window ends for the checks below: the origin, beside each root (1e-3 r
// away, or beyond its rounding) and between roots. Returns their count
// (at most 12).
int ends_beside_roots(const RootRounding& rounding, const double t[4], int count, double* ends) {
  int n = 0;
  ends[n++] = 0;
  for (int i = 0; i < count; ++i) {
    const double offset = std::max(1e-3 * rounding.r / rounding.len, 16 * rounding(t[i]));
    ends[n++] = t[i] - offset;
    ends[n++] = t[i] + offset;
    if (i + 1 < count) ends[n++] = 0.5 * (t[i] + t[i + 1]);
  }
  return n;
}

// torus_blocks answers whether the nearest-root query finds a root in the
// window: checked on windows that start at the origin (a shadow ray leaving
// a surface), beside each root and between roots, and end there or at
// infinity. A window's end within the roots' rounding of a root is left
// out: whether that root lies inside is not decided by either query.
void check_blocks_agrees_with_nearest(double R, double r, const double o[3], const double d[3], const double t[4],
                                      int count) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const RootRounding rounding(R, r, o, d);
  double ends[13];
  int n = ends_beside_roots(rounding, t, count, ends);
  ends[n++] = kInf;
  const auto undecided = [&](double end) {
    for (int i = 0; i < count; ++i)
      if (std::abs(end - t[i]) <= rounding(t[i])) return true;
    return false;
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      if (!(ends[i] < ends[j]) || undecided(ends[i]) || undecided(ends[j])) continue;
      double nearest;
      const bool found = toroid::intersect_torus_nearest(R, r, o, d, ends[i], ends[j], &nearest);
      if (toroid::torus_blocks(R, r, o, d, ends[i], ends[j]) != found) {
        std::fprintf(stderr, "torus_blocks on the window (%.17g, %.17g): not the nearest-root query's answer (%d)\n",
                     ends[i], ends[j], found);
        toroid::fuzz::fail_roots("torus_blocks disagrees with intersect_torus_nearest", R, r, o, d, t, count);
      }
    }
}

// The window queries' hull tests (hull.h: leaving the convex hull, or
// leaving through the hole) pass no ray that meets the torus after its start: checked from the origin and from beside
// each root and between roots, against the list (the all-roots call does not use the test). A root within the roots'
// rounding of the start is not decided.
void check_hull_test_passes_no_meeting_ray(double R, double r, const double o[3], const double d[3], const double t[4],
                                           int count) {
  const RootRounding rounding(R, r, o, d);
  double starts[12];
  const int n = ends_beside_roots(rounding, t, count, starts);
  for (int i = 0; i < n; ++i) {
    if (!toroid::ray_leaves_hull(R, r, o, d, starts[i]) && !toroid::ray_leaves_through_hole(R, r, o, d, starts[i]))
      continue;
    for (int j = 0; j < count; ++j)
      if (t[j] > starts[i] + rounding(t[j])) {
        std::fprintf(stderr, "from %.17g the hull test passes the ray, which meets the torus at %.17g\n", starts[i],
                     t[j]);
        toroid::fuzz::fail_roots("the hull test passes a ray that meets the torus", R, r, o, d, t, count);
      }
  }
}

// A caller that walks the roots one at a time asks for the nearest root
// after the one it has: from exactly each root of the list, the nearest-root
// query gives the list's next root, bit for bit, or none after the last.
void check_nearest_from_each_root(double R, double r, const double o[3], const double d[3], const double t[4],
                                  int count) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < count; ++i) {
    const double* next = std::find_if(t, t + count, [&](double ti) { return ti > t[i]; });
    double nearest = 0;
    const bool found = toroid::intersect_torus_nearest(R, r, o, d, t[i], kInf, &nearest);
    if (found != (next != t + count) || (found && nearest != *next)) {
      std::fprintf(stderr, "from root %d at %.17g: the nearest-root query gives %s%.17g, the list's next is %.17g\n", i,
                   t[i], found ? "" : "none, not ", found ? nearest : 0.0, next != t + count ? *next : kInf);
      toroid::fuzz::fail_roots("the nearest root after a root is not the list's next", R, r, o, d, t, count);
    }
  }
}

// Where this processor runs the default solver's AVX2 copy (the public
// calls do), the baseline build gives the same bits: every root, and the
// nearest root and the shadow answer from the origin and from each root.
void check_copy_matches_baseline(double R, double r, const double o[3], const double d[3], const double t[4],
                                 int count) {
  if (!toroid::x86_64_v3::available()) return;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  struct Answers {
    int count;
    double roots[4];
    bool found[5], blocks[5];
    double nearest[5];
  };
  const auto answers = [&](const double* starts) {
    Answers a{};
    a.count = toroid::intersect_torus(R, r, o, d, a.roots);
    for (int i = 0; i <= count; ++i) {
      a.nearest[i] = 0;
      a.found[i] = toroid::intersect_torus_nearest(R, r, o, d, starts[i], kInf, &a.nearest[i]);
      a.blocks[i] = toroid::torus_blocks(R, r, o, d, starts[i], kInf);
    }
    return a;
  };
  double starts[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < count; ++i) starts[i + 1] = t[i];
  toroid::x86_64_v3::set_enabled_for_testing(false);
  const Answers base = answers(starts);
  toroid::x86_64_v3::set_enabled_for_testing(true);
  const Answers copy = answers(starts);
  bool same = base.count == copy.count;
  for (int i = 0; same && i < base.count; ++i) same = std::memcmp(&base.roots[i], &copy.roots[i], sizeof(double)) == 0;
  for (int i = 0; same && i <= count; ++i)
    same = base.found[i] == copy.found[i] && base.blocks[i] == copy.blocks[i] &&
           std::memcmp(&base.nearest[i], &copy.nearest[i], sizeof(double)) == 0;
  if (!same)
    toroid::fuzz::fail_roots("the AVX2 copy of the solver and the baseline build differ", R, r, o, d, t, count);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int mode = data[0] % 3;
  double x[7] = {0, 0, 0, 0, 0, 0, 0};
  std::memcpy(x, data + 1, std::min(sizeof x, size - 1));
  const double R = std::abs(x[0]), r = std::abs(x[1]);
  if (!(R > 0 && r > 0 && std::isfinite(R) && std::isfinite(r))) return 0;
  const double a = x[2], b = x[3], c = x[4], e = x[5], f = x[6];
  double o[3], d[3];
  if (mode == 0) {
    o[0] = a, o[1] = b, o[2] = c;
    d[0] = e, d[1] = f, d[2] = a * b;
  } else {
    if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(e)) return 0;
    const double u = a, v = mode == 1 ? a * 7 : e;
    const double n[3] = {std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
    const double p[3] = {R * std::cos(u) + r * n[0], R * std::sin(u) + r * n[1], r * n[2]};
    if (mode == 1) {
      o[0] = c, o[1] = e, o[2] = f;
      for (int i = 0; i < 3; ++i) d[i] = p[i] + b * r * n[i] - o[i];
    } else {
      // A tangent: n x (the axis, or x where n is along the axis).
      double tg[3] = {-n[1], n[0], 0};
      if (std::hypot(tg[0], tg[1]) < 1e-3) tg[0] = 0, tg[1] = -n[2], tg[2] = n[1];
      const double len = std::hypot(tg[0], tg[1], tg[2]);
      for (int i = 0; i < 3; ++i) {
        d[i] = tg[i] / len * std::cos(b) - n[i] * std::sin(b);
        o[i] = p[i] - d[i] * (c * r);
      }
    }
  }
  if (!finite3(o) || !finite3(d) || (d[0] == 0 && d[1] == 0 && d[2] == 0)) return 0;
  for (const toroid::TorusSolver s :
       {toroid::TorusSolver::Default, toroid::TorusSolver::Ferrari, toroid::TorusSolver::Tianheng}) {
    double t[4];
    const int count = toroid::intersect_torus(R, r, o, d, t, s);
    const bool in_domain = R / r < toroid::kTorusAspectLimit;
    if (s == toroid::TorusSolver::Default) check_copy_matches_baseline(R, r, o, d, t, count);
    if (s == toroid::TorusSolver::Default && in_domain) {
      toroid::fuzz::check_torus_roots(R, r, o, d, t, count);
      check_blocks_agrees_with_nearest(R, r, o, d, t, count);
      check_nearest_from_each_root(R, r, o, d, t, count);
      check_hull_test_passes_no_meeting_ray(R, r, o, d, t, count);
    } else {
      // The closed-form solvers make no accuracy promise (docs/torus.md),
      // nor the default one on tubes thinner than its stated domain: only
      // the count, finiteness and order are theirs to keep.
      toroid::fuzz::check_torus_root_list(R, r, o, d, t, count);
    }
  }
  return 0;
}
