// SPDX-License-Identifier: Apache-2.0
#include "accuracy/reference.h"

#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace toroid::accuracy {
namespace {

constexpr mpfr_prec_t kPrec = 768;

// Small RAII wrapper so the polynomial code reads like arithmetic.
class Mp {
 public:
  Mp() {
    mpfr_init2(v_, kPrec);
    mpfr_set_zero(v_, 1);
  }
  Mp(double x) {
    mpfr_init2(v_, kPrec);
    mpfr_set_d(v_, x, MPFR_RNDN);
  }  // NOLINT: implicit by design
  Mp(const Mp& o) {
    mpfr_init2(v_, kPrec);
    mpfr_set(v_, o.v_, MPFR_RNDN);
  }
  Mp& operator=(const Mp& o) {
    mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  ~Mp() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }
  long double to_ld() const { return mpfr_get_ld(v_, MPFR_RNDN); }
  int sign() const { return mpfr_sgn(v_); }

  friend Mp operator+(const Mp& a, const Mp& b) {
    Mp r;
    mpfr_add(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  friend Mp operator-(const Mp& a, const Mp& b) {
    Mp r;
    mpfr_sub(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  friend Mp operator*(const Mp& a, const Mp& b) {
    Mp r;
    mpfr_mul(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  friend Mp operator/(const Mp& a, const Mp& b) {
    Mp r;
    mpfr_div(r.v_, a.v_, b.v_, MPFR_RNDN);
    return r;
  }
  friend Mp operator-(const Mp& a) {
    Mp r;
    mpfr_neg(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend bool operator<(const Mp& a, const Mp& b) { return mpfr_less_p(a.v_, b.v_); }
  friend Mp abs(const Mp& a) {
    Mp r;
    mpfr_abs(r.v_, a.v_, MPFR_RNDN);
    return r;
  }
  friend Mp sqrt(const Mp& a) {
    Mp r;
    mpfr_sqrt(r.v_, a.v_, MPFR_RNDN);
    return r;
  }

 private:
  mpfr_t v_;
};

using Poly = std::vector<Mp>;  // coefficients, index = power

Mp eval(const Poly& p, const Mp& x) {
  Mp r = p.back();
  for (int i = static_cast<int>(p.size()) - 2; i >= 0; --i) r = r * x + p[i];
  return r;
}

// Sum of |c_i||x|^i: the scale against which P(x) = 0 is judged.
Mp eval_abs(const Poly& p, const Mp& x) {
  const Mp ax = abs(x);
  Mp r = abs(p.back());
  for (int i = static_cast<int>(p.size()) - 2; i >= 0; --i) r = r * ax + abs(p[i]);
  return r;
}

Poly derivative(const Poly& p) {
  Poly d;
  for (size_t i = 1; i < p.size(); ++i) d.push_back(p[i] * Mp(static_cast<double>(i)));
  return d;
}

struct MpRoot {
  Mp x;
  bool exact_double;
};

// Root of p in [a, b] where p(a), p(b) have opposite signs: Newton guarded by bisection.
Mp bracketed_root(const Poly& p, const Poly& dp, Mp a, Mp b, int sign_a) {
  Mp x = (a + b) * Mp(0.5);
  for (int it = 0; it < 4000; ++it) {
    const Mp v = eval(p, x);
    if (v.sign() == 0) return x;
    if (v.sign() == sign_a)
      a = x;
    else
      b = x;
    Mp next = x - v / eval(dp, x);
    if (!(a < next && next < b)) next = (a + b) * Mp(0.5);
    const Mp step = abs(next - x);
    x = next;
    Mp width = abs(b - a);
    mpfr_mul_2si(width.get(), width.get(), kPrec - 16, MPFR_RNDN);
    Mp step_scaled = step;
    mpfr_mul_2si(step_scaled.get(), step_scaled.get(), kPrec - 16, MPFR_RNDN);
    const Mp mag = abs(x) + Mp(1e-300);
    if (step_scaled < mag || width < mag) break;
  }
  return x;
}

// All real roots with multiplicity (1 or 2, which is all a torus needs; an
// exact triple or quadruple root is reported via repeated doubles).
std::vector<MpRoot> real_roots(const Poly& p) {
  const int n = static_cast<int>(p.size()) - 1;
  if (n == 1) return {{-p[0] / p[1], false}};
  const Poly dp = derivative(p);
  const std::vector<MpRoot> crit = real_roots(dp);
  // Cauchy bound on the roots.
  Mp bound = Mp(1);
  for (int i = 0; i < n; ++i) {
    const Mp q = abs(p[i] / p[n]) + Mp(1);
    if (bound < q) bound = q;
  }
  std::vector<Mp> pts{-bound};
  std::vector<MpRoot> out;
  std::vector<bool> pt_is_root{false};
  for (const MpRoot& c : crit) {
    const Mp v = eval(p, c.x);
    Mp scale = eval_abs(p, c.x);
    mpfr_mul_2si(scale.get(), scale.get(), -(kPrec - 64), MPFR_RNDN);
    const bool touches = abs(v) < scale;
    pts.push_back(c.x);
    pt_is_root.push_back(touches);
  }
  pts.push_back(bound);
  pt_is_root.push_back(false);
  for (size_t i = 0; i + 1 < pts.size(); ++i) {
    if (pt_is_root[i]) {
      // A critical point on zero: a double root, unless a neighbouring
      // critical point coincides (higher multiplicity: counted again there).
      out.push_back({pts[i], true});
      out.push_back({pts[i], true});
      continue;
    }
    if (pt_is_root[i + 1]) continue;
    const int sa = eval(p, pts[i]).sign(), sb = eval(p, pts[i + 1]).sign();
    if (sa != 0 && sb != 0 && sa != sb) out.push_back({bracketed_root(p, dp, pts[i], pts[i + 1], sa), false});
  }
  return out;
}

void torus_terms(const RayCase& c, Mp& alpha, Mp& beta, Mp& gamma, Mp& cxy, Mp& bxy, Mp& axy) {
  const Mp ox(c.origin[0]), oy(c.origin[1]), oz(c.origin[2]);
  const Mp dx(c.direction[0]), dy(c.direction[1]), dz(c.direction[2]);
  const Mp R(c.major), r(c.minor);
  alpha = dx * dx + dy * dy + dz * dz;
  beta = ox * dx + oy * dy + oz * dz;
  gamma = ox * ox + oy * oy + oz * oz + R * R - r * r;
  cxy = dx * dx + dy * dy;
  bxy = ox * dx + oy * dy;
  axy = ox * ox + oy * oy;
}

}  // namespace

std::vector<ReferenceRoot> reference_roots(const RayCase& c) {
  Mp alpha, beta, gamma, cxy, bxy, axy;
  torus_terms(c, alpha, beta, gamma, cxy, bxy, axy);
  const Mp four_r2 = Mp(4) * Mp(c.major) * Mp(c.major);
  Poly p(5);
  p[4] = alpha * alpha;
  p[3] = Mp(4) * alpha * beta;
  p[2] = Mp(2) * alpha * gamma + Mp(4) * beta * beta - four_r2 * cxy;
  p[1] = Mp(4) * beta * gamma - Mp(2) * four_r2 * bxy;
  p[0] = gamma * gamma - four_r2 * axy;
  std::vector<ReferenceRoot> out;
  for (const MpRoot& m : real_roots(p)) out.push_back({m.x.to_double(), m.x.to_ld(), m.exact_double});
  std::sort(out.begin(), out.end(), [](const ReferenceRoot& a, const ReferenceRoot& b) { return a.t < b.t; });
  return out;
}

double surface_distance(const RayCase& c, double t) {
  const Mp tt(t);
  Mp p[3];
  for (int i = 0; i < 3; ++i) p[i] = Mp(c.origin[i]) + tt * Mp(c.direction[i]);
  const Mp rho = sqrt(p[0] * p[0] + p[1] * p[1]);
  const Mp R(c.major), r(c.minor);
  const Mp a_out = rho - R, a_in = rho + R;
  const Mp d_out = abs(sqrt(a_out * a_out + p[2] * p[2]) - r);
  const Mp d_in = abs(sqrt(a_in * a_in + p[2] * p[2]) - r);
  return std::min(d_out.to_double(), d_in.to_double());
}

}  // namespace toroid::accuracy
