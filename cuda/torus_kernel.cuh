// SPDX-License-Identifier: Apache-2.0
// The torus solver as device code: the torus library's own sources
// (roots/, torus/intersect, surface, checked), included into this one
// translation unit, so that nvcc compiles exactly the code the CPU build
// compiles, with no relocatable device code and everything inlinable into
// the kernel. TOROID_DEVICE_ONLY makes their TOROID_HD functions __device__
// alone, and the namespace is renamed for this translation unit (to
// TOROID_CUDA_NAMESPACE), so that nothing here clashes with toroid_torus's
// host definitions when both are linked. Include this once per .cu file, as
// the first include.
#pragma once

// The standard headers the sources include, first, so that the rename below
// reaches only the sources themselves.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

#include <cuda_runtime.h>

#ifndef TOROID_CUDA_NAMESPACE
#define TOROID_CUDA_NAMESPACE toroid_device
#endif

#define TOROID_DEVICE_ONLY
#define toroid TOROID_CUDA_NAMESPACE
#include "toroid/roots/cubic.cpp"
#include "toroid/roots/ferrari.cpp"
#include "toroid/roots/quadratic.cpp"
#include "toroid/roots/tianheng.cpp"
#include "toroid/torus/checked.cpp"
#include "toroid/torus/intersect.cpp"
#include "toroid/torus/surface.cpp"
#undef toroid

namespace {

// One thread per ray: the CPU batch's row, intersect_torus_row.
__global__ void torus_batch_kernel(double major, double minor, std::size_t n, const double* origins,
                                   const double* directions, int* counts, double* roots) {
  const std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= n) return;
  counts[i] =
      TOROID_CUDA_NAMESPACE::intersect_torus_row(major, minor, origins + 3 * i, directions + 3 * i, roots + 4 * i);
}

// Threads per block; a build may set another (tools/gpu-check.sh's variants).
#ifndef TOROID_CUDA_THREADS_PER_BLOCK
#define TOROID_CUDA_THREADS_PER_BLOCK 128
#endif
constexpr unsigned kThreadsPerBlock = TOROID_CUDA_THREADS_PER_BLOCK;

// Launches the kernel on device pointers; the error of the launch.
cudaError_t launch_torus_batch(double major, double minor, std::size_t n, const double* origins,
                               const double* directions, int* counts, double* roots, cudaStream_t stream) {
  if (n == 0) return cudaSuccess;
  if (origins == nullptr || directions == nullptr || counts == nullptr || roots == nullptr)
    return cudaErrorInvalidValue;
  const std::size_t blocks = (n + kThreadsPerBlock - 1) / kThreadsPerBlock;
  if (blocks > 0x7fffffffu) return cudaErrorInvalidValue;  // the grid's limit: n above 2^38
  torus_batch_kernel<<<static_cast<unsigned>(blocks), kThreadsPerBlock, 0, stream>>>(major, minor, n, origins,
                                                                                     directions, counts, roots);
  return cudaGetLastError();
}

// The batch on host arrays: copies in, launches on the default stream,
// copies out, frees; the first error.
cudaError_t run_torus_batch_from_host(double major, double minor, std::size_t n, const double* origins,
                                      const double* directions, int* counts, double* roots) {
  if (n == 0) return cudaSuccess;
  if (origins == nullptr || directions == nullptr || counts == nullptr || roots == nullptr)
    return cudaErrorInvalidValue;
  double *d_origins = nullptr, *d_directions = nullptr, *d_roots = nullptr;
  int* d_counts = nullptr;
  cudaError_t err = cudaMalloc(&d_origins, 3 * n * sizeof(double));
  if (err == cudaSuccess) err = cudaMalloc(&d_directions, 3 * n * sizeof(double));
  if (err == cudaSuccess) err = cudaMalloc(&d_counts, n * sizeof(int));
  if (err == cudaSuccess) err = cudaMalloc(&d_roots, 4 * n * sizeof(double));
  if (err == cudaSuccess) err = cudaMemcpy(d_origins, origins, 3 * n * sizeof(double), cudaMemcpyHostToDevice);
  if (err == cudaSuccess) err = cudaMemcpy(d_directions, directions, 3 * n * sizeof(double), cudaMemcpyHostToDevice);
  if (err == cudaSuccess) err = launch_torus_batch(major, minor, n, d_origins, d_directions, d_counts, d_roots, 0);
  if (err == cudaSuccess) err = cudaMemcpy(counts, d_counts, n * sizeof(int), cudaMemcpyDeviceToHost);
  if (err == cudaSuccess) err = cudaMemcpy(roots, d_roots, 4 * n * sizeof(double), cudaMemcpyDeviceToHost);
  // cudaFree(nullptr) does nothing; the first error is the one returned.
  cudaFree(d_origins);
  cudaFree(d_directions);
  cudaFree(d_counts);
  cudaFree(d_roots);
  return err;
}

}  // namespace
