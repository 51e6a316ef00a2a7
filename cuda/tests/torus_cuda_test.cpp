// SPDX-License-Identifier: Apache-2.0
// The CUDA batch against the CPU batch: the accuracy families (the CPU's
// bars, through the kernel) and the bad inputs, answer by answer. Without a
// CUDA device the tests that need one skip, saying why; the argument checks
// need none and always run.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "accuracy/harness.h"
#include "cuda_compare.h"
#include "toroid/torus_cuda.h"

namespace toroid::cuda_check {
namespace {

#define TOROID_REQUIRE_DEVICE()                    \
  do {                                             \
    const std::string problem = device_problem();  \
    if (!problem.empty()) GTEST_SKIP() << problem; \
  } while (0)

TEST(CudaBatch, EmptyBatchTouchesNothing) {
  EXPECT_EQ(toroid_torus_intersect_batch_cuda(1, 0.25, 0, nullptr, nullptr, nullptr, nullptr, nullptr), 0);
  EXPECT_EQ(toroid_torus_intersect_batch_cuda_host(1, 0.25, 0, nullptr, nullptr, nullptr, nullptr), 0);
}

TEST(CudaBatch, NullArraysAreInvalidValues) {
  const double o[3] = {0, 0, 0}, d[3] = {1, 0, 0};
  int count = 7;
  double roots[4] = {1, 2, 3, 4};
  EXPECT_EQ(toroid_torus_intersect_batch_cuda(1, 0.25, 1, nullptr, d, &count, roots, nullptr), cudaErrorInvalidValue);
  EXPECT_EQ(toroid_torus_intersect_batch_cuda_host(1, 0.25, 1, o, d, &count, nullptr), cudaErrorInvalidValue);
  EXPECT_EQ(count, 7);  // nothing written
  EXPECT_EQ(roots[0], 1);
}

// Every family of the accuracy harness through the kernel: the CPU's bars
// (docs/torus.md) hold, and the answers are the CPU batch's bits (the
// library is built with --fmad=false, and the solver calls no math function
// that rounds differently on the device: docs/gpu.md).
TEST(CudaBatch, AccuracyFamiliesMeetTheBarsAndMatchTheCpu) {
  TOROID_REQUIRE_DEVICE();
  for (const accuracy::Family& f : accuracy::make_families(300)) {
    SCOPED_TRACE(f.name);
    Answers gpu;
    ASSERT_EQ(run_rays(f.rays, toroid_torus_intersect_batch_cuda_host, &gpu), 0);
    const Answers cpu = run_rays_cpu(f.rays);
    const Difference d = compare(gpu, cpu);
    EXPECT_EQ(d.counts_differ, 0u);
    EXPECT_EQ(d.rows_differ, 0u) << d.roots_differ << " roots differ, by up to " << d.max_ulps << " ulps and "
                                 << d.max_abs << " in t";

    const accuracy::ReferenceSet ref = accuracy::compute_references(f);
    const accuracy::Metrics m = accuracy::measure(f, ref, [&](const accuracy::RayCase& c, double t[4]) {
      const std::size_t i = static_cast<std::size_t>(&c - f.rays.data());
      const int n = gpu.counts[i] < 0 ? 0 : gpu.counts[i];
      for (int k = 0; k < n; ++k) t[k] = gpu.roots[4 * i + k];
      return n;
    });
    for (const std::string& v : accuracy::bar_violations(f, m)) ADD_FAILURE() << v;
  }
}

// NaN and infinite rays, zero directions, bad radii: the documented values
// (count 0 or -1, four NaNs), the CPU batch's bits.
TEST(CudaBatch, BadInputsGiveTheDocumentedValues) {
  TOROID_REQUIRE_DEVICE();
  const std::vector<accuracy::RayCase> rays = bad_input_rays();
  Answers gpu;
  ASSERT_EQ(run_rays(rays, toroid_torus_intersect_batch_cuda_host, &gpu), 0);
  const Answers cpu = run_rays_cpu(rays);
  const Difference d = compare(gpu, cpu);
  EXPECT_EQ(d.counts_differ, 0u);
  EXPECT_EQ(d.rows_differ, 0u);
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const bool radii_ok =
        std::isfinite(rays[i].major) && std::isfinite(rays[i].minor) && rays[i].major > 0 && rays[i].minor > 0;
    if (!radii_ok) {
      EXPECT_EQ(gpu.counts[i], -1) << "ray " << i;
    }
    for (int k = gpu.counts[i] < 0 ? 0 : gpu.counts[i]; k < 4; ++k) EXPECT_TRUE(std::isnan(gpu.roots[4 * i + k]));
  }
}

}  // namespace
}  // namespace toroid::cuda_check
