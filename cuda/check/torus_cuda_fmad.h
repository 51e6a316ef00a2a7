// SPDX-License-Identifier: Apache-2.0
// The batch of toroid/torus_cuda.h compiled with --fmad=true
// (check/torus_cuda_fmad.cu): the same calls, for tools/gpu-check.sh.
#pragma once

#include <cstddef>

extern "C" {
int toroid_check_batch_fmad(double major, double minor, size_t n, const double* d_origins, const double* d_directions,
                            int* d_counts, double* d_roots);
int toroid_check_batch_fmad_host(double major, double minor, size_t n, const double* origins, const double* directions,
                                 int* counts, double* roots);
}
