// SPDX-License-Identifier: Apache-2.0
// Ray–torus intersection. See docs/torus.md for the derivation and the
// accuracy figures; the short version of the default solver:
//
//  1. The quartic P(t) = (|p|^2 + R^2 - r^2)^2 - 4 R^2 rho^2 factors exactly as
//     P = h_out * h_in with
//        h_out(t) = (rho - R)^2 + z^2 - r^2   (the tube around the centre circle)
//        h_in(t)  = (rho + R)^2 + z^2 - r^2   (the spindle's inner "lemon"),
//     rho = distance of p(t) = o + t d from the axis. Each factor is evaluated
//     directly from the point: no O(R^4) coefficients cancel into an O(R^2 r^2)
//     value, which is what ruins the quartic for thin tubes and far origins.
//  2. rho(t) is the distance to a line, so rho'' = K / rho^3 with K constant
//     along the ray; hence h_out'' = 2|d|^2 - 2 R K / rho^3 changes sign at
//     most twice, at points known in closed form, and h_in is convex. Cut at
//     those points, each piece is convex or concave, which is known from
//     where it lies: a sign change between its ends is one root; equal signs
//     on the side that allows it are none or two, decided by where the end
//     tangents cross (their crossing bounds h, or h there has the other sign
//     and brackets both roots). Each root is polished by Halley's iteration
//     (h'' and h''' come free with h), guarded by bisection, and stops as soon
//     as the error predicted from the derivatives is below the tolerance. So
//     no root is missed, whatever the structure: double roots (tangent rays)
//     are extrema that touch zero, settled in double-double.
//  3. The origin is first moved, exactly (double-double), to the ray's point
//     nearest the centre, so that far cameras lose nothing; t is returned
//     relative to the original origin.
#include "toroid/torus/intersect.h"

#include "toroid/math/cube_root.h"
#include "toroid/math/double_double.h"
#include "toroid/roots/monotone.h"
#include "toroid/roots/polynomial.h"
#include "toroid/torus/hole.h"
#include "toroid/torus/hull.h"
#include "toroid/torus/solver_copies.h"

#include <algorithm>
#include <cmath>
#include <limits>

// The public calls below run the default solver in the copy of this file
// built for AVX2 and FMA where the processor has them (solver_copies.h); the
// closed forms, the copy itself and the CUDA build run this code.
#if TOROID_SOLVER_AVX2_COPY && !defined(TOROID_SOLVER_COPY) && !defined(__CUDACC__)
#define TOROID_DISPATCHES_SOLVER 1
#else
#define TOROID_DISPATCHES_SOLVER 0
#endif

namespace toroid {

#if !defined(TOROID_SOLVER_COPY) && !defined(__CUDACC__)
namespace x86_64_v3 {

bool available() {
#if TOROID_SOLVER_AVX2_COPY
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi") &&
           __builtin_cpu_supports("bmi2");
  }();
  return has;
#else
  return false;
#endif
}

namespace {
// Read by every public call: a plain flag, set once at load time (a call made
// before, from another file's static initialiser, runs the baseline code,
// which gives the same answers).
bool enabled_flag = available();
}  // namespace

bool enabled() { return enabled_flag; }
void set_enabled_for_testing(bool enabled) { enabled_flag = enabled && available(); }
}  // namespace x86_64_v3
#endif

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Where the ray passes the axis, rho carries the rounding of p's x and y,
// about eps |o_xy|, so a sample there resolves h'' only where rho is well
// above it: h_out's concave stretch beside the axis is cut at its edges
// (rho = rho_i) when rho_i exceeds kAxisBlur |o_xy| (rho's relative error
// there is then below 2^-18), and as a kink at the axis passage otherwise.
constexpr double kAxisBlur = 0x1p-32;

// A factor's value and first three derivatives at s.
struct Sample {
  double s, h, dh, d2h, d3h;
};

// One factor of the torus quartic along the ray, in the shifted frame
// p(s) = origin + s * d. sign = -1 gives h_out, +1 gives h_in.
class TorusFactor {
 public:
  [[gnu::always_inline]] TOROID_HD TorusFactor(const DoubleDouble o[3], const double d[3], double major, double minor,
                                               double sign)
      : d_{d[0], d[1], d[2]}, R_(major), r_(minor), sign_(sign) {
    for (int i = 0; i < 3; ++i) {
      o_hi_[i] = o[i].hi;
      o_lo_[i] = o[i].lo;
    }
    dd_ = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    c_ = d[0] * d[0] + d[1] * d[1];
    const double cross = o_hi_[0] * d[1] - o_hi_[1] * d[0];
    K_ = cross * cross;
  }

  TOROID_HD double dd() const { return dd_; }
  TOROID_HD double major() const { return R_; }
  TOROID_HD bool is_outer() const { return sign_ < 0; }
  TOROID_HD double c() const { return c_; }
  TOROID_HD double K() const { return K_; }

  // h and its derivatives at s. `side` picks the one-sided derivative of rho
  // where the ray crosses the axis (rho = 0): -1 from the left, +1 from the
  // right. h'' = 2|d|^2 + sign 2 R K / rho^3 and h''' = -3 (h'' - 2|d|^2) rho'/rho
  // cost no extra square root. At an axis cut (`at_axis_cut`) rho is at or
  // below its own rounding, so it is treated as the kink at rho = 0: rho'
  // is side |d_xy| and h'' is 2|d|^2 (the spike of h'' beside the axis is
  // narrower than the samples resolve, and is left out).
  TOROID_HD Sample sample(double s, double side = 1.0, bool at_axis_cut = false) const {
    double p[3];
    for (int i = 0; i < 3; ++i) p[i] = o_hi_[i] + (s * d_[i] + o_lo_[i]);
    const double rho2 = p[0] * p[0] + p[1] * p[1];
    const double rho = std::sqrt(rho2);
    const double a = rho + sign_ * R_;  // rho - R, or rho + R
    const double h = (a - r_) * (a + r_) + p[2] * p[2];
    if (rho == 0 || at_axis_cut) return {s, h, 2.0 * (a * side * std::sqrt(c_) + p[2] * d_[2]), 2.0 * dd_, 0.0};
    const double inv_rho = 1.0 / rho;
    const double drho = (p[0] * d_[0] + p[1] * d_[1]) * inv_rho;
    const double k = sign_ * 2.0 * R_ * K_ * (inv_rho * inv_rho * inv_rho);
    return {s, h, 2.0 * (a * drho + p[2] * d_[2]), 2.0 * dd_ + k, -3.0 * k * drho * inv_rho};
  }

  // Where the ray passes nearest the axis (NaN for a ray along it).
  TOROID_HD double axis_passage() const {
    return c_ > 0 ? -(o_hi_[0] * d_[0] + o_hi_[1] * d_[1]) / c_ : std::numeric_limits<double>::quiet_NaN();
  }

  // rho^2 at s, as sample() computes it.
  TOROID_HD double rho2(double s) const {
    const double x = o_hi_[0] + (s * d_[0] + o_lo_[0]), y = o_hi_[1] + (s * d_[1] + o_lo_[1]);
    return x * x + y * y;
  }

  // h alone at s, as sample() computes it.
  TOROID_HD double value(double s) const {
    double p[3];
    for (int i = 0; i < 3; ++i) p[i] = o_hi_[i] + (s * d_[i] + o_lo_[i]);
    const double a = std::sqrt(p[0] * p[0] + p[1] * p[1]) + sign_ * R_;
    return (a - r_) * (a + r_) + p[2] * p[2];
  }

  // h at s in double-double arithmetic: used where double rounding would
  // decide the answer (near-tangent rays, whose two roots are ill-conditioned).
  TOROID_HD double eval_precise(double s) const {
    DoubleDouble p[3];
    for (int i = 0; i < 3; ++i) p[i] = dd_add({o_hi_[i], o_lo_[i]}, two_prod(s, d_[i]));
    const DoubleDouble rho = dd_sqrt(dd_add(dd_mul(p[0], p[0]), dd_mul(p[1], p[1])));
    const DoubleDouble a = dd_add(rho, {sign_ * R_, 0});
    const DoubleDouble r2 = two_prod(r_, r_);
    const DoubleDouble h = dd_add(dd_add(dd_mul(a, a), dd_mul(p[2], p[2])), {-r2.hi, -r2.lo});
    return h.hi + h.lo;
  }

  TOROID_HD double minor() const { return r_; }

 private:
  double o_hi_[3], o_lo_[3];
  double d_[3];
  double R_, r_, sign_;
  double dd_, c_, K_;
};

// A first guess inside (lo, hi): Halley's step from `from` if it lands
// inside, else Newton's, else the midpoint.
TOROID_HD double first_guess(const Sample& from, double lo, double hi) {
  const double halley = from.s - 2 * from.h * from.dh / (2 * from.dh * from.dh - from.h * from.d2h);
  if (halley > lo && halley < hi) return halley;
  const double newton = from.s - from.h / from.dh;
  return newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
}

// The window (t_min, t_max) as the caller will test the roots against it.
struct CallerWindow {
  double t_min, t_max;
  int exponent;  // the solver's t times 2^exponent is the caller's
};

// The caller's window as the solver sees it: s = t - t_shift in the shifted
// frame, and t scaled by 2^-exponent when the torus or the direction was
// rescaled (solve_rescaled). s_min and s_max choose the pieces to search;
// whether a root s lies inside is decided on the t value the caller gets
// (t_shift + s, rounded, then scaled back, rounded again if it is
// subnormal), as the caller decides it. A search for the first root that
// stopped at a root inside (s_min, s_max) whose t rounds onto t_min would
// report none (a caller that asks for the root after the one it has, from
// exactly it).
struct Window {
  double s_min, s_max;
  double t_shift;
  CallerWindow caller;
  TOROID_HD double caller_t(double s) const {
    const double t = t_shift + s;
    return caller.exponent != 0 ? std::scalbn(t, caller.exponent) : t;
  }
  TOROID_HD bool holds(double s) const {
    const double t = caller_t(s);
    return t > caller.t_min && t < caller.t_max;
  }
};

// Collects the roots of one factor, in ascending order, piece by piece. On a
// piece the factor h is convex or concave, known from where the piece lies;
// with sigma = +1 or -1, g = sigma h is convex there, and the cases are few:
// g < 0 at both ends: no root; opposite signs: one root; g > 0 at both ends
// and falling then rising: none or two, decided by the tangents at the ends.
class RootCollector {
 public:
  // With `first_only`, a pair whose first root lies inside the window
  // leaves its second root out: the search stops at the first anyway.
  TOROID_HD RootCollector(const TorusFactor& f, double* out, double length_scale, bool first_only, const Window& window)
      : f_(f),
        out_(out),
        tol_root_(2 * kEps * length_scale),
        tol_extremum_(1e-10 * length_scale),
        first_only_(first_only),
        window_(window) {}
  TOROID_HD int count() const { return n_; }
  // Whether the next piece, which straddles the window's start, may leave
  // out a pair's roots that certainly lie before the start (two_or_none).
  TOROID_HD void set_start_cut(bool on) { start_cut_ = on; }
  // Whether a piece's answer hung on a near-tangent minimum, whose sign can
  // depend on the bracket it was searched on.
  TOROID_HD bool met_near_tangent() const { return met_near_tangent_; }
  // The root of h on (a.s, b.s), where h < 0 at a, h > 0 at b and h is
  // convex: Halley's iteration from b (Fourier's condition), bracketed.
  TOROID_HD double rising_root(const Sample& a, const Sample& b) { return root(a, b, b, true, false); }

  // Roots on the piece [a.s, b.s). A zero exactly at b.s counts only if `last`.
  // With `locate` false only whether there are roots matters (shadow rays):
  // a point of the piece stands for each root found, unrefined (for a single
  // root, the piece's middle: its start can round onto the window's start
  // once the shift is added back).
  TOROID_HD void piece(const Sample& a, const Sample& b, double sigma, bool last, bool locate = true) {
    if (a.s == b.s) {  // a chord of one point
      if (a.h == 0) push(a.s);
      return;
    }
    if (a.h == 0) push(a.s);
    // Signs of g just inside the ends (an end that is an exact zero takes the
    // sign g has next to it).
    const double ga = sigma * a.h, gb = sigma * b.h;
    const bool pos_a = ga != 0 ? ga > 0 : sigma * a.dh > 0;
    const bool pos_b = gb != 0 ? gb > 0 : sigma * b.dh < 0;
    if (pos_a != pos_b) {
      // One root. Newton from the end where g > 0 (Fourier's condition: g
      // and g'' agree) converges without overshoot.
      push(locate ? root(a, b, pos_a ? a : b, pos_a == (sigma < 0), false) : 0.5 * (a.s + b.s));
    } else if (pos_a && sigma * a.dh < 0 && sigma * b.dh > 0) {
      two_or_none(a, b, sigma, locate);
    }
    if (b.h == 0 && last) push(b.s);
  }

 private:
  // g > 0 at both ends, g' < 0 at a and > 0 at b: one minimum inside. The
  // tangents at the ends bound g from below; where they cross, either the
  // bound is positive (no root), or g is negative (a root on each side), or
  // g is positive and the piece shrinks to the side holding the minimum.
  TOROID_HD void two_or_none(Sample a, Sample b, double sigma, bool locate) {
    const double scale = f_.minor() * f_.minor();
    for (int it = 0; it < 8; ++it) {
      const double ga = sigma * a.h, gb = sigma * b.h, dga = sigma * a.dh, dgb = sigma * b.dh;
      double x = (gb - ga + dga * a.s - dgb * b.s) / (dga - dgb);
      if (!(x > a.s && x < b.s)) x = 0.5 * (a.s + b.s);
      if (ga + dga * (x - a.s) > 0) return;  // the lower bound stays positive
      const Sample m = f_.sample(x);
      const double gm = sigma * m.h;
      // Where the minimum is within 1e-6 r^2 of zero, the pair is close and
      // ill-conditioned in double (and g(m) >= the minimum): settle it precisely.
      if (std::abs(gm) < 1e-6 * scale) break;
      if (gm < 0) {
        if (!locate) {
          push(m.s);
          if (!ends_search(m.s)) push(m.s);
        } else if (first_only_) {
          switch (start_cut_ ? pair_before_start(a, m, sigma) : BeforeStart::Unsure) {
            case BeforeStart::Both: return;
            case BeforeStart::First: push(root(m, b, b, sigma > 0, false)); return;
            case BeforeStart::Unsure: break;
          }
          const double first = root(a, m, a, sigma < 0, false);
          push(first);
          if (!ends_search(first)) push(root(m, b, b, sigma > 0, false));
        } else {
          double first, second;
          root_pair(a, m, b, sigma, &first, &second);
          push(first);
          push(second);
        }
        return;
      }
      const double dgm = sigma * m.dh;
      if (dgm == 0) return;  // the minimum, and it is positive
      (dgm < 0 ? a : b) = m;
    }
    near_tangent(a, b, sigma, locate);
  }

  // The minimum of g is within rounding of zero (a near-tangent ray): find
  // it by Newton on g' and decide its sign in double-double.
  TOROID_HD void near_tangent(const Sample& a, const Sample& b, double sigma, bool locate) {
    met_near_tangent_ = true;
    double x0 = (b.h - a.h + a.dh * a.s - b.dh * b.s) / (a.dh - b.dh);
    if (!(x0 > a.s && x0 < b.s)) x0 = 0.5 * (a.s + b.s);
    const double m = solve_monotone(
        [&](double s) {
          const Sample v = f_.sample(s);
          return std::pair<double, double>{v.dh, v.d2h};
        },
        a.s, b.s, a.dh < 0, x0, tol_extremum_);
    const double hm = f_.eval_precise(m);
    if (hm == 0) {  // tangent: a double root
      push(m);
      push(m);
      return;
    }
    if (sigma * hm > 0) return;
    const Sample sm{m, hm, 0.0, 0.0, 0.0};
    const double first = locate ? root(a, sm, a, sigma < 0, true) : m;
    push(first);
    if (!ends_search(first)) push(locate ? root(sm, b, b, sigma > 0, true) : m);
  }

  TOROID_HD bool ends_search(double s) const { return first_only_ && window_.holds(s); }

  // Which roots of a pair (g(m) < 0 between them, g convex) certainly lie
  // before the window's start, for a ray that starts beside a surface it
  // leaves. The search of the whole pair locates the first root on (a, m),
  // so one before m lies before a start beyond m; otherwise g at the start
  // decides, beyond rounding (the bound two_or_none trusts): negative, the
  // start lies between the roots; positive and rising, past both. The roots
  // the search goes on to locate are located as before, so their bits are
  // the same; only the work on roots the query would drop is spared. (A
  // start before m where a's tangent, a lower bound of g, is still
  // positive lies before the pair: no sample is spent there.)
  enum class BeforeStart { Unsure, First, Both };
  TOROID_HD BeforeStart pair_before_start(const Sample& a, const Sample& m, double sigma) const {
    const double s_min = window_.s_min;
    if (m.s > s_min && sigma * (a.h + a.dh * (s_min - a.s)) > 0) return BeforeStart::Unsure;
    const Sample w = f_.sample(s_min);
    const double gw = sigma * w.h, uncertain = 1e-6 * f_.minor() * f_.minor();
    if (gw > uncertain && sigma * w.dh >= 0) return BeforeStart::Both;
    if (m.s <= s_min || gw < -uncertain) return BeforeStart::First;
    return BeforeStart::Unsure;
  }

  // The root of h on (a.s, b.s), where h changes sign once; Newton starts
  // from `start`'s step, `lo_negative` tells the sign of h at a.s.
  TOROID_HD double root(const Sample& a, const Sample& b, const Sample& start, bool lo_negative, bool precise) {
    RootSearch search(a, b, start, lo_negative, tol_root_);
    while (!search.done) search.step(f_, precise);
    if (precise) {
      // A close pair: the same iteration with the value in double-double,
      // on the whole bracket (the double iteration's signs may be rounding).
      return solve_monotone(
          [&](double s) {
            return std::pair<double, double>{f_.eval_precise(s), f_.sample(s).dh};
          },
          a.s, b.s, lo_negative, search.x, search.tol);
    }
    return search.x;
  }

  // The two roots of a pair, on (a.s, m.s) and (m.s, b.s): root() for each,
  // their iterations interleaved so that the processor overlaps the two
  // chains of dependent square roots and divisions. The same steps, so the
  // same bits, as two calls of root().
  TOROID_HD void root_pair(const Sample& a, const Sample& m, const Sample& b, double sigma, double* first,
                           double* second) {
    RootSearch left(a, m, a, sigma < 0, tol_root_), right(m, b, b, sigma > 0, tol_root_);
    while (!left.done && !right.done) {
      left.step(f_, false);
      right.step(f_, false);
    }
    while (!left.done) left.step(f_, false);
    while (!right.done) right.step(f_, false);
    *first = left.x;
    *second = right.x;
  }

  // Halley's iteration on a bracket where h changes sign once, one step at
  // a time; `x` is the root once `done`.
  struct RootSearch {
    TOROID_HD RootSearch(const Sample& a, const Sample& b, const Sample& start, bool lo_is_negative, double tol_root)
        : lo(a.s), hi(b.s), x(first_guess(start, a.s, b.s)), lo_negative(lo_is_negative) {
      tol = tol_root * 0.5 + 2 * kEps * std::abs(x);
    }

    TOROID_HD void step(const TorusFactor& f, bool precise) {
      const Sample v = f.sample(x);
      if (v.h == 0) {
        done = true;
        return;
      }
      ((v.h < 0) == lo_negative ? lo : hi) = x;
      // Halley's step: cubic convergence, with h'' and h''' free from sample().
      const double step = 2 * v.h * v.dh / (2 * v.dh * v.dh - v.h * v.d2h);
      double next = x - step;
      // Where |h h''| <= h'^2 the step is 2/3 to 2 times Newton's, h / h',
      // so a small step means a near root; elsewhere (beside an extremum of
      // h, or where a sample beside the axis is unreliable) it can be small
      // far from any root: then bisect.
      const bool halley = std::abs(v.h * v.d2h) <= v.dh * v.dh;
      if (!halley || !(next > lo && next < hi)) {  // also catches NaN
        // x is an end of the bracket now: a step that leaves x unchanged
        // is below x's resolution, and x is the root.
        if (halley && next == x) {
          done = true;
          return;
        }
        next = 0.5 * (lo + hi);
      } else if (!precise) {
        // The error after a Halley step is about |C| step^3, with
        // C = (h''/2h')^2 - h'''/6h': below the tolerance, no further sample needed.
        const double inv_dh = 1 / v.dh;
        const double q = 0.5 * (v.d2h * inv_dh);
        const double c = std::abs(q * q - (v.d3h * inv_dh) * (1.0 / 6));
        // (c step^2 first: it is dimensionless, so nothing underflows on
        // tori of any size.)
        if (c * (step * step) * std::abs(step) <= 0.25 * tol) {
          x = next;
          done = true;
          return;
        }
      }
      const double moved = std::abs(next - x);
      x = next;
      done = moved <= tol || hi - lo <= tol || ++iterations == 100;
    }

    double lo, hi, x, tol;
    bool lo_negative;
    bool done = false;
    int iterations = 0;
  };

  TOROID_HD void push(double s) {
    if (n_ < 4) out_[n_++] = s;
  }

  const TorusFactor& f_;
  double* out_;
  double tol_root_, tol_extremum_;
  bool first_only_;
  const Window& window_;
  int n_ = 0;
  bool met_near_tangent_ = false;
  bool start_cut_ = false;
};

// What a search wants: every root, the first one in the window, or only
// whether the window holds one (then a piece inside the window stops the
// search as soon as it holds a root, with a point of it for the root).
enum class Search { All, First, Any };

// Whether the ray's passage by the axis (s_axis) lies in [lo, hi] or within
// rho's rounding of it (axis_blur, see kAxisBlur), or the rounding of the s
// values themselves: there a convex piece may hold a spike of h'' narrower
// than the samples resolve, and a search of part of the piece and one of
// the whole can disagree.
TOROID_HD bool nears_axis_passage(const TorusFactor& f, double s_axis, double axis_blur, double lo, double hi) {
  const double reach = std::max(axis_blur / std::sqrt(f.c()), 4 * kEps * (std::abs(lo) + std::abs(hi)));
  return s_axis >= lo - reach && s_axis <= hi + reach;
}

// Whether the part of the piece [a.s, b.s] inside the window (s_min, s_max)
// certainly holds no root: the piece cut at the window's ends, with a sample
// there whose sign is beyond rounding (the bound two_or_none trusts), and
// the same sign and tangent tests on what is left. A shadow ray starts
// beside the surface it left, so a piece that straddles the window's start
// holds that surface's root just before it: this spares locating it. A
// piece that holds a root in the window, or whose answer on the cut piece
// hangs on a near-tangent minimum, is searched as a whole, as the
// nearest-root query searches it, so the two queries agree. An end
// at an axis cut is not moved: the window's end may lie within rho's
// rounding of the kink, where a sample's one-sided derivatives are unsure;
// nor is a convex piece cut where the part left holds the axis passage.
[[gnu::noinline]] TOROID_HD bool window_misses_piece(const TorusFactor& f, const Sample& a, const Sample& b,
                                                     double sigma, bool kink_at_a, bool kink_at_b, double s_axis,
                                                     double axis_blur, const Window& window) {
  const double s_min = window.s_min, s_max = window.s_max;
  const double uncertain = 1e-6 * f.minor() * f.minor();
  Sample lo = a, hi = b;
  if (lo.s < s_min) {
    if (kink_at_a) return false;
    lo = f.sample(s_min);
    if (!(std::abs(lo.h) > uncertain)) return false;
  }
  if (hi.s > s_max) {
    if (kink_at_b) return false;
    hi = f.sample(s_max);
    if (!(std::abs(hi.h) > uncertain)) return false;
  }
  if (!(lo.s < hi.s)) return false;
  // Not cut where the cut part of a convex piece nears the axis passage.
  if (sigma > 0 && nears_axis_passage(f, s_axis, axis_blur, lo.s, hi.s)) return false;
  double found[4];
  RootCollector probe(f, found, f.minor() / std::sqrt(f.dd()), false, window);
  probe.piece(lo, hi, sigma, true, false);
  return probe.count() == 0 && !probe.met_near_tangent();
}

// The part of the ray, in the shifted frame, inside the ball |p| <= radius
// and the slab |z| <= r, each inflated so that rounding never clips a root
// at its edge; empty (hi < lo) where the ray misses either.
struct Chord {
  double lo, hi;
};

TOROID_HD Chord chord_of(const TorusFactor& f, const DoubleDouble o[3], const double d[3], double radius) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  // Ball: dd s^2 + 2 b s + (|o|^2 - radius^2) = 0. The origin is the ray's
  // point nearest the centre, so b is ~0 and the chord is well conditioned.
  const double b = o[0].hi * d[0] + o[1].hi * d[1] + o[2].hi * d[2];
  const double oo = o[0].hi * o[0].hi + o[1].hi * o[1].hi + o[2].hi * o[2].hi;
  const double rad = radius * (1 + 1e-9) + 1e-300;
  const double disc = b * b - f.dd() * (oo - rad * rad);
  if (disc < 0) return {kInf, -kInf};
  const double w = std::sqrt(disc);
  double lo = (-b - w) / f.dd();
  double hi = (-b + w) / f.dd();
  // The torus lies in the slab |z| <= r: clip the chord to it, inflated by
  // 1e-9 r and by more than the rounding of z along the ray (a few eps |zo|),
  // which is the larger for thin tubes seen from afar: a root just inside a
  // face must stay inside the chord.
  const double zo = o[2].hi + o[2].lo;
  const double slab = std::max(f.minor() * (1 + 1e-9) + 1e-300, f.minor() + 8 * kEps * std::abs(zo));
  if (d[2] != 0) {
    double z_lo = (-slab - zo) / d[2], z_hi = (slab - zo) / d[2];
    if (z_lo > z_hi) std::swap(z_lo, z_hi);
    lo = std::max(lo, z_lo);
    hi = std::min(hi, z_hi);
  } else if (std::abs(zo) > slab) {
    return {kInf, -kInf};
  }
  return {lo, hi};
}

// The first root in the window of a ring torus's ray whose window starts
// inside the tube (a ray refracted into it, or reflected inside it), located
// from the start rather than from the pieces' ends: the tube is convex along
// the ray up to the chord's end, so h < 0 at the start and h > 0 at the
// chord's end bracket a single root, which Halley's iteration finds from the
// end. It is the root the list holds to the solver's tolerance, not always
// bit for bit (the list brackets it from the other side of the pair).
// Returns 1 with the root in *out, 0 when it lies beyond the window, and -1
// where the shortcut does not apply: a start outside the tube or within
// rounding of its surface (a caller walking the list from a root), h_out
// not convex beyond the start (the ray turns towards the axis), or a root
// so near the window's end that the list's root could lie on its other side.
[[gnu::noinline]] TOROID_HD int exit_from_inside(const TorusFactor& f, double hi, const Window& window, double* out) {
  const double R = f.major(), r = f.minor(), s_min = window.s_min;
  const Sample start = f.sample(s_min);
  // Inside beyond the rounding two_or_none trusts, and beyond h's rounding
  // at a start that is itself rounded (s_min = t_min - t_shift, to eps of
  // |t|: a caller walking a far ray's list from a root starts on the
  // surface only to that).
  const double reach = R + r + (std::abs(window.t_shift) + std::abs(s_min)) * std::sqrt(f.dd());
  if (!(start.h < -std::max(1e-6 * r * r, 0x1p-40 * r * reach))) return -1;
  // h_out'' = 2 |d|^2 - 2 R K / rho^3 >= 0 where rho^3 >= R K / |d|^2: on
  // [s_min, hi] at rho's least there (at the passage by the axis, if it lies
  // inside, else at an end), compared in sixth powers, with a margin far
  // above their rounding.
  const double c = f.c(), K = f.K();
  const double s_axis = f.axis_passage();  // NaN for a ray along the axis: the ends then
  const double rho2 = s_axis > s_min && s_axis < hi ? K / c : std::min(f.rho2(s_min), f.rho2(hi));
  const double rho_i3 = R * K / f.dd();
  if (!(rho2 * rho2 * rho2 > 1.01 * rho_i3 * rho_i3)) return -1;
  const Sample end = f.sample(hi);
  if (!(end.h > 0)) return -1;
  RootCollector collector(f, out, r / std::sqrt(f.dd()), true, window);
  const double x = collector.rising_root(start, end);
  // The list's root lies within the solver's tolerance of x (a few eps of
  // r / |d|, and of t): decide on x only where a margin far above that,
  // 1e-6 r / |d|, leaves the answer the same.
  const double margin = 1e-6 * r / std::sqrt(f.dd()) + 8 * kEps * (std::abs(x) + std::abs(window.t_shift));
  if (window.holds(x - margin) && window.holds(x + margin)) {
    *out = x;
    return 1;
  }
  return window.caller_t(x - margin) >= window.caller.t_max ? 0 : -1;
}

// Whether a shadow ray's window certainly holds a root of a ring torus
// (search Any), found before any cut or sample of the pieces: a point p of
// the window deep inside the tube (h_out(p) < -r^2/64, at least r/128 from
// the surface) and the window's end well outside it (h_out > r^2/64) hold a
// root between them, at least r / (128 |d|) from each, far beyond the
// solver's tolerance and the rounding of t (guarded), so the search would
// report it inside the window: the answer is the same, only cheaper. The
// candidates for p are where the ray crosses the torus's plane and the
// cylinder rho = R (where a ray through the tube usually is deepest);
// *stand_in is p, the window's point that stands for the root.
TOROID_HD bool window_certainly_blocked(const TorusFactor& f, const DoubleDouble o[3], const double d[3],
                                        const Window& window, double* stand_in) {
  const double R = f.major(), r = f.minor();
  if (!(r > 0x1p-16 * (R + r))) return false;  // h's rounding is then far below r^2/64
  const double deep = r * r / 64;
  const double margin = r / (128 * std::sqrt(f.dd()));
  if (!(margin > 0x1p-40 * (std::abs(window.t_shift) + 2 * std::abs(window.s_max)))) return false;
  double candidates[3];
  int n = 0;
  if (d[2] != 0) candidates[n++] = -(o[2].hi + o[2].lo) / d[2];
  // rho^2 = R^2: c s^2 + 2 b s + |o_xy|^2 - R^2 = 0.
  const double c = f.c(), b = o[0].hi * d[0] + o[1].hi * d[1];
  const double disc = b * b - c * (o[0].hi * o[0].hi + o[1].hi * o[1].hi - R * R);
  if (c > 0 && disc >= 0) {
    const double w = std::sqrt(disc);
    candidates[n++] = (-b - w) / c;
    candidates[n++] = (-b + w) / c;
  }
  for (int i = 0; i < n; ++i)
    if (f.value(candidates[i]) < -deep && window.holds(candidates[i])) {
      *stand_in = candidates[i];
      return f.value(window.s_max) > deep;
    }
  return false;
}

// Roots of one factor inside the ball |p| <= radius, in the shifted frame,
// ascending, restricted to the window. Pieces wholly outside (s_min, s_max)
// are skipped; see Search.
TOROID_HD int factor_roots(const TorusFactor& f, const DoubleDouble o[3], const double d[3], double radius,
                           const Window& window, Search search, double* out) {
  const double s_min = window.s_min, s_max = window.s_max;
  const Chord chord = chord_of(f, o, d, radius);
  const double lo = chord.lo, hi = chord.hi;
  if (hi < lo || hi < s_min || lo > s_max) return 0;
  if (search == Search::Any && f.is_outer() && f.minor() < f.major() && std::isfinite(s_max) &&
      window_certainly_blocked(f, o, d, window, out))
    return 1;
  // A window that starts inside the chord of a ring torus's tube may start
  // inside the tube (a ray refracted into it).
  if (search == Search::First && f.is_outer() && f.minor() < f.major() && lo < s_min) {
    const int exit = exit_from_inside(f, hi, window, out);
    if (exit >= 0) return exit;
  }
  if (f.is_outer()) {
    // The part of the chord inside the window lies in a ring torus's hole
    // (hole.h): no root there.
    const double limit = hole_limit(f.major(), f.minor());
    if (f.rho2(std::max(lo, s_min)) < limit && f.rho2(std::min(hi, s_max)) < limit) return 0;
  }

  // Breakpoints of convexity: the axis crossing when K = 0 (a kink of rho),
  // else for h_out the two points s_axis -+ hw where rho^3 = R K / |d|^2;
  // h_out is concave between them, convex elsewhere; h_in is convex. Where
  // the ray passes the axis within rho's rounding, the passage is a kink
  // for either factor.
  double cuts[4];
  bool axis_cut[4] = {false, false, false, false};
  int ncut = 0;
  cuts[ncut++] = lo;
  double concave_lo = 0, concave_hi = 0;  // empty: convex everywhere
  // Where the ray passes closest to the axis (NaN for a ray along it), and
  // rho's rounding there (see kAxisBlur).
  const double s_axis = f.axis_passage();
  const double blur = kAxisBlur * (std::abs(o[0].hi) + std::abs(o[1].hi));
  if (f.c() > 0) {
    if (f.K() == 0) {
      if (s_axis > lo && s_axis < hi) axis_cut[ncut] = true, cuts[ncut++] = s_axis;
    } else if (f.is_outer()) {
      // h_out'' < 0 somewhere iff it is at the ray's point nearest the axis,
      // rho_min^2 = K / c: iff (R K / |d|^2)^2 > (K / c)^3. Only then is the
      // cube root needed.
      const double rho_i3 = f.major() * f.K() / f.dd(), rho_min2 = f.K() / f.c();
      // For a ray that passes within ~1e-50 torus sizes of the axis the
      // square and the cube underflow: then the roots themselves decide, or,
      // where a root underflows too (within ~1e-100 of the axis), the same
      // test in exponents, R^2 c^3 > K |d|^4. A rho_i that underflows to 0
      // is a passage within rho's rounding of the axis, cut as a kink below.
      const double square = rho_i3 * rho_i3;
      constexpr double kNormal = std::numeric_limits<double>::min();
      const bool concave = square > rho_min2 * rho_min2 * rho_min2 ||
                           (square < 0x1p-1000 && (rho_i3 >= kNormal && rho_min2 >= kNormal
                                                       ? cube_root(rho_i3) > std::sqrt(rho_min2)
                                                       : 2 * std::log2(f.major()) + 3 * std::log2(f.c()) >
                                                             std::log2(f.K()) + 2 * std::log2(f.dd())));
      if (concave) {
        const double rho_i = cube_root(rho_i3);
        const double hw = rho_i > blur ? std::sqrt(std::max(0.0, rho_i * rho_i - rho_min2) / f.c()) : 0.0;
        // A half-width that underflows to 0 although rho_min is well below
        // rho_i (a ray that passes the axis far closer than rho_i, at a
        // large |d|) leaves a stretch narrower than any s between: a kink
        // too. (The batch sends such rays to this code: their square
        // underflows.)
        if (rho_i > blur && !(hw == 0 && rho_min2 < 0.25 * rho_i * rho_i)) {
          concave_lo = s_axis - hw;
          concave_hi = s_axis + hw;
          if (concave_lo > lo && concave_lo < hi) cuts[ncut++] = concave_lo;
          if (concave_hi > lo && concave_hi < hi) cuts[ncut++] = concave_hi;
        } else if (s_axis > lo && s_axis < hi) {
          // The concave stretch is too narrow for rho's rounding (see
          // kAxisBlur), or for s's: the axis passage is cut as a kink.
          axis_cut[ncut] = true, cuts[ncut++] = s_axis;
        }
      }
    } else if (s_axis > lo && s_axis < hi && f.K() <= blur * blur * f.c()) {
      // h_in beside the axis: rho_min = sqrt(K / c) below the rounding of
      // rho is a kink of h_in, which near_tangent would locate
      // too coarsely for the sign of its minimum (a nearly horn spindle's
      // lemon); cut as for K = 0, each side is a plain convex piece.
      axis_cut[ncut] = true, cuts[ncut++] = s_axis;
    }
  }
  cuts[ncut] = hi;

  RootCollector collector(f, out, f.minor() / std::sqrt(f.dd()), search != Search::All, window);
  Sample start = f.sample(lo, +1.0);
  for (int i = 0; i < ncut; ++i) {
    // Each cut is sampled once and shared by the pieces on either side (from
    // each side at an axis crossing, where rho has a kink).
    const Sample end = f.sample(cuts[i + 1], -1.0, axis_cut[i + 1]);
    const Sample next_start = axis_cut[i + 1] ? f.sample(cuts[i + 1], +1.0, true) : end;
    if (cuts[i + 1] >= s_min && cuts[i] <= s_max) {
      const double mid = 0.5 * (cuts[i] + cuts[i + 1]);
      const double sigma = mid > concave_lo && mid < concave_hi ? -1.0 : 1.0;
      const bool inside_window = cuts[i] > s_min && cuts[i + 1] < s_max;
      // A convex piece that straddles the window's start, away from the
      // axis passage (see window_misses_piece): the nearest-root query may
      // leave out a pair's roots before the start (RootCollector::piece).
      bool start_cut = search == Search::First && sigma > 0 && cuts[i] < s_min && !axis_cut[i];
      if (start_cut) {
        start_cut = !nears_axis_passage(f, s_axis, blur, s_min, cuts[i + 1]);
      }
      collector.set_start_cut(start_cut);
      if (search != Search::Any || inside_window ||
          !window_misses_piece(f, start, end, sigma, axis_cut[i], axis_cut[i + 1], s_axis, blur, window))
        collector.piece(start, end, sigma, i + 1 == ncut, !(search == Search::Any && inside_window));
      if (search != Search::All) {
        for (int k = 0; k < collector.count(); ++k)
          if (window.holds(out[k])) return collector.count();
      }
    }
    start = next_start;
  }
  return collector.count();
}

// The ray with its origin moved, exactly, to its point nearest the centre.
// It and the TorusFactor constructor are always inlined, as solve_in_range
// is, so that the common path makes no call.
struct ShiftedRay {
  DoubleDouble o[3];
  double t_shift;
};

[[gnu::always_inline]] TOROID_HD inline ShiftedRay shift_to_nearest_centre_point(const double origin[3],
                                                                                 const double d[3]) {
  const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double od = origin[0] * d[0] + origin[1] * d[1] + origin[2] * d[2];
  ShiftedRay r;
  // Any double near the true value works: the shift itself is exact.
  r.t_shift = dd > 0 ? -od / dd : 0.0;
  for (int i = 0; i < 3; ++i) r.o[i] = add_scaled(origin[i], r.t_shift, d[i]);
  return r;
}

// Whether the torus's size and |d|^2 lie in the range where the factors'
// products (R^2, r^2, |p|^2, |d|^2 and the derivatives) neither underflow
// nor overflow.
TOROID_HD bool in_solver_range(double R, double r, const double d[3]) {
  const double size = R + r, dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  return size > 0x1p-100 && size < 0x1p100 && dd > 0x1p-400 && dd < 0x1p400;
}

// The default solver on a torus and direction in_solver_range; writes roots
// as t values. (t_min, t_max) is the window in the solver's scale, `caller`
// the window as the caller will test the roots against it. Inlined into both
// callers, so that the common path is one function, as it would be without
// solve_rescaled.
[[gnu::always_inline]] TOROID_HD inline int solve_in_range(double R, double r, const double origin[3],
                                                           const double d[3], double t_min, double t_max,
                                                           const CallerWindow& caller, Search search, double t[4]) {
  const ShiftedRay ray = shift_to_nearest_centre_point(origin, d);
  const Window window{t_min - ray.t_shift, t_max - ray.t_shift, ray.t_shift, caller};
  // A window query on a ray that leaves the torus's hull from the window's
  // start (hull.h): a shadow or reflected ray from the tube's outer half.
  // Only a window that starts less than R / |d| before the ray's point
  // nearest the centre can: rays aimed at the torus from afar skip the test.
  if (search != Search::All) {
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if ((window.s_min >= 0 || window.s_min * window.s_min * dd < R * R) &&
        (ray_leaves_hull(R, r, origin, d, t_min) || ray_leaves_through_hole(R, r, origin, d, t_min)))
      return 0;
  }
  double s_out[4], s_in[4];
  const TorusFactor outer(ray.o, d, R, r, -1.0);
  // With the lemon's roots to merge, the outer sheet's are all needed.
  int n_out = factor_roots(outer, ray.o, d, R + r, window, r < R ? search : Search::All, s_out);
  int n_in = 0;
  if (r >= R) {
    const TorusFactor inner(ray.o, d, R, r, +1.0);
    if (r > R) {  // the spindle's lemon
      n_in = factor_roots(inner, ray.o, d, std::sqrt((r - R) * (r + R)), window, Search::All, s_in);
    } else {
      // The horn torus's lemon is its centre alone, where h_in reads 0 only
      // within rounding of it: searched as a chord, every sample on it would
      // read 0. The quartic's root there is double (fourfold along the axis),
      // listed twice: the outer sheet lists it once (at the kink where the
      // ray crosses the axis) or twice (the two ends of a concave stretch
      // narrower than rounding, or a tangent along the axis), so an odd
      // count gets one more.
      int at_centre = 0;
      for (int i = 0; i < n_out; ++i)
        if (inner.sample(s_out[i]).h == 0) s_in[0] = s_out[i], ++at_centre;
      n_in = at_centre % 2;
    }
  }
  // Merge the two ascending lists.
  int n = 0, i = 0, j = 0;
  while ((i < n_out || j < n_in) && n < 4) {
    const double s = (j >= n_in || (i < n_out && s_out[i] <= s_in[j])) ? s_out[i++] : s_in[j++];
    t[n++] = ray.t_shift + s;
  }
  return n;
}

// solve_in_range on a torus or a direction far from unit size: scaled by
// powers of two into the range, solved, and t scaled back.
[[gnu::noinline, gnu::cold]] TOROID_HD int solve_rescaled(double R, double r, const double origin[3], const double d[3],
                                                          double t_min, double t_max, Search search, double t[4]) {
  // The power of two to scale by: 0 within the range, or for 0, inf and NaN.
  const auto exponent_outside = [](double x, double lo, double hi) {
    return x > 0 && std::isfinite(x) && !(x > lo && x < hi) ? std::ilogb(x) : 0;
  };
  const int k = exponent_outside(R + r, 0x1p-100, 0x1p100);
  const int j = exponent_outside(std::max({std::abs(d[0]), std::abs(d[1]), std::abs(d[2])}), 0x1p-200, 0x1p200);
  if (k == 0 && j == 0) return 0;  // a radius or the direction is 0, infinite or NaN: no ray, no torus
  // p = o + t d becomes 2^-k p = o' + t' d' with o' = 2^-k o, d' = 2^-j d,
  // t' = 2^(j-k) t.
  const double o_s[3] = {std::scalbn(origin[0], -k), std::scalbn(origin[1], -k), std::scalbn(origin[2], -k)};
  const double d_s[3] = {std::scalbn(d[0], -j), std::scalbn(d[1], -j), std::scalbn(d[2], -j)};
  // An origin more than the largest double of torus sizes away sees nothing.
  if (!std::isfinite(o_s[0]) || !std::isfinite(o_s[1]) || !std::isfinite(o_s[2])) return 0;
  // Scaled, the torus and the direction are in range, unless a radius or
  // the direction holds a NaN or an infinity: no ray, no torus.
  const double R_s = std::scalbn(R, -k), r_s = std::scalbn(r, -k);
  if (!in_solver_range(R_s, r_s, d_s)) return 0;
  // A root beyond the largest double (a tiny direction) is not representable:
  // left out, and the window ends there, so that a search for the first
  // root in it does not stop at one that is left out.
  const double t_limit = std::scalbn(std::numeric_limits<double>::max(), j - k);
  const double lo = std::max(std::scalbn(t_min, j - k), -t_limit), hi = std::min(std::scalbn(t_max, j - k), t_limit);
  double found[4];
  const int m = solve_in_range(R_s, r_s, o_s, d_s, lo, hi, CallerWindow{t_min, t_max, k - j}, search, found);
  int n = 0;
  for (int i = 0; i < m; ++i)
    if (const double ti = std::scalbn(found[i], k - j); std::isfinite(ti)) t[n++] = ti;
  return n;
}

// The default solver; writes roots as t values. A torus far from unit size
// would underflow or overflow the factors' products, and a direction far
// from unit length |d|^2 and the derivatives: then the geometry (radii and
// origin) and the direction are each scaled by a power of two, which is
// exact, and so is scaling t back (solve_rescaled). Not recursive, so that
// the device's stack size is known. Inlined into each caller, so that each
// query's path is built for its own search (the all-roots path without the
// window queries' hull test).
[[gnu::always_inline]] TOROID_HD inline int solve_default(double R, double r, const double origin[3], const double d[3],
                                                          double t_min, double t_max, Search search, double t[4]) {
  if (!in_solver_range(R, r, d)) return solve_rescaled(R, r, origin, d, t_min, t_max, search, t);
  return solve_in_range(R, r, origin, d, t_min, t_max, CallerWindow{t_min, t_max, 0}, search, t);
}

// Sort a few values in place (insertion sort: at most four).
TOROID_HD void sort_small(double* v, int n) {
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && v[j] < v[j - 1]; --j) std::swap(v[j], v[j - 1]);
}

}  // namespace

TOROID_HD void torus_quartic_coefficients(double R, double r, const double o[3], const double d[3], double coeffs[5]) {
  // |o + t d|^2 = alpha t^2 + 2 beta t + |o|^2, and gamma = |o|^2 + R^2 - r^2:
  // (alpha t^2 + 2 beta t + gamma)^2 = 4 R^2 ((ox + t dx)^2 + (oy + t dy)^2).
  const double alpha = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const double beta = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
  const double gamma = o[0] * o[0] + o[1] * o[1] + o[2] * o[2] + R * R - r * r;
  const double four_r2 = 4 * R * R;
  coeffs[0] = alpha * alpha;
  coeffs[1] = 4 * alpha * beta;
  coeffs[2] = 2 * alpha * gamma + 4 * beta * beta - four_r2 * (d[0] * d[0] + d[1] * d[1]);
  coeffs[3] = 4 * beta * gamma - 2 * four_r2 * (o[0] * d[0] + o[1] * d[1]);
  coeffs[4] = gamma * gamma - four_r2 * (o[0] * o[0] + o[1] * o[1]);
}

TOROID_HD int intersect_torus(double major, double minor, const double origin[3], const double direction[3],
                              double t[4], TorusSolver solver) {
#if TOROID_DISPATCHES_SOLVER
  if (solver == TorusSolver::Default && x86_64_v3::enabled())
    return x86_64_v3::intersect_torus(major, minor, origin, direction, t, solver);
#endif
  constexpr double kInf = std::numeric_limits<double>::infinity();
  if (solver == TorusSolver::Default)
    return solve_default(major, minor, origin, direction, -kInf, kInf, Search::All, t);
  double k[5];
  torus_quartic_coefficients(major, minor, origin, direction, k);
  double found[4];
  const int m = solver == TorusSolver::Ferrari ? solve_quartic_ferrari(k[0], k[1], k[2], k[3], k[4], found)
                                               : solve_quartic_tianheng(k[0], k[1], k[2], k[3], k[4], found);
  // Coefficients that overflow give NaN or infinite "roots": not roots.
  int n = 0;
  for (int i = 0; i < m; ++i)
    if (std::isfinite(found[i])) t[n++] = found[i];
  sort_small(t, n);
  return n;
}

namespace {

// The first root in (t_min, t_max), to the search's precision.
TOROID_HD bool first_root_in(double major, double minor, const double origin[3], const double direction[3],
                             double t_min, double t_max, double* t, TorusSolver solver, Search search) {
  // On a spindle or horn torus the list merges the two factors' roots and
  // keeps four: near a tangent, rounding can give the factors more than four
  // between them, and which four a window's search would keep depends on
  // the window. There the queries read the whole list, so that they give
  // its roots.
  const bool from_list = solver != TorusSolver::Default || !(minor < major);
  double roots[4];
  const int n = from_list ? intersect_torus(major, minor, origin, direction, roots, solver)
                          : solve_default(major, minor, origin, direction, t_min, t_max, search, roots);
  for (int i = 0; i < n; ++i)
    if (roots[i] > t_min && roots[i] < t_max) {
      *t = roots[i];
      return true;
    }
  return false;
}

}  // namespace

TOROID_HD bool intersect_torus_nearest(double major, double minor, const double origin[3], const double direction[3],
                                       double t_min, double t_max, double* t, TorusSolver solver) {
#if TOROID_DISPATCHES_SOLVER
  if (solver == TorusSolver::Default && x86_64_v3::enabled())
    return x86_64_v3::intersect_torus_nearest(major, minor, origin, direction, t_min, t_max, t, solver);
#endif
  return first_root_in(major, minor, origin, direction, t_min, t_max, t, solver, Search::First);
}

TOROID_HD bool torus_blocks(double major, double minor, const double origin[3], const double direction[3], double t_min,
                            double t_max, TorusSolver solver) {
#if TOROID_DISPATCHES_SOLVER
  if (solver == TorusSolver::Default && x86_64_v3::enabled())
    return x86_64_v3::torus_blocks(major, minor, origin, direction, t_min, t_max, solver);
#endif
  double t;
  return first_root_in(major, minor, origin, direction, t_min, t_max, &t, solver, Search::Any);
}

}  // namespace toroid
