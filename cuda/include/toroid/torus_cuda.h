/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The ray-torus batch of toroid on a CUDA device, for C and C++. Link
 * toroid::torus_cuda (CMake target toroid_torus_cuda), which links the CUDA
 * runtime. The answers are those of toroid_torus_intersect_batch
 * (toroid/torus_c.h): the kernel runs one thread per ray on the same source
 * as the CPU batch (toroid::intersect_torus_row), compiled for the device.
 * With the default build (--fmad=false, TOROID_CUDA_FMAD=OFF) no
 * multiply-add is contracted, as on baseline x86-64; docs/gpu.md says what
 * has been verified of that.
 *
 * Layout, as in the C batch: ray i is origins[3i..3i+2] +
 * t directions[3i..3i+2]; counts[i] gets its count (0..4, or -1 for invalid
 * radii) and roots[4i..4i+3] its roots, ascending, the slots beyond the
 * count NaN. Bad rays (a NaN or infinite component, a zero direction) give
 * 0 and four NaNs; invalid radii (not finite and > 0) give -1 and four NaNs
 * in every row.
 *
 * Both calls return 0 (cudaSuccess) or a cudaError_t value: with n > 0 and
 * a NULL array, cudaErrorInvalidValue and nothing is read or written; n == 0
 * returns 0 and touches nothing (no CUDA call is made).
 */
#ifndef TOROID_TORUS_CUDA_H
#define TOROID_TORUS_CUDA_H

#include <cuda_runtime_api.h>
#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The batch on device pointers (cudaMalloc'd or managed memory): launches
 * the kernel on `stream` and returns without waiting (synchronise the
 * stream before reading counts and roots). Returns the launch's error.
 */
int toroid_torus_intersect_batch_cuda(double major, double minor, size_t n, const double* d_origins,
                                      const double* d_directions, int* d_counts, double* d_roots, cudaStream_t stream);

/*
 * The batch on host arrays: copies origins and directions to the current
 * device, runs the kernel, copies counts and roots back and frees the device
 * memory; returns when they are written (or the first error).
 */
int toroid_torus_intersect_batch_cuda_host(double major, double minor, size_t n, const double* origins,
                                           const double* directions, int* counts, double* roots);

#ifdef __cplusplus
}
#endif

#endif /* TOROID_TORUS_CUDA_H */
