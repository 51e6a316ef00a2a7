// SPDX-License-Identifier: Apache-2.0
// What the CUDA test and tools/gpu-check.sh's program share: the device
// check, the accuracy families and the bad inputs run through a batch call
// (one call per run of rays on the same torus), and the comparison of two
// batches' answers bit for bit and in ulps.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "accuracy/harness.h"

namespace toroid::cuda_check {

// Why no CUDA device can be used here ("" when one can).
std::string device_problem();

// A batch call on host arrays, as toroid_torus_intersect_batch_cuda_host.
using HostBatch = int (*)(double major, double minor, std::size_t n, const double* origins, const double* directions,
                          int* counts, double* roots);

// Counts and roots of a list of rays, laid out as the batch writes them.
struct Answers {
  std::vector<int> counts;
  std::vector<double> roots;
};

// The rays through `batch`, one call per run of consecutive rays on the same
// torus; returns the first call's error (0 for none).
int run_rays(const std::vector<accuracy::RayCase>& rays, HostBatch batch, Answers* out);
// The same through the CPU batch (toroid::intersect_torus_batch).
Answers run_rays_cpu(const std::vector<accuracy::RayCase>& rays);

// Distance in ulps between two doubles (0 for equal bits, or two NaNs;
// UINT64_MAX when one is NaN and the other is not).
std::uint64_t ulps_apart(double a, double b);

struct Difference {
  std::size_t rays = 0;
  std::size_t counts_differ = 0;  // rays whose counts differ
  std::size_t rows_differ = 0;    // rays with equal counts and a root of other bits
  std::size_t roots_differ = 0;   // such roots
  std::uint64_t max_ulps = 0;     // the largest distance among them in ulps
  double max_abs = 0;             // and in t (ulps mislead across 0)
};
Difference compare(const Answers& a, const Answers& b);

// The bad inputs of the C API (torus_c.h): NaN and infinite rays, zero
// directions, and radii that are not finite and > 0, beside good rays.
std::vector<accuracy::RayCase> bad_input_rays();

}  // namespace toroid::cuda_check
