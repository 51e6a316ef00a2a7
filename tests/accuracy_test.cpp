// The accuracy bars of the default solver, per ray family (docs/torus.md):
// no missed and no spurious roots anywhere; p99 root error <= 1e-12 r, or
// 1e-10 r for the far, thin and large families. The reference is MPFR.
#include <gtest/gtest.h>

#include <limits>
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

TEST_P(AccuracyBars, DefaultSolverMeetsTheBars) {
  const Family& f = families()[GetParam()];
  const Metrics m = measure(f, compute_references(f), TorusSolver::Default);
  SCOPED_TRACE(f.name);
  EXPECT_GT(m.reference_roots, f.rays.size() / 2) << "family should mostly hit the torus";
  EXPECT_EQ(m.missed - m.missed_subvisible, 0);
  EXPECT_EQ(m.spurious, 0);
  EXPECT_EQ(m.extra, 0);
  EXPECT_LE(m.p99, f.p99_bar);
}

INSTANTIATE_TEST_SUITE_P(Families, AccuracyBars, ::testing::Range(0, 13),
                         [](const ::testing::TestParamInfo<int>& info) {
                           std::string n = families()[info.param].name;
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

// Shadow rays ask torus_blocks whether a root lies in (t_min, t_max); it
// skips refining roots, never the decision: the same answer as the nearest-
// root query on every ray of every family (grazing and far ones included),
// for windows that end just before, between and just after the roots.
TEST(ShadowQuery, AgreesWithTheNearestRootOnEveryFamily) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int decided = 0, blocked = 0;
  for (const Family& f : families())
    for (const RayCase& c : f.rays) {
      double all[4];
      const int n = intersect_torus(c.major, c.minor, c.origin, c.direction, all);
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
    }
  EXPECT_GT(blocked, decided / 4);
  EXPECT_GT(decided - blocked, decided / 4);
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

}  // namespace
}  // namespace toroid::accuracy
