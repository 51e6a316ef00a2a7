// SPDX-License-Identifier: Apache-2.0
// The batch call's code paths: intersect_torus_batch (checked.h) runs the
// widest one this CPU has; tests and benchmarks pick one by name. Every path
// gives every row the single-ray call's answer, bit for bit: the SIMD paths
// run the default solver's common case on 8 or 16 rays at a time with the
// same operations in the same order (no fused multiply-add where the scalar
// code has none), and hand every ray that leaves that case (a near-tangent
// pair, a ray through the axis, a spindle, an invalid ray, a torus or ray far
// from unit size) to the scalar code.
#pragma once

#include <cstddef>

namespace toroid {

enum class BatchPath {
  Scalar,  // one ray at a time, on any CPU
  Avx2,    // 8 rays at a time (two vectors of four), x86-64 with AVX2 and FMA
  Avx512,  // 16 rays at a time (two vectors of eight), x86-64 with AVX-512F
};

// The path's name as the benchmarks print it: "scalar", "avx2", "avx512".
const char* batch_path_name(BatchPath path);

// Whether this build has the path and this CPU can run it.
bool batch_path_available(BatchPath path);

// The path intersect_torus_batch takes here: the widest available one.
BatchPath batch_path_best();

// intersect_torus_batch on the given path, which must be available.
long long intersect_torus_batch_on(BatchPath path, double major, double minor, std::size_t n, const double* origins,
                                   const double* directions, int* counts, double* roots);

// cube_root_seed (math/cube_root.h) of in[i], for in[i] in [2^-900, 2^900],
// computed as the path computes it (on its vectors), into out[i]: the tests
// check each path's against the scalar seed, bit for bit.
void cube_root_seeds_on(BatchPath path, std::size_t n, const double* in, double* out);

}  // namespace toroid
