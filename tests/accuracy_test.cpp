// The accuracy bars of the default solver, per ray family (docs/torus.md):
// no missed and no spurious roots anywhere; p99 root error <= 1e-12 r, or
// 1e-10 r for the far, thin and large families. The reference is MPFR.
#include <gtest/gtest.h>

#include "accuracy/harness.h"

namespace toroid::accuracy {
namespace {

class AccuracyBars : public ::testing::TestWithParam<int> {};

const std::vector<Family>& families() {
  static const std::vector<Family> f = make_families(2000);
  return f;
}

TEST_P(AccuracyBars, DefaultSolverMeetsTheBars) {
  const Family& f = families()[GetParam()];
  const Metrics m = measure(f, compute_references(f), QuarticSolver::Default);
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
  const Metrics m = measure(shifted, ref, QuarticSolver::Default);
  EXPECT_GT(m.missed + m.spurious, 0);
}

}  // namespace
}  // namespace toroid::accuracy
