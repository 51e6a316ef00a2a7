// SPDX-License-Identifier: Apache-2.0
// A second copy of the kernel, compiled with --fmad=true (contracted
// multiply-adds), for tools/gpu-check.sh to count how far its answers move
// from the CPU's. Its own namespace keeps its copies of the solver apart
// from the library's.
#define TOROID_CUDA_NAMESPACE toroid_device_fmad
#include "torus_kernel.cuh"
// (torus_kernel.cuh first: it includes the solver's sources under a renamed
// namespace.)
#include "check/torus_cuda_fmad.h"

extern "C" int toroid_check_batch_fmad(double major, double minor, size_t n, const double* d_origins,
                                       const double* d_directions, int* d_counts, double* d_roots) {
  return launch_torus_batch(major, minor, n, d_origins, d_directions, d_counts, d_roots, 0);
}

extern "C" int toroid_check_batch_fmad_host(double major, double minor, size_t n, const double* origins,
                                            const double* directions, int* counts, double* roots) {
  return run_torus_batch_from_host(major, minor, n, origins, directions, counts, roots);
}
