// SPDX-License-Identifier: Apache-2.0
// The scalar solver's copy for AVX2 and FMA (solver_copies.h) gives the
// baseline build's answers, bit for bit, through all three queries, on rays
// and tori of every kind the solver treats apart.
#include "toroid/torus/solver_copies.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include "toroid/torus/intersect.h"

namespace toroid {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct Case {
  double R, r, o[3], d[3];
};

// Ring, thin, spindle and horn tori, at unit size and far from it (the
// rescaled path); rays aimed into the tube, through the hole, from afar,
// along and across the axis, and tangent to the top and the outer equator.
std::vector<Case> cases() {
  std::mt19937_64 gen(2026);
  std::uniform_real_distribution<double> u(-1, 1);
  const double shapes[][2] = {{1, 0.25}, {1, 1e-4}, {1, 0.999}, {1, 1}, {1, 1.5}, {1e-200, 2.5e-201}, {3e150, 1e150}};
  std::vector<Case> out;
  for (const auto& shape : shapes) {
    const double R = shape[0], r = shape[1], size = R + r;
    for (int i = 0; i < 800; ++i) {
      Case c{R, r, {}, {}};
      const double a = 4 * u(gen), rho = R + 0.9 * r * u(gen);
      const double far = i % 5 == 0 ? 1e6 : 4;
      switch (i % 6) {
        case 0:
        case 1:  // towards a point inside the tube
          for (int k = 0; k < 3; ++k) c.o[k] = far * size * u(gen);
          c.d[0] = rho * std::cos(a) - c.o[0];
          c.d[1] = rho * std::sin(a) - c.o[1];
          c.d[2] = 0.5 * r * u(gen) - c.o[2];
          break;
        case 2:  // random
          for (int k = 0; k < 3; ++k) c.o[k] = 3 * size * u(gen), c.d[k] = u(gen);
          break;
        case 3:  // through the axis
          c.o[0] = 3 * size * std::cos(a), c.o[1] = 3 * size * std::sin(a), c.o[2] = r * u(gen);
          for (int k = 0; k < 3; ++k) c.d[k] = -c.o[k] * (1 + 1e-3 * u(gen));
          break;
        case 4:  // tangent to the top circle
          c.o[0] = -5 * size, c.o[1] = R * u(gen), c.o[2] = r, c.d[0] = 1;
          break;
        default:  // from inside the tube, as a refracted ray leaves it
          c.o[0] = rho * std::cos(a), c.o[1] = rho * std::sin(a), c.o[2] = 0.5 * r * u(gen);
          for (int k = 0; k < 3; ++k) c.d[k] = u(gen);
      }
      out.push_back(c);
    }
  }
  return out;
}

struct Answers {
  int count = 0;
  double roots[4] = {};
  std::vector<int> nearest_found, blocks;
  std::vector<double> nearest;
};

// Every root; the nearest root and the shadow query from 0 and from each
// root onwards, with windows ending at, between and beyond the roots.
Answers answers(const Case& c) {
  Answers a;
  a.count = intersect_torus(c.R, c.r, c.o, c.d, a.roots);
  std::vector<double> starts = {-kInf, 0};
  for (int i = 0; i < a.count; ++i) starts.push_back(a.roots[i]);
  for (const double t_min : starts)
    for (const double t_max :
         {kInf, a.count > 0 ? a.roots[a.count - 1] : 1.0, a.count > 1 ? 0.5 * (a.roots[0] + a.roots[1]) : 2.0}) {
      double t = -1;
      a.nearest_found.push_back(intersect_torus_nearest(c.R, c.r, c.o, c.d, t_min, t_max, &t));
      a.nearest.push_back(t);
      a.blocks.push_back(torus_blocks(c.R, c.r, c.o, c.d, t_min, t_max));
    }
  return a;
}

TEST(SolverCopies, TheAvx2CopyGivesTheBaselinesBits) {
  if (!x86_64_v3::available()) GTEST_SKIP() << "this build or processor has no AVX2 copy of the solver";
  ASSERT_TRUE(x86_64_v3::enabled());
  int compared = 0, roots = 0;
  for (const Case& c : cases()) {
    x86_64_v3::set_enabled_for_testing(false);
    const Answers base = answers(c);
    x86_64_v3::set_enabled_for_testing(true);
    const Answers copy = answers(c);
    ASSERT_EQ(base.count, copy.count) << "R " << c.R << " r " << c.r;
    for (int i = 0; i < base.count; ++i) EXPECT_TRUE(same_bits(base.roots[i], copy.roots[i])) << base.roots[i];
    ASSERT_EQ(base.nearest.size(), copy.nearest.size());
    for (std::size_t i = 0; i < base.nearest.size(); ++i) {
      EXPECT_EQ(base.nearest_found[i], copy.nearest_found[i]);
      EXPECT_TRUE(same_bits(base.nearest[i], copy.nearest[i])) << base.nearest[i] << " vs " << copy.nearest[i];
      EXPECT_EQ(base.blocks[i], copy.blocks[i]);
    }
    ++compared;
    roots += base.count;
  }
  EXPECT_EQ(compared, 7 * 800);
  EXPECT_GT(roots, 7 * 800);  // most rays hit: the comparison is not of empty rows
}

TEST(SolverCopies, TheSwitchForTestsTakesEffect) {
  x86_64_v3::set_enabled_for_testing(false);
  EXPECT_FALSE(x86_64_v3::enabled());
  x86_64_v3::set_enabled_for_testing(true);
  EXPECT_EQ(x86_64_v3::enabled(), x86_64_v3::available());
}

}  // namespace
}  // namespace toroid
