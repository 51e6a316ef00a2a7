// SPDX-License-Identifier: Apache-2.0
// The accuracy bars of the default solver, per ray family (docs/torus.md):
// no missed and no spurious roots anywhere, the roots of grazing (near-
// tangent) pairs included; p99 root error <= 1e-12 r, or 1e-10 r for the
// far, thin and large families; and a bar on the largest error of each
// family. The reference is MPFR.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "accuracy/harness.h"
#include "toroid/torus/intersect.h"

namespace toroid::accuracy {
namespace {

class AccuracyBars : public ::testing::TestWithParam<int> {};

const std::vector<Family>& families() {
  static const std::vector<Family> f = make_families(2000);
  return f;
}

void expect_bars(const Family& f, const Metrics& m) {
  EXPECT_GT(m.reference_roots, f.rays.size() / 2) << "family should mostly hit the torus";
  // Every missed root counts, those of sub-visible grazing pairs too: a
  // solver that dropped every near-tangent pair must fail here.
  EXPECT_EQ(m.missed, 0) << m.missed_subvisible << " of them in grazing pairs";
  EXPECT_EQ(m.grazing_pairs_found, m.grazing_pairs) << "grazing pairs with a root missing";
  EXPECT_EQ(m.spurious, 0);
  EXPECT_EQ(m.extra, 0);
  EXPECT_LE(m.p99, f.p99_bar);
  EXPECT_LE(m.max, f.max_bar);
  // The same bars as the harness states them (the self-checks below show
  // that this list is not empty for solvers that break them).
  for (const std::string& v : bar_violations(f, m)) ADD_FAILURE() << v;
  if (f.name == "grazing") {
    EXPECT_GT(m.grazing_pairs, 100) << "the grazing family must hold grazing pairs";
  }
}

// The default solver, one ray at a time and through every batch path this
// CPU has (the batch's rows are the single-ray call's bits, so its errors
// are the same errors).
TEST_P(AccuracyBars, DefaultSolverMeetsTheBars) {
  const Family& f = families()[GetParam()];
  SCOPED_TRACE(f.name);
  const ReferenceSet ref = compute_references(f);
  const Metrics single = measure(f, ref, TorusSolver::Default);
  expect_bars(f, single);
  for (const BatchPath path : {BatchPath::Scalar, BatchPath::Avx2, BatchPath::Avx512}) {
    if (!batch_path_available(path)) continue;
    SCOPED_TRACE(std::string("batch path ") + batch_path_name(path));
    const Metrics batch = measure(f, ref, path);
    expect_bars(f, batch);
    EXPECT_EQ(batch.errors, single.errors);
  }
}

INSTANTIATE_TEST_SUITE_P(Families, AccuracyBars, ::testing::Range(0, 13),
                         [](const ::testing::TestParamInfo<int>& info) {
                           std::string n = families()[info.param].name;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// Calls check(family, ray, roots, count) for every ray of every family,
// with the default solver's list of its roots; stops at a fatal failure.
template <typename Check>
void for_each_ray_and_its_roots(Check&& check) {
  for (const Family& f : families())
    for (const RayCase& c : f.rays) {
      double all[4];
      const int n = intersect_torus(c.major, c.minor, c.origin, c.direction, all);
      check(f, c, all, n);
      if (::testing::Test::HasFatalFailure()) return;
    }
}

// Shadow rays ask torus_blocks whether a root lies in (t_min, t_max); it
// skips refining roots, never the decision: the same answer as the nearest-
// root query on every ray of every family (grazing and far ones included),
// for windows that end just before, between and just after the roots.
TEST(ShadowQuery, AgreesWithTheNearestRootOnEveryFamily) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int decided = 0, blocked = 0;
  for_each_ray_and_its_roots([&](const Family& f, const RayCase& c, const double* all, int n) {
    std::vector<double> ends = {-kInf, -1e-300, 0.0, kInf};
    for (int i = 0; i < n; ++i)
      for (const double k : {1 - 1e-9, 1.0, 1 + 1e-9}) ends.push_back(all[i] * k + (all[i] == 0 ? k - 1 : 0));
    for (int i = 0; i + 1 < n; ++i) ends.push_back(0.5 * (all[i] + all[i + 1]));
    for (const double lo : ends)
      for (const double hi : ends) {
        if (!(lo < hi)) continue;
        double t;
        const bool nearest = intersect_torus_nearest(c.major, c.minor, c.origin, c.direction, lo, hi, &t);
        ASSERT_EQ(torus_blocks(c.major, c.minor, c.origin, c.direction, lo, hi), nearest)
            << f.name << " window (" << lo << ", " << hi << ")";
        ++decided;
        blocked += nearest;
      }
  });
  EXPECT_GT(blocked, decided / 4);
  EXPECT_GT(decided - blocked, decided / 4);
}

// Whether the point at t on the ray lies inside the tube (h_out < 0, in
// long double): there the nearest-root query may find the next root from the
// window's start instead of taking it from the list.
bool starts_inside_tube(const RayCase& c, double t) {
  long double p[3];
  for (int i = 0; i < 3; ++i) p[i] = c.origin[i] + static_cast<long double>(t) * c.direction[i];
  const long double a = std::sqrt(p[0] * p[0] + p[1] * p[1]) - c.major;
  return c.minor < c.major && a * a + p[2] * p[2] < static_cast<long double>(c.minor) * c.minor;
}

// A ray that leaves a surface (reflected, refracted) asks for the nearest
// root from just beyond the root it leaves; the query leaves out the roots
// of a pair that lie before the window's start rather than locate them. A
// caller that walks a ray's roots one at a time asks from exactly the root
// it has: a root the search meets at the start is outside the window once
// it is a t value, so the search goes on past it. The answer is the list's
// first root after the start, bit for bit, on every ray of every family,
// for windows that start before, at and after each root (just beyond its
// rounding, and 1e-6 of it beyond), halfway between two roots, and end at
// infinity; where the window starts inside the tube (a refracted ray) the
// root is found from the start, so it is the list's root within the
// family's bar on the largest error (twice: each is within it of the exact
// root), and whether there is one is the list's answer.
TEST(NearestQuery, IsTheListsFirstRootAfterTheWindowsStart) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int compared = 0, found = 0, inside = 0;
  for_each_ray_and_its_roots([&](const Family& f, const RayCase& c, const double* all, int n) {
    std::vector<double> starts = {-kInf, 0.0};
    for (int i = 0; i < n; ++i)
      for (const double k : {1 - 1e-9, 1.0, 1 + 1e-9, 1 + 1e-6})
        starts.push_back(all[i] * k + (all[i] == 0 ? k - 1 : 0));
    for (int i = 0; i + 1 < n; ++i) starts.push_back(0.5 * (all[i] + all[i + 1]));
    const double dlen =
        std::sqrt(c.direction[0] * c.direction[0] + c.direction[1] * c.direction[1] + c.direction[2] * c.direction[2]);
    for (const double lo : starts) {
      const double* first = std::find_if(all, all + n, [lo](double t) { return t > lo; });
      double t = 0;
      const bool hit = intersect_torus_nearest(c.major, c.minor, c.origin, c.direction, lo, kInf, &t);
      ASSERT_EQ(hit, first != all + n) << f.name << " window from " << lo;
      if (hit) {
        if (std::isfinite(lo) && starts_inside_tube(c, lo)) {
          ASSERT_LE(std::abs(t - *first) * dlen / c.minor, 2 * f.max_bar) << f.name << " window from " << lo;
          ++inside;
        } else {
          ASSERT_EQ(t, *first) << f.name << " window from " << lo;
        }
        ++found;
      }
      ++compared;
    }
  });
  EXPECT_GT(found, compared / 2);
  EXPECT_GT(inside, found / 10);
}

// A caller that walks a ray's roots one call at a time passes each answer
// back as the next window's start: the walk from -infinity visits the
// list's roots, bit for bit, each once (a tangent's double root once too),
// and ends there, on every ray of every family.
TEST(NearestQuery, WalksTheListFromItsOwnAnswers) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int walked = 0;
  for_each_ray_and_its_roots([&](const Family& f, const RayCase& c, const double* all, int n) {
    std::vector<double> roots(all, all + n);
    roots.erase(std::unique(roots.begin(), roots.end()), roots.end());
    double lo = -kInf, t = 0;
    std::size_t k = 0;
    while (intersect_torus_nearest(c.major, c.minor, c.origin, c.direction, lo, kInf, &t)) {
      ASSERT_LT(k, roots.size()) << f.name << ": the walk found more roots than the list";
      ASSERT_EQ(t, roots[k]) << f.name << " root " << k;
      lo = t;
      ++k;
    }
    ASSERT_EQ(k, roots.size()) << f.name << ": the walk stopped early";
    walked += static_cast<int>(k);
  });
  EXPECT_GT(walked, 40000);
}

// The roots the nearest-root query finds from inside the tube, measured
// against MPFR's as the list's are (AccuracyBars): each ray's list, with
// every root that follows a stretch inside the tube replaced by the query's
// answer from a window that starts a thousandth of the way into the stretch.
TEST(NearestQuery, FromInsideTheTubeMeetsTheBars) {
  int replaced = 0;
  for (const Family& f : families()) {
    SCOPED_TRACE(f.name);
    const RootFinder walk = [&replaced](const RayCase& c, double t[4]) {
      const int n = intersect_torus(c.major, c.minor, c.origin, c.direction, t);
      for (int i = 0; i + 1 < n; ++i) {
        const double start = t[i] + 1e-3 * (t[i + 1] - t[i]);
        if (!(start > t[i]) || !starts_inside_tube(c, start)) continue;
        double next = 0;
        if (!intersect_torus_nearest(c.major, c.minor, c.origin, c.direction, start,
                                     std::numeric_limits<double>::infinity(), &next))
          return i + 1;  // counted as missed roots
        t[i + 1] = next;
        ++replaced;
      }
      return n;
    };
    const Metrics m = measure(f, compute_references(f), walk);
    EXPECT_EQ(m.missed, 0);
    EXPECT_EQ(m.spurious, 0);
    EXPECT_EQ(m.extra, 0);
    EXPECT_LE(m.p99, f.p99_bar);
    EXPECT_LE(m.max, f.max_bar);
  }
  EXPECT_GT(replaced, 10000);
}

TEST(AccuracyHarness, FamilyCountMatchesTheParameterRange) { EXPECT_EQ(families().size(), 13u); }

// The harness must be able to fail: a solver that drops every other root
// is caught as missing roots.
TEST(AccuracyHarness, DetectsMissingRoots) {
  const Family& f = families()[0];
  const ReferenceSet ref = compute_references(f);
  int total = 0;
  for (const auto& r : ref.roots) total += static_cast<int>(r.size());
  EXPECT_GT(total, 0);
  // Reference against itself minus one root per ray: every removed root is a miss.
  Family shifted = f;
  for (RayCase& c : shifted.rays) c.minor *= 1.01;  // a different torus: roots move
  const Metrics m = measure(shifted, ref, TorusSolver::Default);
  EXPECT_GT(m.missed + m.spurious, 0);
}

// The grazing logic of the harness (close pairs in the reference, both roots
// of a pair matched), on hand-made rays whose roots are known: the torus
// R = 1, r = 0.25; rays along x in the plane z = r - h, which touch the top
// of the tube near x = -1 and x = +1 with chords 2 sqrt(2 r h - h^2).
Family grazing_check_family() {
  Family f{"grazing-self-check", 1e-12, 1e-10, false, {}};
  auto ray = [](double z) { return RayCase{1.0, 0.25, {-5, 0, z}, {1, 0, 0}}; };
  f.rays.push_back(ray(0.0));           // four roots, no close pair
  f.rays.push_back(ray(0.25));          // tangent: two exact double roots, t = 4 and 6
  f.rays.push_back(ray(0.25 - 1e-13));  // two grazing pairs, chord 4.5e-7 = 1.8e-6 r (< 1e-5 r)
  f.rays.push_back(ray(0.25 - 5e-11));  // chords 1e-5 = 4e-5 r: close, but not a grazing pair
  return f;
}

// Removes every pair of roots closer than `chord` (what a solver that lost
// near-tangent pairs would return), or merges each into its midpoint.
RootFinder without_close_pairs(bool merge) {
  return [merge](const RayCase& c, double t[4]) {
    double all[4];
    const int n = intersect_torus(c.major, c.minor, c.origin, c.direction, all);
    const double dlen =
        std::sqrt(c.direction[0] * c.direction[0] + c.direction[1] * c.direction[1] + c.direction[2] * c.direction[2]);
    const double chord = 1e-5 * c.minor / dlen;
    int k = 0;
    for (int i = 0; i < n; ++i) {
      if (i + 1 < n && all[i + 1] - all[i] < chord) {
        if (merge) t[k++] = 0.5 * (all[i] + all[i + 1]);
        ++i;
        continue;
      }
      t[k++] = all[i];
    }
    return k;
  };
}

TEST(AccuracyHarness, ClassifiesGrazingPairs) {
  const Family f = grazing_check_family();
  const ReferenceSet ref = compute_references(f);
  ASSERT_EQ(ref.roots.size(), 4u);
  for (const auto& r : ref.roots) ASSERT_EQ(r.size(), 4u);
  EXPECT_TRUE(ref.roots[1][0].exact_double && ref.roots[1][1].exact_double);
  EXPECT_EQ(ref.roots[1][0].t, 4.0);
  EXPECT_EQ(ref.roots[1][3].t, 6.0);
  const Metrics m = measure(f, ref, TorusSolver::Default);
  // Two pairs on the tangent ray, two on the grazing one; none on the others.
  EXPECT_EQ(m.reference_roots, 16);
  EXPECT_EQ(m.grazing_pairs, 4);
  EXPECT_EQ(m.grazing_pairs_found, 4);
  EXPECT_EQ(m.missed, 0);
  EXPECT_EQ(m.spurious + m.extra, 0);
  EXPECT_TRUE(bar_violations(f, m).empty());
}

TEST(AccuracyHarness, FailsASolverThatDropsGrazingPairs) {
  const Family f = grazing_check_family();
  const ReferenceSet ref = compute_references(f);
  const Metrics m = measure(f, ref, without_close_pairs(false));
  EXPECT_EQ(m.grazing_pairs, 4);
  EXPECT_EQ(m.grazing_pairs_found, 0);
  EXPECT_EQ(m.missed, 8);
  EXPECT_EQ(m.missed_subvisible, 8);
  const std::vector<std::string> v = bar_violations(f, m);
  EXPECT_NE(std::find(v.begin(), v.end(), "8 missed roots (8 in grazing pairs)"), v.end());
  EXPECT_NE(std::find(v.begin(), v.end(), "4 of 4 grazing pairs not found"), v.end());
}

TEST(AccuracyHarness, FailsASolverThatMergesGrazingPairs) {
  // One root at the middle of each pair: within the matching tolerance of a
  // reference root of the pair, so it is matched, but its partner is missed
  // and the error of the matched one is half the chord.
  const Family f = grazing_check_family();
  const ReferenceSet ref = compute_references(f);
  const Metrics m = measure(f, ref, without_close_pairs(true));
  EXPECT_EQ(m.grazing_pairs, 4);
  EXPECT_EQ(m.grazing_pairs_found, 0);
  EXPECT_EQ(m.missed, 4);
  EXPECT_EQ(m.missed_subvisible, 4);
  EXPECT_EQ(m.spurious + m.extra, 0);
  EXPECT_GT(m.max, 1e-7);  // the merged roots of the grazing ray, 0.9e-6 r off
  EXPECT_LE(m.p99, m.max);
  const std::vector<std::string> v = bar_violations(f, m);
  EXPECT_EQ(v.size(), 4u) << "missed, grazing pairs, p99 and max";
}

// On the real grazing family, the same broken solver fails its bars.
TEST(AccuracyHarness, GrazingFamilyCatchesDroppedPairs) {
  const Family& f = families()[2];
  ASSERT_EQ(f.name, "grazing");
  const Metrics m = measure(f, compute_references(f), without_close_pairs(false));
  EXPECT_GT(m.grazing_pairs, 100);
  EXPECT_EQ(m.grazing_pairs_found, 0);
  EXPECT_FALSE(bar_violations(f, m).empty());
}

}  // namespace
}  // namespace toroid::accuracy
