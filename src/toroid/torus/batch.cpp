// SPDX-License-Identifier: Apache-2.0
// The batch call and the choice of its path at run time (batch.h).
#include "toroid/torus/batch.h"

#include <algorithm>

#include "toroid/math/cube_root.h"
#include "toroid/torus/checked.h"

namespace toroid {

#if TOROID_BATCH_X86_SIMD
// In batch_avx2.cpp and batch_avx512.cpp, each compiled for its instruction set.
long long intersect_torus_batch_avx2(double major, double minor, std::size_t n, const double* origins,
                                     const double* directions, int* counts, double* roots);
long long intersect_torus_batch_avx512(double major, double minor, std::size_t n, const double* origins,
                                       const double* directions, int* counts, double* roots);
void cube_root_seeds_avx2(std::size_t n, const double* in, double* out);
void cube_root_seeds_avx512(std::size_t n, const double* in, double* out);
#endif

namespace {

long long intersect_torus_batch_scalar(double major, double minor, std::size_t n, const double* origins,
                                       const double* directions, int* counts, double* roots) {
  const bool radii = torus_radii_valid(major, minor);
  long long total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const int count = intersect_torus_row(major, minor, origins + 3 * i, directions + 3 * i, roots + 4 * i);
    counts[i] = count;
    total += std::max(count, 0);
  }
  return radii ? total : -1;
}

}  // namespace

const char* batch_path_name(BatchPath path) {
  switch (path) {
    case BatchPath::Avx2: return "avx2";
    case BatchPath::Avx512: return "avx512";
    case BatchPath::Scalar: break;
  }
  return "scalar";
}

bool batch_path_available(BatchPath path) {
  switch (path) {
    case BatchPath::Scalar: return true;
#if TOROID_BATCH_X86_SIMD
    case BatchPath::Avx2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case BatchPath::Avx512: return __builtin_cpu_supports("avx512f");
#else
    default: return false;
#endif
  }
  return false;
}

BatchPath batch_path_best() {
  static const BatchPath best = batch_path_available(BatchPath::Avx512) ? BatchPath::Avx512
                                : batch_path_available(BatchPath::Avx2) ? BatchPath::Avx2
                                                                        : BatchPath::Scalar;
  return best;
}

long long intersect_torus_batch_on(BatchPath path, double major, double minor, std::size_t n, const double* origins,
                                   const double* directions, int* counts, double* roots) {
#if TOROID_BATCH_X86_SIMD
  if (path == BatchPath::Avx512)
    return intersect_torus_batch_avx512(major, minor, n, origins, directions, counts, roots);
  if (path == BatchPath::Avx2) return intersect_torus_batch_avx2(major, minor, n, origins, directions, counts, roots);
#endif
  (void)path;
  return intersect_torus_batch_scalar(major, minor, n, origins, directions, counts, roots);
}

void cube_root_seeds_on(BatchPath path, std::size_t n, const double* in, double* out) {
#if TOROID_BATCH_X86_SIMD
  if (path == BatchPath::Avx512) return cube_root_seeds_avx512(n, in, out);
  if (path == BatchPath::Avx2) return cube_root_seeds_avx2(n, in, out);
#endif
  (void)path;
  for (std::size_t i = 0; i < n; ++i) out[i] = cube_root_seed(in[i]);
}

long long intersect_torus_batch(double major, double minor, std::size_t n, const double* origins,
                                const double* directions, int* counts, double* roots) {
  return intersect_torus_batch_on(batch_path_best(), major, minor, n, origins, directions, counts, roots);
}

}  // namespace toroid
