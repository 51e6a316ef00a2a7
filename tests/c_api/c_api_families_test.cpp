// SPDX-License-Identifier: Apache-2.0
// The C API answers exactly what the C++ calls answer (default solver) on
// every ray of every accuracy family: roots, nearest roots in windows around
// them, and unit normals at the roots.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "accuracy/harness.h"
#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"
#include "toroid/torus_c.h"

namespace toroid::accuracy {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

TEST(CApiFamilies, AnswersAreTheCppAnswersOnEveryFamily) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  int rays = 0, roots = 0, nearest_hits = 0, normals = 0;
  for (const Family& f : make_families(2000))
    for (const RayCase& c : f.rays) {
      SCOPED_TRACE(f.name);
      ++rays;
      double cpp[4], ca[4];
      const int n = intersect_torus(c.major, c.minor, c.origin, c.direction, cpp);
      ASSERT_EQ(toroid_torus_intersect(c.major, c.minor, c.origin, c.direction, ca), n);
      for (int i = 0; i < n; ++i) ASSERT_TRUE(same_bits(ca[i], cpp[i])) << i;
      roots += n;

      // The batch, one ray at a time, is the same.
      int count = -2;
      double row[4];
      toroid_torus_intersect_batch(c.major, c.minor, 1, c.origin, c.direction, &count, row);
      ASSERT_EQ(count, n);
      for (int i = 0; i < n; ++i) ASSERT_TRUE(same_bits(row[i], cpp[i])) << i;

      std::vector<double> starts = {-kInf, 0.0};
      for (int i = 0; i < n; ++i) starts.push_back(cpp[i]);
      for (const double lo : starts) {
        double t_cpp = -7, t_c = -7;
        const bool hit = intersect_torus_nearest(c.major, c.minor, c.origin, c.direction, lo, kInf, &t_cpp);
        ASSERT_EQ(toroid_torus_nearest(c.major, c.minor, c.origin, c.direction, lo, kInf, &t_c), hit ? 1 : 0);
        ASSERT_TRUE(same_bits(t_c, t_cpp));
        nearest_hits += hit;
      }

      for (int i = 0; i < n; ++i) {
        const double p[3] = {c.origin[0] + cpp[i] * c.direction[0], c.origin[1] + cpp[i] * c.direction[1],
                             c.origin[2] + cpp[i] * c.direction[2]};
        double m[3], want[3], got[3];
        torus_normal(c.major, c.minor, p, m);
        const double length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        if (!(length > 1e-150 && length < 1e150)) continue;  // the plain formula would lose range
        for (int k = 0; k < 3; ++k) want[k] = m[k] / length;
        toroid_torus_normal(c.major, c.minor, p, got);
        for (int k = 0; k < 3; ++k) ASSERT_TRUE(same_bits(got[k], want[k])) << i << " " << k;
        ++normals;
      }
    }
  EXPECT_GT(rays, 20000);
  EXPECT_GT(roots, rays);
  EXPECT_GT(nearest_hits, rays);
  EXPECT_GT(normals, roots / 2);
}

}  // namespace
}  // namespace toroid::accuracy
