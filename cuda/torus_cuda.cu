// SPDX-License-Identifier: Apache-2.0
// The CUDA batch (toroid/torus_cuda.h): the kernel of torus_kernel.cuh, on
// device pointers and on host arrays.
#include "torus_kernel.cuh"
// (torus_kernel.cuh first: it includes the solver's sources under a renamed
// namespace.)
#include "toroid/torus_cuda.h"

extern "C" int toroid_torus_intersect_batch_cuda(double major, double minor, size_t n, const double* d_origins,
                                                 const double* d_directions, int* d_counts, double* d_roots,
                                                 cudaStream_t stream) {
  return launch_torus_batch(major, minor, n, d_origins, d_directions, d_counts, d_roots, stream);
}

extern "C" int toroid_torus_intersect_batch_cuda_host(double major, double minor, size_t n, const double* origins,
                                                      const double* directions, int* counts, double* roots) {
  return run_torus_batch_from_host(major, minor, n, origins, directions, counts, roots);
}
