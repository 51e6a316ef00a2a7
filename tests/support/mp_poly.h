// SPDX-License-Identifier: Apache-2.0
// High-precision (MPFR) reference for the root-solver tests: builds
// polynomials from chosen roots, tells whether their double coefficients are
// exact, and refines the true roots of the double polynomial by Newton's
// method at 256 bits. No double-precision solver is involved.
#pragma once

#include <gtest/gtest.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>
#include <vector>

namespace toroid::testing {

inline constexpr mpfr_prec_t kMpBits = 256;

// RAII wrapper of one mpfr_t at kMpBits.
class Mp {
 public:
  Mp() { mpfr_init2(v_, kMpBits), mpfr_set_zero(v_, 1); }
  explicit Mp(double d) { mpfr_init2(v_, kMpBits), mpfr_set_d(v_, d, MPFR_RNDN); }
  Mp(const Mp& o) { mpfr_init2(v_, kMpBits), mpfr_set(v_, o.v_, MPFR_RNDN); }
  Mp& operator=(const Mp& o) {
    mpfr_set(v_, o.v_, MPFR_RNDN);
    return *this;
  }
  ~Mp() { mpfr_clear(v_); }
  mpfr_ptr get() { return v_; }
  mpfr_srcptr get() const { return v_; }
  double to_double() const { return mpfr_get_d(v_, MPFR_RNDN); }

 private:
  mpfr_t v_;
};

// A polynomial with double coefficients, highest degree first, together with
// whether those doubles equal the exact coefficients of the chosen roots.
struct Poly {
  std::vector<double> c;
  bool exact = true;
};

struct ComplexPair {
  double re, im;  // the roots re +- i im
};

// lead * prod (x - r) * prod (x^2 - 2 re x + re^2 + im^2), coefficients
// computed at 256 bits and then rounded to double.
inline Poly poly_from_roots(double lead, const std::vector<double>& real_roots,
                            const std::vector<ComplexPair>& pairs = {}) {
  std::vector<Mp> p(1, Mp(lead));  // highest degree first
  Mp t, u;
  for (double r : real_roots) {  // p *= (x - r)
    p.emplace_back();
    for (size_t i = p.size() - 1; i > 0; --i) {
      mpfr_mul_d(t.get(), p[i - 1].get(), r, MPFR_RNDN);
      mpfr_sub(p[i].get(), p[i].get(), t.get(), MPFR_RNDN);
    }
  }
  for (const ComplexPair& z : pairs) {  // p *= (x^2 - 2 re x + |z|^2)
    Mp s(-2 * z.re), n(z.re);
    mpfr_sqr(n.get(), n.get(), MPFR_RNDN);
    mpfr_set_d(t.get(), z.im, MPFR_RNDN);
    mpfr_sqr(t.get(), t.get(), MPFR_RNDN);
    mpfr_add(n.get(), n.get(), t.get(), MPFR_RNDN);
    std::vector<Mp> q(p.size() + 2);
    for (size_t i = 0; i < p.size(); ++i) {
      mpfr_add(q[i].get(), q[i].get(), p[i].get(), MPFR_RNDN);
      mpfr_mul(t.get(), p[i].get(), s.get(), MPFR_RNDN);
      mpfr_add(q[i + 1].get(), q[i + 1].get(), t.get(), MPFR_RNDN);
      mpfr_mul(t.get(), p[i].get(), n.get(), MPFR_RNDN);
      mpfr_add(q[i + 2].get(), q[i + 2].get(), t.get(), MPFR_RNDN);
    }
    p = std::move(q);
  }
  Poly out;
  for (const Mp& m : p) {
    const double d = m.to_double();
    out.c.push_back(d);
    if (mpfr_cmp_d(m.get(), d) != 0) out.exact = false;
  }
  return out;
}

// p(x) and p'(x) at 256 bits for the double coefficients c (exact inputs).
inline void mp_eval(const std::vector<double>& c, const Mp& x, Mp& f, Mp& df) {
  mpfr_set_zero(f.get(), 1);
  mpfr_set_zero(df.get(), 1);
  for (double ci : c) {
    mpfr_mul(df.get(), df.get(), x.get(), MPFR_RNDN);
    mpfr_add(df.get(), df.get(), f.get(), MPFR_RNDN);
    mpfr_mul(f.get(), f.get(), x.get(), MPFR_RNDN);
    mpfr_add_d(f.get(), f.get(), ci, MPFR_RNDN);
  }
}

// The true root of the double polynomial c nearest x0 (a simple root),
// refined by Newton's method at 256 bits and rounded to double.
inline double refine_root(const std::vector<double>& c, double x0) {
  Mp x(x0), f, df, step;
  for (int it = 0; it < 200; ++it) {
    mp_eval(c, x, f, df);
    if (mpfr_zero_p(f.get()) || mpfr_zero_p(df.get())) break;
    mpfr_div(step.get(), f.get(), df.get(), MPFR_RNDN);
    mpfr_sub(x.get(), x.get(), step.get(), MPFR_RNDN);
    if (mpfr_zero_p(step.get()) || mpfr_get_exp(step.get()) < mpfr_get_exp(x.get()) - 240) break;
  }
  return x.to_double();
}

// The reference roots: the chosen real roots themselves when the coefficients
// are exact, else each refined as a root of the rounded polynomial.
inline std::vector<double> reference_roots(const Poly& p, std::vector<double> chosen) {
  if (!p.exact)
    for (double& r : chosen) r = refine_root(p.c, r);
  std::sort(chosen.begin(), chosen.end());
  return chosen;
}

// Same count, ascending output, and |got - want| <= tol * max(1, |want|).
inline ::testing::AssertionResult RootsMatch(const double* got, int n, const std::vector<double>& want, double tol) {
  std::ostringstream os;
  os.precision(17);
  os << "got " << n << " roots {";
  for (int i = 0; i < n; ++i) os << (i ? ", " : "") << got[i];
  os << "}, want " << want.size() << " {";
  for (size_t i = 0; i < want.size(); ++i) os << (i ? ", " : "") << want[i];
  os << "} within " << tol << " (relative to max(1, |root|))";
  if (n != static_cast<int>(want.size())) return ::testing::AssertionFailure() << os.str();
  for (int i = 0; i + 1 < n; ++i)
    if (got[i] > got[i + 1]) return ::testing::AssertionFailure() << "not ascending: " << os.str();
  for (int i = 0; i < n; ++i)
    if (!(std::fabs(got[i] - want[i]) <= tol * std::max(1.0, std::fabs(want[i]))))
      return ::testing::AssertionFailure() << os.str();
  return ::testing::AssertionSuccess();
}

// Largest |got - want| / max(1, |want|) (same count assumed).
inline double max_rel_error(const double* got, const std::vector<double>& want) {
  double m = 0;
  for (size_t i = 0; i < want.size(); ++i)
    m = std::max(m, std::fabs(got[i] - want[i]) / std::max(1.0, std::fabs(want[i])));
  return m;
}

}  // namespace toroid::testing
