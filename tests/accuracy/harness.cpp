// SPDX-License-Identifier: Apache-2.0
#include "accuracy/harness.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "toroid/torus/intersect.h"

namespace toroid::accuracy {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Vec {
  double x, y, z;
};
Vec operator+(Vec a, Vec b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator-(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator*(Vec a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
Vec unit(Vec a) { return a * (1 / std::sqrt(dot(a, a))); }

class Sampler {
 public:
  explicit Sampler(uint64_t seed) : rng_(seed) {}
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng_); }
  double log_uniform(double a, double b) { return std::exp(uniform(std::log(a), std::log(b))); }
  Vec direction() {
    const double z = uniform(-1, 1), phi = uniform(0, 2 * kPi), s = std::sqrt(1 - z * z);
    return {s * std::cos(phi), s * std::sin(phi), z};
  }
  // A point of the torus surface and its outward unit normal.
  std::pair<Vec, Vec> surface_point(double R, double r) {
    const double u = uniform(0, 2 * kPi), v = uniform(0, 2 * kPi);
    const Vec n{std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
    const Vec c{R * std::cos(u), R * std::sin(u), 0};
    return {c + n * r, n};
  }
  Vec box_point(double R, double r) { return {uniform(-(R + r), R + r), uniform(-(R + r), R + r), uniform(-r, r)}; }

 private:
  std::mt19937_64 rng_;
};

RayCase make_case(double R, double r, Vec o, Vec d) { return {R, r, {o.x, o.y, o.z}, {d.x, d.y, d.z}}; }

// Origin `dist` sizes away in a random direction, aimed at `target`.
RayCase aimed(Sampler& s, double R, double r, double dist, Vec target) {
  const Vec o = s.direction() * (dist * (R + r));
  return make_case(R, r, o, unit(target - o));
}

std::vector<RayCase> near_rays(Sampler& s, double R, double r, int n) {
  std::vector<RayCase> v;
  for (int i = 0; i < n; ++i) {
    const Vec target = i % 2 ? s.surface_point(R, r).first : s.box_point(R, r);
    v.push_back(aimed(s, R, r, s.uniform(1, 5), target));
  }
  return v;
}

}  // namespace

std::vector<Family> make_families(int n) {
  std::vector<Family> fams;
  Sampler s(20191122);
  const double R = 1.0, r = 0.25;

  fams.push_back({"near", 1e-12, 1e-10, false, near_rays(s, R, r, n)});

  {
    Family f{"far", 1e-10, 1e-8, true, {}};
    for (int i = 0; i < n; ++i) {
      const double dist = s.log_uniform(1e2, 1e8);
      f.rays.push_back(aimed(s, R, r, dist, i % 2 ? s.surface_point(R, r).first : s.box_point(R, r)));
    }
    fams.push_back(f);
  }

  {
    // Tangent plane at a surface point, direction tilted into the surface by theta.
    Family f{"grazing", 1e-12, 1e-10, false, {}};
    for (int i = 0; i < n; ++i) {
      const auto [p, nrm] = s.surface_point(R, r);
      const Vec tangent = unit(cross(nrm, s.direction()));
      const double theta = s.log_uniform(1e-12, 1e-1);
      const Vec d = unit(tangent * std::cos(theta) - nrm * std::sin(theta));
      f.rays.push_back(make_case(R, r, p - d * (s.uniform(2, 4) * (R + r)), d));
    }
    fams.push_back(f);
  }

  {
    // Through the hole, close to the equatorial plane: four roots.
    Family f{"four-root", 1e-12, 1e-10, false, {}};
    for (int i = 0; i < n; ++i) {
      const double phi = s.uniform(0, 2 * kPi), dist = s.uniform(2, 5) * (R + r);
      const Vec o{dist * std::cos(phi), dist * std::sin(phi), s.uniform(-0.5, 0.5) * r};
      const Vec target{s.uniform(-0.5, 0.5) * (R - r), s.uniform(-0.5, 0.5) * (R - r), s.uniform(-0.5, 0.5) * r};
      f.rays.push_back(make_case(R, r, o, unit(target - o)));
    }
    fams.push_back(f);
  }

  {
    // Along the axis, in the equatorial plane, from the centre; direction lengths 1e-3..1e3.
    Family f{"special", 1e-12, 1e-10, false, {}};
    for (int i = 0; i < n; ++i) {
      const double len = s.log_uniform(1e-3, 1e3);
      Vec o, d;
      switch (i % 4) {
        case 0:
          o = {0, 0, s.uniform(-5, 5)};
          d = {0, 0, 1};
          break;  // along the axis
        case 1:
          o = {s.uniform(-2, 2), 0, s.uniform(-1, 1) * r};
          d = {0, 0, 1};
          break;  // parallel to it
        case 2: {
          const Vec q = s.direction();
          o = Vec{q.x, q.y, 0} * 3;
          d = unit(Vec{s.uniform(-1, 1), s.uniform(-1, 1), 0} - o);
          break;
        }
        default:
          o = {0, 0, 0};
          d = s.direction();
          break;  // from the centre
      }
      f.rays.push_back(make_case(R, r, o, d * len));
    }
    fams.push_back(f);
  }

  {
    Family f{"inside-tube", 1e-12, 1e-10, false, {}};
    for (int i = 0; i < n; ++i) {
      const double u = s.uniform(0, 2 * kPi), v = s.uniform(0, 2 * kPi), k = s.uniform(0, 0.99) * r;
      const Vec o{(R + k * std::cos(v)) * std::cos(u), (R + k * std::cos(v)) * std::sin(u), k * std::sin(v)};
      f.rays.push_back(make_case(R, r, o, s.direction()));
    }
    fams.push_back(f);
  }

  {
    // Secondary rays: from the point a primary ray hits (computed in double,
    // as a renderer does), in a random direction.
    Family f{"secondary", 1e-12, 1e-10, false, {}};
    while (static_cast<int>(f.rays.size()) < n) {
      const RayCase p = aimed(s, R, r, s.uniform(2, 5), s.surface_point(R, r).first);
      double t[4];
      if (intersect_torus(R, r, p.origin, p.direction, t) == 0) continue;
      const Vec hit{p.origin[0] + t[0] * p.direction[0], p.origin[1] + t[0] * p.direction[1],
                    p.origin[2] + t[0] * p.direction[2]};
      f.rays.push_back(make_case(R, r, hit, s.direction()));
    }
    fams.push_back(f);
  }

  for (double ratio : {1e-3, 1e-4}) {
    Family f{ratio == 1e-3 ? "thin-1e-3" : "thin-1e-4", 1e-10, 1e-8, false, {}};
    for (int i = 0; i < n; ++i) {
      // Aim at the tube itself (a box point would almost never hit it).
      const auto [p, nrm] = s.surface_point(1.0, ratio);
      const Vec target = p - nrm * (s.uniform(0, 2) * ratio);
      f.rays.push_back(aimed(s, 1.0, ratio, s.uniform(1, 5), target));
    }
    fams.push_back(f);
  }

  fams.push_back({"spindle", 1e-12, 1e-10, false, near_rays(s, 1.0, 1.5, n)});
  fams.push_back({"horn", 1e-12, 1e-10, false, near_rays(s, 1.0, 1.0, n)});
  fams.push_back({"large-R1e4", 1e-10, 1e-8, false, near_rays(s, 1e4, 1.0, n)});
  fams.push_back({"tiny-R1e-3", 1e-12, 1e-10, false, near_rays(s, 1e-3, 0.25e-3, n)});
  return fams;
}

ReferenceSet compute_references(const Family& f) {
  ReferenceSet set;
  for (const RayCase& c : f.rays) set.roots.push_back(reference_roots(c));
  return set;
}

Metrics measure(const Family& f, const ReferenceSet& ref, TorusSolver solver) {
  return measure(f, ref, [solver](const RayCase& c, double t[4]) {
    return intersect_torus(c.major, c.minor, c.origin, c.direction, t, solver);
  });
}

Metrics measure(const Family& f, const ReferenceSet& ref, BatchPath path) {
  const std::size_t n = f.rays.size();
  std::vector<double> origins(3 * n), directions(3 * n), rows(4 * n);
  std::vector<int> counts(n);
  for (std::size_t k = 0; k < n; ++k)
    for (int i = 0; i < 3; ++i) {
      origins[3 * k + i] = f.rays[k].origin[i];
      directions[3 * k + i] = f.rays[k].direction[i];
    }
  for (std::size_t begin = 0, end = 0; begin < n; begin = end) {
    const double major = f.rays[begin].major, minor = f.rays[begin].minor;
    while (end < n && f.rays[end].major == major && f.rays[end].minor == minor) ++end;
    intersect_torus_batch_on(path, major, minor, end - begin, &origins[3 * begin], &directions[3 * begin],
                             &counts[begin], &rows[4 * begin]);
  }
  // measure() hands the finder the family's own RayCase: its index is its
  // place in f.rays.
  return measure(f, ref, [&](const RayCase& c, double t[4]) {
    const std::size_t k = static_cast<std::size_t>(&c - f.rays.data());
    const int count = std::max(counts[k], 0);  // -1 (bad input) would be a bug: measured as no roots
    for (int i = 0; i < count; ++i) t[i] = rows[4 * k + i];
    return count;
  });
}

Metrics measure(const Family& f, const ReferenceSet& ref, const RootFinder& solve) {
  Metrics m;
  for (size_t k = 0; k < f.rays.size(); ++k) {
    const RayCase& c = f.rays[k];
    const std::vector<ReferenceRoot>& want = ref.roots[k];
    double got[4];
    const int n = solve(c, got);
    const double dlen =
        std::sqrt(c.direction[0] * c.direction[0] + c.direction[1] * c.direction[1] + c.direction[2] * c.direction[2]);
    const double r = c.minor;
    const double match_tol = 1e-6 * r / dlen;
    const double chord_tol = 1e-5 * r / dlen;
    ++m.rays;
    m.reference_roots += static_cast<int>(want.size());

    // Close pairs in the reference (grazing: sub-visible chords).
    std::vector<bool> in_close_pair(want.size(), false);
    for (size_t i = 0; i + 1 < want.size(); ++i)
      if (want[i + 1].t - want[i].t < chord_tol) {
        in_close_pair[i] = in_close_pair[i + 1] = true;
      }

    // Greedy matching of the two ascending lists.
    std::vector<bool> matched_ref(want.size(), false);
    size_t i = 0;
    int j = 0;
    while (i < want.size() && j < n) {
      const double dt = got[j] - want[i].t;
      if (std::abs(dt) <= match_tol) {
        double err = std::abs(static_cast<double>(static_cast<long double>(got[j]) - want[i].t_ld)) * dlen / r;
        if (f.beyond_rounding) {
          const double half_ulp = 0.5 * (std::nextafter(std::abs(want[i].t), INFINITY) - std::abs(want[i].t));
          err = std::max(0.0, err - half_ulp * dlen / r);
        }
        m.errors.push_back(err);
        matched_ref[i] = true;
        ++i;
        ++j;
      } else if (dt < 0) {
        (surface_distance(c, got[j]) > 1e-7 * r ? m.spurious : m.extra)++;
        ++j;
      } else {
        ++i;
      }
    }
    for (; j < n; ++j) (surface_distance(c, got[j]) > 1e-7 * r ? m.spurious : m.extra)++;
    for (size_t q = 0; q < want.size(); ++q) {
      if (matched_ref[q]) continue;
      ++m.missed;
      if (in_close_pair[q]) ++m.missed_subvisible;
    }
    for (size_t q = 0; q + 1 < want.size(); ++q)
      if (in_close_pair[q] && in_close_pair[q + 1] && want[q + 1].t - want[q].t < chord_tol) {
        ++m.grazing_pairs;
        if (matched_ref[q] && matched_ref[q + 1]) ++m.grazing_pairs_found;
        ++q;
      }
  }
  std::vector<double> e = m.errors;
  std::sort(e.begin(), e.end());
  if (!e.empty()) {
    m.p50 = e[e.size() / 2];
    m.p99 = e[std::min(e.size() - 1, static_cast<size_t>(std::ceil(0.99 * e.size())) - 1)];
    m.max = e.back();
  }
  return m;
}

std::vector<std::string> bar_violations(const Family& f, const Metrics& m) {
  std::vector<std::string> v;
  auto add = [&v](const std::string& s) { v.push_back(s); };
  if (m.missed != 0)
    add(std::to_string(m.missed) + " missed roots (" + std::to_string(m.missed_subvisible) + " in grazing pairs)");
  if (m.grazing_pairs_found != m.grazing_pairs)
    add(std::to_string(m.grazing_pairs - m.grazing_pairs_found) + " of " + std::to_string(m.grazing_pairs) +
        " grazing pairs not found");
  if (m.spurious != 0) add(std::to_string(m.spurious) + " spurious roots");
  if (m.extra != 0) add(std::to_string(m.extra) + " extra roots");
  char buf[96];
  if (!(m.p99 <= f.p99_bar)) {
    std::snprintf(buf, sizeof buf, "p99 error %.3g r > bar %.3g r", m.p99, f.p99_bar);
    add(buf);
  }
  if (!(m.max <= f.max_bar)) {
    std::snprintf(buf, sizeof buf, "max error %.3g r > bar %.3g r", m.max, f.max_bar);
    add(buf);
  }
  return v;
}

}  // namespace toroid::accuracy
