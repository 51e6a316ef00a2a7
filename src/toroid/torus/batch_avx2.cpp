// SPDX-License-Identifier: Apache-2.0
// The batch's AVX2 path: batch_kernel.h on eight lanes, two AVX2 vectors of
// four doubles (batch_two_vectors.h).
// Compiled with -mavx2 -mfma -ffp-contract=off (CMakeLists.txt), and called
// only where the CPU has both (batch.cpp). fma() is the one fused operation:
// it stands where the scalar code calls std::fma.
#if TOROID_BATCH_X86_SIMD
#include <immintrin.h>

#include <cstddef>

namespace toroid {
namespace {

// One vector of the instruction set; the kernel's lanes are two of them
// (batch_two_vectors.h).
constexpr int kVecWidth = 4;

struct Vec {
  __m256d v;
};
struct Mask {
  __m256d m;
};

inline Vec vec_splat(double x) { return {_mm256_set1_pd(x)}; }
inline Vec vec_load(const double* p) { return {_mm256_load_pd(p)}; }
inline void vec_store(double* p, Vec a) { _mm256_store_pd(p, a.v); }
inline Vec operator+(Vec a, Vec b) { return {_mm256_add_pd(a.v, b.v)}; }
inline Vec operator-(Vec a, Vec b) { return {_mm256_sub_pd(a.v, b.v)}; }
inline Vec operator*(Vec a, Vec b) { return {_mm256_mul_pd(a.v, b.v)}; }
inline Vec operator/(Vec a, Vec b) { return {_mm256_div_pd(a.v, b.v)}; }
inline Vec operator-(Vec a) { return {_mm256_xor_pd(a.v, _mm256_set1_pd(-0.0))}; }
inline Vec abs(Vec a) { return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)}; }
inline Vec sqrt(Vec a) { return {_mm256_sqrt_pd(a.v)}; }
inline Vec fma(Vec a, Vec b, Vec c) { return {_mm256_fmadd_pd(a.v, b.v, c.v)}; }
inline Mask operator<(Vec a, Vec b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask operator<=(Vec a, Vec b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask operator>(Vec a, Vec b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_GT_OQ)}; }
inline Mask operator==(Vec a, Vec b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask operator!=(Vec a, Vec b) { return {_mm256_cmp_pd(a.v, b.v, _CMP_NEQ_UQ)}; }
inline Mask operator&(Mask a, Mask b) { return {_mm256_and_pd(a.m, b.m)}; }
inline Mask operator|(Mask a, Mask b) { return {_mm256_or_pd(a.m, b.m)}; }
inline Mask operator^(Mask a, Mask b) { return {_mm256_xor_pd(a.m, b.m)}; }
inline Mask operator~(Mask a) { return {_mm256_xor_pd(a.m, _mm256_castsi256_pd(_mm256_set1_epi64x(-1)))}; }
// m ? a : b, lane by lane.
inline Vec select(Mask m, Vec a, Vec b) { return {_mm256_blendv_pd(b.v, a.v, m.m)}; }
// Bit l set where lane l of m is set.
inline unsigned bits(Mask m) { return static_cast<unsigned>(_mm256_movemask_pd(m.m)); }
// Each lane's bits as a 64-bit unsigned integer: +, -, |, & and shifts by 32.
inline __m256i as_int(Vec a) { return _mm256_castpd_si256(a.v); }
inline Vec as_double(__m256i i) { return {_mm256_castsi256_pd(i)}; }
inline Vec int_add(Vec a, Vec b) { return as_double(_mm256_add_epi64(as_int(a), as_int(b))); }
inline Vec int_sub(Vec a, Vec b) { return as_double(_mm256_sub_epi64(as_int(a), as_int(b))); }
inline Vec int_or(Vec a, Vec b) { return as_double(_mm256_or_si256(as_int(a), as_int(b))); }
inline Vec int_and(Vec a, Vec b) { return as_double(_mm256_and_si256(as_int(a), as_int(b))); }
inline Vec int_shift_right_32(Vec a) { return as_double(_mm256_srli_epi64(as_int(a), 32)); }
inline Vec int_shift_left_32(Vec a) { return as_double(_mm256_slli_epi64(as_int(a), 32)); }
// The lanes of a set in `lanes`, in order, to dst[0], dst[1], ...; writes
// kVecWidth doubles. AVX2 has no compress: a permutation of the vector's 32-bit
// halves from a table indexed by the lane mask, then one store.
inline void compress(double* dst, unsigned lanes, Vec a) {
  alignas(32) static constexpr int kOrder[16][8] = {
      {0, 1, 0, 1, 0, 1, 0, 1}, {0, 1, 0, 1, 0, 1, 0, 1}, {2, 3, 0, 1, 0, 1, 0, 1}, {0, 1, 2, 3, 0, 1, 0, 1},
      {4, 5, 0, 1, 0, 1, 0, 1}, {0, 1, 4, 5, 0, 1, 0, 1}, {2, 3, 4, 5, 0, 1, 0, 1}, {0, 1, 2, 3, 4, 5, 0, 1},
      {6, 7, 0, 1, 0, 1, 0, 1}, {0, 1, 6, 7, 0, 1, 0, 1}, {2, 3, 6, 7, 0, 1, 0, 1}, {0, 1, 2, 3, 6, 7, 0, 1},
      {4, 5, 6, 7, 0, 1, 0, 1}, {0, 1, 4, 5, 6, 7, 0, 1}, {2, 3, 4, 5, 6, 7, 0, 1}, {0, 1, 2, 3, 4, 5, 6, 7}};
  const __m256i order = _mm256_load_si256(reinterpret_cast<const __m256i*>(kOrder[lanes & 15]));
  _mm256_storeu_pd(dst, _mm256_castps_pd(_mm256_permutevar8x32_ps(_mm256_castpd_ps(a.v), order)));
}
// The same for kVecWidth ints at src: writes kVecWidth ints. The table lists the
// lanes set in each mask, in order.
inline void compress_ints(int* dst, unsigned lanes, const int* src) {
  alignas(32) static constexpr int kLanes[16][8] = {
      {0, 0, 0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0, 0, 0}, {1, 0, 0, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0, 0, 0},
      {2, 0, 0, 0, 0, 0, 0, 0}, {0, 2, 0, 0, 0, 0, 0, 0}, {1, 2, 0, 0, 0, 0, 0, 0}, {0, 1, 2, 0, 0, 0, 0, 0},
      {3, 0, 0, 0, 0, 0, 0, 0}, {0, 3, 0, 0, 0, 0, 0, 0}, {1, 3, 0, 0, 0, 0, 0, 0}, {0, 1, 3, 0, 0, 0, 0, 0},
      {2, 3, 0, 0, 0, 0, 0, 0}, {0, 2, 3, 0, 0, 0, 0, 0}, {1, 2, 3, 0, 0, 0, 0, 0}, {0, 1, 2, 3, 0, 0, 0, 0}};
  const __m256i v = _mm256_zextsi128_si256(_mm_loadu_si128(reinterpret_cast<const __m128i*>(src)));
  const __m256i order = _mm256_load_si256(reinterpret_cast<const __m256i*>(kLanes[lanes & 15]));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(dst), _mm256_castsi256_si128(_mm256_permutevar8x32_epi32(v, order)));
}

// The same for the kernel's 2 kVecWidth lanes of ints: each half's, the
// high half's after the low half's lanes.
inline void compress_lane_ints(int* dst, unsigned lanes, const int* src) {
  compress_ints(dst, lanes & 15, src);
  compress_ints(dst + __builtin_popcount(lanes & 15), lanes >> 4, src + 4);
}

// A row from a candidate's six slots (NaN where a slot holds no root): the
// slots' roots plus shift, in slot order, the first four, NaN after them.
// Returns how many it wrote. (Scalar: the six slots span two vectors here.)
inline int first_roots(const double* slots, double shift, double* row) {
  double found[6];
  int n = 0;
  for (int k = 0; k < 6; ++k) {
    found[n] = shift + slots[k];
    n += slots[k] == slots[k];
  }
  n = n < 4 ? n : 4;
  for (int k = 0; k < 4; ++k) row[k] = k < n ? found[k] : __builtin_nan("");
  return n;
}

}  // namespace
}  // namespace toroid

#include "toroid/torus/batch_two_vectors.h"

#define TOROID_BATCH_ENTRY intersect_torus_batch_avx2
#define TOROID_BATCH_SEED_ENTRY cube_root_seeds_avx2
#include "toroid/torus/batch_kernel.h"
#endif
