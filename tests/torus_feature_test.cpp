// SPDX-License-Identifier: Apache-2.0
// features/torus.feature, scenario by scenario: suite TorusFeature, each test
// named after its scenario's title in CamelCase (features/README.md), doing
// what the scenario says with its numbers and tolerances; a Scenario
// Outline's test loops over its Examples rows. TorusFeatureFile checks that
// the feature file and this suite name the same scenarios, and
// TorusFeatureHardCases that the hard cases' tolerances are ones the
// textbook quartic solver fails.
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <fstream>
#include <memory>
#include <numbers>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "accuracy/reference.h"
#include "support/approx.h"
#include "toroid/core/bounds.h"
#include "toroid/core/intersection.h"
#include "toroid/core/ray.h"
#include "toroid/math/transform.h"
#include "toroid/math/tuple.h"
#include "toroid/render/computations.h"
#include "toroid/render/uv_mapping.h"
#include "toroid/shapes/torus.h"
#include "toroid/torus/solver.h"

namespace toroid {
namespace {

constexpr double kPi = std::numbers::pi;
// The feature file's EPSILON_T, for t values (EPSILON, for tuples and uv, is
// toroid's kEpsilon: EXPECT_APPROX and approx_equal).
constexpr double kEpsilonT = 1e-9;

Intersections local_intersect(const Torus& t, const Ray& r) {
  Intersections xs;
  t.local_intersect(r, xs);
  return xs;
}

Intersections world_intersect(const Torus& t, const Ray& r) {
  Intersections xs;
  t.intersect(r, xs);
  return xs;
}

// xs holds exactly the roots `want`, in order, each within `tolerance`.
::testing::AssertionResult HitsAre(const Intersections& xs, const std::vector<double>& want, double tolerance) {
  std::ostringstream got;
  got.precision(17);
  for (const Intersection& x : xs) got << " " << x.t;
  if (xs.size() != want.size())
    return ::testing::AssertionFailure() << "xs.count = " << xs.size() << ", expected " << want.size()
                                         << "; xs:" << got.str();
  for (std::size_t i = 0; i < want.size(); ++i)
    if (!(std::abs(xs[i].t - want[i]) < tolerance))
      return ::testing::AssertionFailure() << "xs[" << i << "].t = " << xs[i].t << ", expected " << want[i] << " ± "
                                           << tolerance << "; xs:" << got.str();
  return ::testing::AssertionSuccess();
}

std::shared_ptr<Torus> swept(double theta_max, double phi_min, double phi_max) {
  auto t = std::make_shared<Torus>(1, 0.25);
  t->set_sweep({theta_max, phi_min, phi_max});
  return t;
}

// ---------------------------------------------------------------------------
// The torus

TEST(TorusFeature, TheDefaultTorus) {
  const Torus t;
  EXPECT_EQ(t.major(), 1);
  EXPECT_EQ(t.minor(), 0.25);
}

TEST(TorusFeature, ATorusIsWholeByDefault) {
  const Torus t;
  EXPECT_NEAR(t.sweep().theta_max, 2 * kPi, kEpsilon);
  EXPECT_NEAR(t.sweep().phi_min, -kPi, kEpsilon);
  EXPECT_NEAR(t.sweep().phi_max, kPi, kEpsilon);
  EXPECT_EQ(t.spindle(), SpindleSurface::Whole);
}

// ---------------------------------------------------------------------------
// Intersections

TEST(TorusFeature, ARayMissesATorus) {
  const Torus t(1, 0.25);
  const Ray rows[] = {
      {point(-5, 0, 1), vector(1, 0, 0)},   {point(-5, 0, 0.2500001), vector(1, 0, 0)},
      {point(-5, 1.5, 0), vector(1, 0, 0)}, {point(0, 0, -5), vector(0, 0, 1)},
      {point(0, 0, 0), vector(0, 0, 1)},    {point(0.5, 0, -5), vector(0, 0, 1)},
      {point(2, 0, -5), vector(0, 0, 1)},
  };
  for (const Ray& r : rows) EXPECT_TRUE(HitsAre(local_intersect(t, r), {}, kEpsilonT)) << r.origin;
}

TEST(TorusFeature, ARayStrikesATorusFourTimes) {
  struct Row {
    Tuple origin, direction;
    std::vector<double> t;
  };
  const Row rows[] = {
      {point(-5, 0, 0), vector(1, 0, 0), {3.75, 4.25, 5.75, 6.25}},
      {point(-5, 0.5, 0), vector(1, 0, 0), {3.85435607626104, 4.44098300562505, 5.55901699437495, 6.14564392373896}},
      {point(-5, 0, 0.15), vector(1, 0, 0), {3.8, 4.2, 5.8, 6.2}},
      {point(-5, 0.3, 0.1),
       vector(1, -0.06, -0.02),
       {3.76098732961585, 4.25939115634874, 5.76058888355153, 6.25899271028443}},
  };
  const Torus t(1, 0.25);
  for (const Row& row : rows) {
    const Ray r{row.origin, normalize(row.direction)};
    EXPECT_TRUE(HitsAre(local_intersect(t, r), row.t, kEpsilonT)) << row.origin;
  }
}

TEST(TorusFeature, ARayCrossesTheTubeTwice) {
  struct Row {
    Tuple origin, direction;
    std::vector<double> t;
  };
  const Row rows[] = {
      {point(1, 0, -5), vector(0, 0, 1), {4.75, 5.25}},
      {point(-5, 1, 0), vector(1, 0, 0), {4.25, 5.75}},
  };
  const Torus t(1, 0.25);
  for (const Row& row : rows)
    EXPECT_TRUE(HitsAre(local_intersect(t, {row.origin, row.direction}), row.t, kEpsilonT)) << row.origin;
}

TEST(TorusFeature, IntersectionsBehindTheOriginOfTheRayHaveANegativeT) {
  struct Row {
    Tuple origin;
    std::vector<double> t;
  };
  const Row rows[] = {
      {point(5, 0, 0), {-6.25, -5.75, -4.25, -3.75}},
      {point(0, 0, 0), {-1.25, -0.75, 0.75, 1.25}},
  };
  const Torus t(1, 0.25);
  for (const Row& row : rows)
    EXPECT_TRUE(HitsAre(local_intersect(t, {row.origin, vector(1, 0, 0)}), row.t, kEpsilonT)) << row.origin;
}

TEST(TorusFeature, ARayFromInsideTheTubeMeetsItOnceBehindAndOnceAhead) {
  const Torus t(1, 0.25);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(1, 0, 0), vector(0, 0, 1)}), {-0.25, 0.25}, kEpsilonT));
}

TEST(TorusFeature, TheDirectionOfTheRayNeedNotBeAUnitVector) {
  struct Row {
    Tuple direction;
    std::vector<double> t;
  };
  const Row rows[] = {
      {vector(2, 0, 0), {1.875, 2.125, 2.875, 3.125}},
      {vector(0.5, 0, 0), {7.5, 8.5, 11.5, 12.5}},
  };
  const Torus t(1, 0.25);
  for (const Row& row : rows)
    EXPECT_TRUE(HitsAre(local_intersect(t, {point(-5, 0, 0), row.direction}), row.t, kEpsilonT)) << row.direction;
}

TEST(TorusFeature, ARayTangentToTheOuterEquatorTouchesTheTorusAtOnePointCountedTwice) {
  const Torus t(1, 0.25);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(1.25, -5, 0), vector(0, 1, 0)}), {5, 5}, kEpsilonT));
}

TEST(TorusFeature, ARayTangentToTheTopOfTheTubeTouchesItTwiceEachTouchCountedTwice) {
  const Torus t(1, 0.25);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(-5, 0, 0.25), vector(1, 0, 0)}), {4, 4, 6, 6}, kEpsilonT));
}

TEST(TorusFeature, ARayTangentToTheInnerEquatorMeetsTheTorusAtThreePoints) {
  const Torus t(1, 0.25);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(-5, 0.75, 0), vector(1, 0, 0)}), {4, 5, 5, 6}, kEpsilonT));
}

// ---------------------------------------------------------------------------
// The cases that break naive solvers: one table per scenario, shared with
// TorusFeatureHardCases below.

struct HardCase {
  double major, minor;
  Tuple origin, direction;
  std::vector<double> t;
  double tolerance;
};

const std::vector<HardCase> kDistantCamera = {
    {1, 0.25, point(-10000, 0, 0), vector(1, 0, 0), {9998.75, 9999.25, 10000.75, 10001.25}, 1e-10},
    {1, 0.25, point(-1000000, 0, 0), vector(1, 0, 0), {999998.75, 999999.25, 1000000.75, 1000001.25}, 1e-8},
    {1, 0.25, point(-100000000, 0, 0), vector(1, 0, 0), {99999998.75, 99999999.25, 100000000.75, 100000001.25}, 1e-6},
};

const std::vector<HardCase> kDistantSlant = {
    {1, 0.25, point(1, -600000, 800000), vector(0, 0.6, -0.8), {999999.6882528678598, 1000000.3117471320310}, 1e-8},
    {1, 0.25, point(1, -60000000, 80000000), vector(0, 0.6, -0.8), {99999999.68825286245, 100000000.31174712662}, 1e-6},
};

const std::vector<HardCase> kThinAcross = {
    {1, 0.0001, point(-5, 0, 0), vector(1, 0, 0), {3.9999, 4.0001, 5.9999, 6.0001}, 1e-12},
    {1, 0.000001, point(-5, 0, 0), vector(1, 0, 0), {3.999999, 4.000001, 5.999999, 6.000001}, 1e-12},
};

const std::vector<HardCase> kThinDown = {
    {1, 0.0001, point(1, 0, -5), vector(0, 0, 1), {4.9999, 5.0001}, 1e-12},
    {1, 0.000001, point(1, 0, -5), vector(0, 0, 1), {4.999999, 5.000001}, 1e-12},
};

const std::vector<HardCase> kGrazing = {
    {1, 0.25, point(1.249999999, -5, 0), vector(0, 1, 0), {4.99994999999794149, 5.00005000000205851}, 1e-12},
    {1, 0.25, point(-5, 1, 0.249999999), vector(1, 0, 0), {4.99331255957084450, 5.00668744042915550}, 1e-12},
};

const std::vector<HardCase> kSkimming = {
    {1,
     0.25,
     point(-5, 0, 0.249999999),
     vector(1, 0, 0),
     {3.99997763932025325, 4.00002236067974675, 5.99997763932025325, 6.00002236067974675},
     1e-12},
};

const std::vector<HardCase> kHugeHole = {
    {10000, 1, point(-30000, 0, 0), vector(1, 0, 0), {19999, 20001, 39999, 40001}, 1e-9},
};

const std::vector<HardCase> kHugeCentreCircle = {
    {10000, 1, point(10000, -30000, 0), vector(0, 1, 0), {29858.5751082729776, 30141.4248917270224}, 1e-9},
};

const std::vector<HardCase> kNearlyAlongTheAxis = {
    {1, 0.25, point(0, 0, 1000), vector(0.001, 0, -1), {999.750000124999906, 1000.249999875000094}, 1e-10},
};

const std::vector<HardCase> kSpindleAxis = {
    {1,
     1.5,
     point(0, 0, -5),
     vector(0, 0, 1),
     {3.88196601125010515, 3.88196601125010515, 6.11803398874989485, 6.11803398874989485},
     1e-12},
};

const std::vector<HardCase> kSpindleBesideTheAxis = {
    {1,
     1.5,
     point(0.000001, 0, -5),
     vector(0, 0, 1),
     {3.88196511682371914, 3.88196690567810114, 6.11803309432189886, 6.11803488317628086},
     1e-12},
};

Intersections hard_case_hits(const HardCase& c, TorusSolver solver) {
  Torus t(c.major, c.minor);
  t.set_solver(solver);
  return local_intersect(t, {c.origin, c.direction});
}

void expect_hard_cases(const std::vector<HardCase>& rows) {
  for (const HardCase& c : rows)
    EXPECT_TRUE(HitsAre(hard_case_hits(c, TorusSolver::Default), c.t, c.tolerance))
        << "torus(" << c.major << ", " << c.minor << "), ray from " << c.origin;
}

TEST(TorusFeature, ADistantCameraStillSeesAllFourWallsOfTheTube) { expect_hard_cases(kDistantCamera); }

TEST(TorusFeature, ADistantCameraLookingDownAtTheTubeAtASlant) { expect_hard_cases(kDistantSlant); }

TEST(TorusFeature, ARayAcrossAThinTorusMeetsAllFourWalls) { expect_hard_cases(kThinAcross); }

TEST(TorusFeature, ARayDownThroughAThinTubeMeetsBothOfItsWalls) { expect_hard_cases(kThinDown); }

TEST(TorusFeature, ARayGrazingTheTubeMeetsItTwiceCloseTogether) { expect_hard_cases(kGrazing); }

TEST(TorusFeature, ARaySkimmingJustUnderTheTopOfTheTubeMeetsItFourTimes) { expect_hard_cases(kSkimming); }

TEST(TorusFeature, ARayThroughTheHoleOfAHugeTorusMeetsAllFourWalls) { expect_hard_cases(kHugeHole); }

TEST(TorusFeature, ARayAlongTheCentreCircleOfAHugeTorusStaysInsideTheTubeForAWhile) {
  expect_hard_cases(kHugeCentreCircle);
}

TEST(TorusFeature, ARayNearlyAlongTheAxisMeetsTheTubeFarBelow) { expect_hard_cases(kNearlyAlongTheAxis); }

TEST(TorusFeature, ARayAlongTheAxisOfASpindleTorusMeetsEachApexTwice) { expect_hard_cases(kSpindleAxis); }

TEST(TorusFeature, ARayBesideTheAxisOfASpindleTorusSplitsEachApexIntoTwoHits) {
  expect_hard_cases(kSpindleBesideTheAxis);
}

const std::vector<const std::vector<HardCase>*> kHardCaseTables = {&kDistantCamera,
                                                                   &kDistantSlant,
                                                                   &kThinAcross,
                                                                   &kThinDown,
                                                                   &kGrazing,
                                                                   &kSkimming,
                                                                   &kHugeHole,
                                                                   &kHugeCentreCircle,
                                                                   &kNearlyAlongTheAxis,
                                                                   &kSpindleAxis,
                                                                   &kSpindleBesideTheAxis};

// The expected roots are those of the test suite's own reference (the
// quartic formed exactly from the same doubles, solved in MPFR), to a
// hundredth of each tolerance.
TEST(TorusFeatureHardCases, TheExpectedRootsAreThoseOfTheMpfrReference) {
  for (const auto* table : kHardCaseTables)
    for (const HardCase& c : *table) {
      const accuracy::RayCase ray{
          c.major, c.minor, {c.origin.x, c.origin.y, c.origin.z}, {c.direction.x, c.direction.y, c.direction.z}};
      const std::vector<accuracy::ReferenceRoot> ref = accuracy::reference_roots(ray);
      SCOPED_TRACE(::testing::Message() << "torus(" << c.major << ", " << c.minor << "), ray from " << c.origin);
      ASSERT_EQ(ref.size(), c.t.size());
      for (std::size_t i = 0; i < ref.size(); ++i) EXPECT_NEAR(ref[i].t, c.t[i], c.tolerance / 100) << i;
    }
}

// The tolerances discriminate: toroid's textbook Ferrari solver (the paper's
// quartic, its coefficients formed in double precision) misses a root or
// is off by more than the tolerance on every row of every hard case.
TEST(TorusFeatureHardCases, TheTextbookFerrariSolverFailsEveryRow) {
  int rows = 0;
  for (const auto* table : kHardCaseTables)
    for (const HardCase& c : *table) {
      ++rows;
      EXPECT_FALSE(HitsAre(hard_case_hits(c, TorusSolver::Ferrari), c.t, c.tolerance))
          << "torus(" << c.major << ", " << c.minor << "), ray from " << c.origin;
    }
  EXPECT_EQ(rows, 17);
}

// ---------------------------------------------------------------------------
// Normals

TEST(TorusFeature, TheNormalOnATorus) {
  struct Row {
    Tuple point, normal;
  };
  const Row rows[] = {
      {point(1.25, 0, 0), vector(1, 0, 0)},
      {point(0, -1.25, 0), vector(0, -1, 0)},
      {point(0.75, 0, 0), vector(-1, 0, 0)},
      {point(0, 1, 0.25), vector(0, 0, 1)},
      {point(-1, 0, -0.25), vector(0, 0, -1)},
      {point(0.69, 0.92, 0.2), vector(0.36, 0.48, 0.8)},
      {point(0.48, 0.64, 0.15), vector(-0.48, -0.64, 0.6)},
      {point(-0.92, -0.69, -0.2), vector(-0.48, -0.36, -0.8)},
  };
  const Torus t(1, 0.25);
  for (const Row& row : rows) EXPECT_APPROX(t.normal_at(row.point), row.normal);
}

// ---------------------------------------------------------------------------
// Bounds

TEST(TorusFeature, ATorusHasABoundingBox) {
  struct Row {
    double major, minor;
    Tuple min, max;
  };
  const Row rows[] = {
      {1, 0.25, point(-1.25, -1.25, -0.25), point(1.25, 1.25, 0.25)},
      {2, 0.5, point(-2.5, -2.5, -0.5), point(2.5, 2.5, 0.5)},
      {1, 1.5, point(-2.5, -2.5, -1.5), point(2.5, 2.5, 1.5)},
      {10000, 1, point(-10001, -10001, -1), point(10001, 10001, 1)},
  };
  for (const Row& row : rows) {
    const BoundingBox box = Torus(row.major, row.minor).bounds();
    EXPECT_APPROX(box.min, row.min);
    EXPECT_APPROX(box.max, row.max);
  }
}

TEST(TorusFeature, ARotatedTorusHasATightBoundingBoxInItsParentSpace) {
  Torus t(1, 0.25);
  t.set_transform(rotation_x(kPi / 4));
  const BoundingBox box = t.parent_space_bounds();
  EXPECT_APPROX(box.min, point(-1.25, -0.95711, -0.95711));
  EXPECT_APPROX(box.max, point(1.25, 0.95711, 0.95711));
}

// ---------------------------------------------------------------------------
// Partial tori

TEST(TorusFeature, AHalfTorusKeepsTheHitsOnItsHalf) {
  const auto t = swept(kPi, -kPi, kPi);
  EXPECT_TRUE(HitsAre(local_intersect(*t, {point(-5, 1, 0), vector(1, 0, 0)}), {4.25, 5.75}, kEpsilonT));
}

TEST(TorusFeature, ARayThroughTheRemovedHalfOfAPartialTorusMisses) {
  const auto t = swept(kPi, -kPi, kPi);
  EXPECT_TRUE(HitsAre(local_intersect(*t, {point(-5, -1, 0), vector(1, 0, 0)}), {}, kEpsilonT));
}

TEST(TorusFeature, HitsOnTheCutOfAPartialTorusAreKept) {
  const auto t = swept(kPi, -kPi, kPi);
  EXPECT_TRUE(HitsAre(local_intersect(*t, {point(-5, 0, 0), vector(1, 0, 0)}), {3.75, 4.25, 5.75, 6.25}, kEpsilonT));
}

TEST(TorusFeature, AQuarterTorusDropsTheHitsBeyondItsSweep) {
  const auto t = swept(kPi / 2, -kPi, kPi);
  EXPECT_TRUE(HitsAre(local_intersect(*t, {point(-5, 0, 0), vector(1, 0, 0)}), {5.75, 6.25}, kEpsilonT));
}

TEST(TorusFeature, ARayThroughTheOpenEndOfAPartialTorusMeetsTheTubeFromInside) {
  const auto t = swept(kPi, -kPi, kPi);
  const Ray r{point(1, -5, 0), vector(0, 1, 0)};
  const Intersections xs = local_intersect(*t, r);
  ASSERT_TRUE(HitsAre(xs, {5.75}, kEpsilonT));
  const Computations comps = prepare_computations(xs[0], r, xs);
  EXPECT_TRUE(comps.inside);
}

TEST(TorusFeature, APhiSweepAroundTheInnerEquatorKeepsTheHalfOfTheTubeFacingTheAxis) {
  const double rows[][2] = {{kPi / 2, 3 * kPi / 2}, {-3 * kPi / 2, -kPi / 2}};
  for (const auto& row : rows) {
    const auto t = swept(2 * kPi, row[0], row[1]);
    EXPECT_TRUE(HitsAre(local_intersect(*t, {point(-5, 0, 0), vector(1, 0, 0)}), {4.25, 5.75}, kEpsilonT))
        << "phi from " << row[0] << " to " << row[1];
  }
}

TEST(TorusFeature, APhiSweepOverTheTopOfTheTubeKeepsItsUpperHalf) {
  const auto t = swept(2 * kPi, 0, kPi);
  EXPECT_TRUE(HitsAre(local_intersect(*t, {point(1, 0, 5), vector(0, 0, -1)}), {4.75}, kEpsilonT));
}

TEST(TorusFeature, APartialTorusHasABoundingBoxAroundItsSweptPart) {
  struct Row {
    double theta_max, phi_min, phi_max;
    Tuple min, max;
  };
  const Row rows[] = {
      {kPi, -kPi, kPi, point(-1.25, 0, -0.25), point(1.25, 1.25, 0.25)},
      {kPi / 2, -kPi, kPi, point(0, 0, -0.25), point(1.25, 1.25, 0.25)},
      {3 * kPi / 4, -kPi, kPi, point(-0.88388, 0, -0.25), point(1.25, 1.25, 0.25)},
      {2 * kPi, 0, kPi, point(-1.25, -1.25, 0), point(1.25, 1.25, 0.25)},
      {kPi / 4, -kPi / 2, kPi / 2, point(0.70711, 0, -0.25), point(1.25, 0.88388, 0.25)},
      {2 * kPi, kPi / 3, 2 * kPi / 3, point(-1.125, -1.125, 0.21651), point(1.125, 1.125, 0.25)},
  };
  for (const Row& row : rows) {
    SCOPED_TRACE(::testing::Message() << row.theta_max << " " << row.phi_min << " " << row.phi_max);
    const BoundingBox box = swept(row.theta_max, row.phi_min, row.phi_max)->bounds();
    EXPECT_APPROX(box.min, row.min);
    EXPECT_APPROX(box.max, row.max);
  }
}

// ---------------------------------------------------------------------------
// Horn and spindle tori

TEST(TorusFeature, ARayThroughTheCentreOfAHornTorusTouchesItThereTwice) {
  const Torus t(1, 1);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(-5, 0, 0), vector(1, 0, 0)}), {3, 5, 5, 7}, kEpsilonT));
}

TEST(TorusFeature, ARayAlongTheEquatorOfASpindleTorusMeetsTheOuterSheetAndTheLemon) {
  const Torus t(1, 1.5);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(-5, 0, 0), vector(1, 0, 0)}), {2.5, 4.5, 5.5, 7.5}, kEpsilonT));
}

TEST(TorusFeature, ASpindleTorusCanKeepItsOuterSheetOnly) {
  Torus t(1, 1.5);
  t.set_spindle(SpindleSurface::Outer);
  EXPECT_TRUE(HitsAre(local_intersect(t, {point(-5, 0, 0), vector(1, 0, 0)}), {2.5, 7.5}, kEpsilonT));
}

TEST(TorusFeature, TheLemonOfAHalfSpindleTorusLiesAcrossTheAxisFromItsOuterHalf) {
  Torus t(1, 1.5);
  t.set_sweep({kPi, -kPi, kPi});
  EXPECT_TRUE(
      HitsAre(local_intersect(t, {point(-0.3, -5, 0), vector(0, 1, 0)}), {4.6, 7.48193472919817132}, kEpsilonT));
}

TEST(TorusFeature, TheNormalOnASpindleTorus) {
  struct Row {
    Tuple point, normal;
  };
  const Row rows[] = {
      {point(-2.5, 0, 0), vector(-1, 0, 0)},
      {point(1.9, 0, 1.2), vector(0.6, 0, 0.8)},
      {point(0.5, 0, 0), vector(1, 0, 0)},
      {point(-0.2, 0, 0.9), vector(-0.8, 0, 0.6)},
      {point(0, 0, 1.118033988749895), vector(0, 0, 1)},
      {point(0, 0, -1.118033988749895), vector(0, 0, -1)},
  };
  const Torus t(1, 1.5);
  for (const Row& row : rows) EXPECT_APPROX(t.normal_at(row.point), row.normal);
}

TEST(TorusFeature, TheNormalAtTheCentreOfAHornTorusPointsUpTheAxis) {
  const Torus t(1, 1);
  EXPECT_APPROX(t.normal_at(point(0, 0, 0)), vector(0, 0, 1));
}

// ---------------------------------------------------------------------------
// Texture mapping

struct UvRow {
  Tuple point;
  double u, v;
};

void expect_toroidal_map(const Torus& t, const std::vector<UvRow>& rows) {
  for (const UvRow& row : rows) {
    const UvCoord uv = toroidal_map(t.major(), t.minor(), row.point);
    EXPECT_TRUE(approx_equal(uv.u, row.u)) << row.point << ": u = " << uv.u << ", expected " << row.u;
    EXPECT_TRUE(approx_equal(uv.v, row.v)) << row.point << ": v = " << uv.v << ", expected " << row.v;
  }
}

TEST(TorusFeature, UsingAToroidalMappingOnA3DPoint) {
  expect_toroidal_map(Torus(1, 0.25), {
                                          {point(1.25, 0, 0), 0.0, 0.0},
                                          {point(0, 1.25, 0), 0.25, 0.0},
                                          {point(-1.25, 0, 0), 0.5, 0.0},
                                          {point(0, -1.25, 0), 0.75, 0.0},
                                          {point(1, 0, 0.25), 0.0, 0.25},
                                          {point(0.75, 0, 0), 0.0, 0.5},
                                          {point(1, 0, -0.25), 0.0, 0.75},
                                          {point(0, -1, 0.25), 0.75, 0.25},
                                          {point(0.69, 0.92, 0.2), 0.147584, 0.147584},
                                          {point(0.48, 0.64, 0.15), 0.147584, 0.397584},
                                          {point(-0.92, -0.69, -0.2), 0.602416, 0.852416},
                                      });
}

TEST(TorusFeature, UsingAToroidalMappingOnASpindleTorus) {
  expect_toroidal_map(Torus(1, 1.5), {
                                         {point(2.5, 0, 0), 0.0, 0.0},
                                         {point(0, 2.5, 0), 0.25, 0.0},
                                         {point(-0.5, 0, 0), 0.0, 0.5},
                                         {point(0.5, 0, 0), 0.5, 0.5},
                                         {point(-0.2, 0, 0.9), 0.0, 0.397584},
                                         {point(0, 0, 1.118033988749895), 0.0, 0.366139},
                                     });
}

// ---------------------------------------------------------------------------
// A torus standing up

TEST(TorusFeature, ATorusRotatedAQuarterTurnAboutXHasItsAxisAlongY) {
  Torus t(1, 0.25);
  t.set_transform(rotation_x(kPi / 2));
  EXPECT_TRUE(HitsAre(world_intersect(t, {point(0, -5, 0), vector(0, 1, 0)}), {}, kEpsilonT));
  EXPECT_TRUE(HitsAre(world_intersect(t, {point(-5, 0, 0), vector(1, 0, 0)}), {3.75, 4.25, 5.75, 6.25}, kEpsilonT));
}

TEST(TorusFeature, TheNormalOnATorusRotatedAQuarterTurnAboutX) {
  Torus t(1, 0.25);
  t.set_transform(rotation_x(kPi / 2));
  EXPECT_APPROX(t.normal_at(point(0, 0, 1.25)), vector(0, 0, 1));
  EXPECT_APPROX(t.normal_at(point(0, 0.25, 1)), vector(0, 1, 0));
}

// ---------------------------------------------------------------------------
// The feature file and this suite name the same scenarios.

// A scenario's test name: its title without the characters that are neither
// letters, digits nor spaces, each word capitalised, the spaces removed.
std::string test_name(std::string_view title) {
  std::string name;
  bool word_start = true;
  for (const char c : title) {
    const auto u = static_cast<unsigned char>(c);
    if (c == ' ' || c == '\t') {
      word_start = true;
    } else if (std::isalnum(u) && u < 0x80) {
      name += word_start ? static_cast<char>(std::toupper(u)) : c;
      word_start = false;
    }
  }
  return name;
}

TEST(TorusFeatureFile, TestNamesAreTheTitlesInCamelCase) {
  EXPECT_EQ(test_name("A ray misses a torus"), "ARayMissesATorus");
  EXPECT_EQ(test_name("  Hits on the cut, kept (π/2)  "), "HitsOnTheCutKept2");
  EXPECT_EQ(test_name("Using a toroidal mapping on a 3D point"), "UsingAToroidalMappingOnA3DPoint");
}

TEST(TorusFeatureFile, EveryScenarioHasATestAndEveryTestAScenario) {
  const std::string path = std::string(TOROID_SOURCE_DIR) + "/features/torus.feature";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "cannot read " << path;
  std::set<std::string> scenarios;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    const std::string_view text = std::string_view(line).substr(first);
    for (const std::string_view keyword : {"Scenario Outline:", "Scenario:"}) {
      if (!text.starts_with(keyword)) continue;
      const std::string name = test_name(text.substr(keyword.size()));
      EXPECT_FALSE(name.empty()) << path << ":" << number << ": a scenario without a title";
      EXPECT_TRUE(scenarios.insert(name).second) << path << ":" << number << ": a second scenario named " << name;
      break;
    }
  }
  EXPECT_GT(scenarios.size(), 30u);

  std::set<std::string> tests;
  const ::testing::UnitTest& unit = *::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit.total_test_suite_count(); ++i) {
    const ::testing::TestSuite& suite = *unit.GetTestSuite(i);
    if (std::string_view(suite.name()) != "TorusFeature") continue;
    for (int j = 0; j < suite.total_test_count(); ++j) tests.insert(suite.GetTestInfo(j)->name());
  }
  for (const std::string& s : scenarios) EXPECT_TRUE(tests.count(s)) << "scenario without a test: TorusFeature." << s;
  for (const std::string& t : tests)
    EXPECT_TRUE(scenarios.count(t)) << "test without a scenario in " << path << ": TorusFeature." << t;
}

}  // namespace
}  // namespace toroid
