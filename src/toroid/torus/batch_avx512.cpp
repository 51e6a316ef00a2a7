// SPDX-License-Identifier: Apache-2.0
// The batch's 8-wide path: batch_kernel.h on AVX-512 vectors of eight
// doubles. Compiled with -mavx512f -ffp-contract=off (CMakeLists.txt), and
// called only where the CPU has AVX-512F (batch.cpp). fma() is the one fused
// operation: it stands where the scalar code calls std::fma.
#if TOROID_BATCH_X86_SIMD
#include <immintrin.h>

#include <cstddef>

namespace toroid {
namespace {

constexpr int kWidth = 8;

struct VD {
  __m512d v;
};
struct VM {
  __mmask8 m;
};

inline VD splat(double x) { return {_mm512_set1_pd(x)}; }
inline VD load(const double* p) { return {_mm512_load_pd(p)}; }
inline void store(double* p, VD a) { _mm512_store_pd(p, a.v); }
inline VD operator+(VD a, VD b) { return {_mm512_add_pd(a.v, b.v)}; }
inline VD operator-(VD a, VD b) { return {_mm512_sub_pd(a.v, b.v)}; }
inline VD operator*(VD a, VD b) { return {_mm512_mul_pd(a.v, b.v)}; }
inline VD operator/(VD a, VD b) { return {_mm512_div_pd(a.v, b.v)}; }
inline VD operator-(VD a) {
  return {_mm512_castsi512_pd(
      _mm512_xor_si512(_mm512_castpd_si512(a.v), _mm512_set1_epi64(static_cast<long long>(0x8000000000000000ULL))))};
}
inline VD abs(VD a) { return {_mm512_abs_pd(a.v)}; }
// (The zero-masked form: GCC 12 warns of the undefined vector that the plain
// _mm512_sqrt_pd passes through.)
inline VD sqrt(VD a) { return {_mm512_maskz_sqrt_pd(0xFF, a.v)}; }
inline VD fma(VD a, VD b, VD c) { return {_mm512_fmadd_pd(a.v, b.v, c.v)}; }
inline VM operator<(VD a, VD b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
inline VM operator<=(VD a, VD b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)}; }
inline VM operator>(VD a, VD b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)}; }
inline VM operator==(VD a, VD b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_EQ_OQ)}; }
inline VM operator!=(VD a, VD b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
inline VM operator&(VM a, VM b) { return {static_cast<__mmask8>(a.m & b.m)}; }
inline VM operator|(VM a, VM b) { return {static_cast<__mmask8>(a.m | b.m)}; }
inline VM operator^(VM a, VM b) { return {static_cast<__mmask8>(a.m ^ b.m)}; }
inline VM operator~(VM a) { return {static_cast<__mmask8>(~a.m)}; }
// m ? a : b, lane by lane.
inline VD select(VM m, VD a, VD b) { return {_mm512_mask_blend_pd(m.m, b.v, a.v)}; }
// Bit l set where lane l of m is set.
inline unsigned bits(VM m) { return m.m; }
// Each lane's bits as a 64-bit unsigned integer: +, -, |, & and shifts by 32.
inline __m512i as_int(VD a) { return _mm512_castpd_si512(a.v); }
inline VD as_double(__m512i i) { return {_mm512_castsi512_pd(i)}; }
inline VD int_add(VD a, VD b) { return as_double(_mm512_add_epi64(as_int(a), as_int(b))); }
inline VD int_sub(VD a, VD b) { return as_double(_mm512_sub_epi64(as_int(a), as_int(b))); }
inline VD int_or(VD a, VD b) { return as_double(_mm512_or_si512(as_int(a), as_int(b))); }
inline VD int_and(VD a, VD b) { return as_double(_mm512_and_si512(as_int(a), as_int(b))); }
inline VD int_shift_right_32(VD a) { return as_double(_mm512_maskz_srli_epi64(0xFF, as_int(a), 32)); }
inline VD int_shift_left_32(VD a) { return as_double(_mm512_maskz_slli_epi64(0xFF, as_int(a), 32)); }
// The lanes of a set in `lanes`, in order, to dst[0], dst[1], ...; writes
// kWidth doubles (compressed in a register and stored whole: the store form
// of the compress instruction is slow on some CPUs).
inline void compress(double* dst, unsigned lanes, VD a) {
  _mm512_storeu_pd(dst, _mm512_maskz_compress_pd(static_cast<__mmask8>(lanes), a.v));
}
// The same for kWidth ints at src: writes kWidth ints. (Masked loads and
// stores of the low eight lanes: GCC 12 warns of the undefined upper half
// that the 256-bit casts would carry.)
inline void compress(int* dst, unsigned lanes, const int* src) {
  const __m512i v = _mm512_maskz_loadu_epi32(0xFF, src);
  _mm512_mask_storeu_epi32(dst, 0xFF, _mm512_maskz_compress_epi32(static_cast<__mmask16>(lanes & 0xFF), v));
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

#define TOROID_BATCH_ENTRY intersect_torus_batch_avx512
#define TOROID_BATCH_SEED_ENTRY cube_root_seeds_avx512
#include "toroid/torus/batch_kernel.h"
#endif
