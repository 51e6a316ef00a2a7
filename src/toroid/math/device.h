// SPDX-License-Identifier: Apache-2.0
// TOROID_HD marks the functions of the torus solver's path (math/
// double_double.h, roots/, torus/intersect, surface, checked) so that one
// source serves the CPU and a CUDA device: under nvcc it is
// __host__ __device__, everywhere else it is empty, so a C++ compiler sees
// exactly the code it would without it. The CUDA library (cuda/) defines
// TOROID_DEVICE_ONLY before including the solver's sources into its one
// translation unit: there the functions are __device__ alone, since their
// host copies come from toroid_torus (docs/gpu.md).
#pragma once

#if defined(__CUDACC__)
#if defined(TOROID_DEVICE_ONLY)
#define TOROID_HD __device__
#else
#define TOROID_HD __host__ __device__
#endif
#else
#define TOROID_HD
#endif
