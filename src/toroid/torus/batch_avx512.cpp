// SPDX-License-Identifier: Apache-2.0
// The batch's AVX-512 path: batch_kernel.h on sixteen lanes, two AVX-512
// vectors of eight doubles (batch_two_vectors.h). Compiled with -mavx512f
// -ffp-contract=off (CMakeLists.txt), and called only where the CPU has
// AVX-512F (batch.cpp). fma() is the one fused operation: it stands where the
// scalar code calls std::fma.
#if TOROID_BATCH_X86_SIMD
#include <immintrin.h>

#include <cstddef>

namespace toroid {
namespace {

// One vector of the instruction set; the kernel's lanes are two of them
// (batch_two_vectors.h).
constexpr int kVecWidth = 8;

struct Vec {
  __m512d v;
};
struct Mask {
  __mmask8 m;
};

inline Vec vec_splat(double x) { return {_mm512_set1_pd(x)}; }
inline Vec vec_load(const double* p) { return {_mm512_load_pd(p)}; }
inline void vec_store(double* p, Vec a) { _mm512_store_pd(p, a.v); }
inline Vec operator+(Vec a, Vec b) { return {_mm512_add_pd(a.v, b.v)}; }
inline Vec operator-(Vec a, Vec b) { return {_mm512_sub_pd(a.v, b.v)}; }
inline Vec operator*(Vec a, Vec b) { return {_mm512_mul_pd(a.v, b.v)}; }
inline Vec operator/(Vec a, Vec b) { return {_mm512_div_pd(a.v, b.v)}; }
inline Vec operator-(Vec a) {
  return {_mm512_castsi512_pd(
      _mm512_xor_si512(_mm512_castpd_si512(a.v), _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ULL))))};
}
inline Vec abs(Vec a) { return {_mm512_abs_pd(a.v)}; }
// (The zero-masked form: GCC 12 warns of the undefined vector that the plain
// _mm512_sqrt_pd passes through.)
inline Vec sqrt(Vec a) { return {_mm512_maskz_sqrt_pd(0xFF, a.v)}; }
inline Vec fma(Vec a, Vec b, Vec c) { return {_mm512_fmadd_pd(a.v, b.v, c.v)}; }
inline Mask operator<(Vec a, Vec b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline Mask operator<=(Vec a, Vec b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline Mask operator>(Vec a, Vec b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)}; }
inline Mask operator==(Vec a, Vec b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline Mask operator!=(Vec a, Vec b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
inline Mask operator&(Mask a, Mask b) { return {static_cast<__mmask8>(a.m & b.m)}; }
inline Mask operator|(Mask a, Mask b) { return {static_cast<__mmask8>(a.m | b.m)}; }
inline Mask operator^(Mask a, Mask b) { return {static_cast<__mmask8>(a.m ^ b.m)}; }
inline Mask operator~(Mask a) { return {static_cast<__mmask8>(~a.m)}; }
// m ? a : b, lane by lane.
inline Vec select(Mask m, Vec a, Vec b) { return {_mm512_mask_blend_pd(m.m, b.v, a.v)}; }
// Bit l set where lane l of m is set.
inline unsigned bits(Mask m) { return m.m; }
// Each lane's bits as a 64-bit unsigned integer: +, -, |, & and shifts by 32.
inline __m512i as_int(Vec a) { return _mm512_castpd_si512(a.v); }
inline Vec as_double(__m512i i) { return {_mm512_castsi512_pd(i)}; }
inline Vec int_add(Vec a, Vec b) { return as_double(_mm512_add_epi64(as_int(a), as_int(b))); }
inline Vec int_sub(Vec a, Vec b) { return as_double(_mm512_sub_epi64(as_int(a), as_int(b))); }
inline Vec int_or(Vec a, Vec b) { return as_double(_mm512_or_si512(as_int(a), as_int(b))); }
inline Vec int_and(Vec a, Vec b) { return as_double(_mm512_and_si512(as_int(a), as_int(b))); }
inline Vec int_shift_right_32(Vec a) { return as_double(_mm512_maskz_srli_epi64(0xFF, as_int(a), 32)); }
inline Vec int_shift_left_32(Vec a) { return as_double(_mm512_maskz_slli_epi64(0xFF, as_int(a), 32)); }
// The lanes of a set in `lanes`, in order, to dst[0], dst[1], ...; writes
// kVecWidth doubles (compressed in a register and stored whole: the store form
// of the compress instruction is slow on some CPUs).
inline void compress(double* dst, unsigned lanes, Vec a) {
  _mm512_storeu_pd(dst, _mm512_maskz_compress_pd(static_cast<__mmask8>(lanes), a.v));
}
// The same for the kernel's 2 kVecWidth lanes of ints at src (one compress
// of sixteen): writes 2 kVecWidth ints.
inline void compress_lane_ints(int* dst, unsigned lanes, const int* src) {
  const __m512i v = _mm512_loadu_si512(src);
  _mm512_storeu_si512(dst, _mm512_maskz_compress_epi32(static_cast<__mmask16>(lanes & 0xFFFF), v));
}

// A row from a candidate's six slots (NaN where a slot holds no root): the
// slots' roots plus shift, in slot order, the first four, NaN after them.
// Returns how many it wrote.
inline int first_roots(const double* slots, double shift, double* row) {
  const __m512d v = _mm512_maskz_loadu_pd(0x3F, slots);
  const __mmask8 found = _mm512_mask_cmp_pd_mask(0x3F, v, v, _CMP_ORD_Q);
  const __m512d t = _mm512_add_pd(_mm512_set1_pd(shift), v);
  _mm512_mask_storeu_pd(row, 0xF, _mm512_mask_compress_pd(_mm512_set1_pd(__builtin_nan("")), found, t));
  const int n = __builtin_popcount(found);
  return n < 4 ? n : 4;
}

}  // namespace
}  // namespace toroid

#include "toroid/torus/batch_two_vectors.h"

#define TOROID_BATCH_ENTRY intersect_torus_batch_avx512
#define TOROID_BATCH_SEED_ENTRY cube_root_seeds_avx512
#include "toroid/torus/batch_kernel.h"
#endif
