// SPDX-License-Identifier: Apache-2.0
// The SIMD batch's lane vector VD (and its mask VM) as two vectors of the
// instruction set, for batch_kernel.h. Included by batch_avx2.cpp and
// batch_avx512.cpp after each defines its own vector Vec of kVecWidth doubles
// and its Mask with their operations (vec_splat, vec_load, vec_store,
// arithmetic, comparisons, select, bits, the integer operations, compress
// of a Vec, and compress_lane_ints on kWidth ints). The kernel's steps are bound by the latency of their
// chains of square roots and divisions, not by how many issue: two
// independent vectors per operation keep twice as many chains in flight
// (the AVX2 path ran about 7% faster on eight lanes than on four, the AVX-512
// path about 3% faster on sixteen than on eight; CHANGELOG 2026-12-05).
#pragma once

namespace toroid {
namespace {

constexpr int kWidth = 2 * kVecWidth;
constexpr unsigned kLowLanes = (1u << kVecWidth) - 1;

struct VD {
  Vec lo, hi;
};
struct VM {
  Mask lo, hi;
};

inline VD splat(double x) {
  const Vec v = vec_splat(x);
  return {v, v};
}
inline VD load(const double* p) { return {vec_load(p), vec_load(p + kVecWidth)}; }
inline void store(double* p, VD a) {
  vec_store(p, a.lo);
  vec_store(p + kVecWidth, a.hi);
}
inline VD operator+(VD a, VD b) { return {a.lo + b.lo, a.hi + b.hi}; }
inline VD operator-(VD a, VD b) { return {a.lo - b.lo, a.hi - b.hi}; }
inline VD operator*(VD a, VD b) { return {a.lo * b.lo, a.hi * b.hi}; }
inline VD operator/(VD a, VD b) { return {a.lo / b.lo, a.hi / b.hi}; }
inline VD operator-(VD a) { return {-a.lo, -a.hi}; }
inline VD abs(VD a) { return {abs(a.lo), abs(a.hi)}; }
inline VD sqrt(VD a) { return {sqrt(a.lo), sqrt(a.hi)}; }
inline VD fma(VD a, VD b, VD c) { return {fma(a.lo, b.lo, c.lo), fma(a.hi, b.hi, c.hi)}; }
inline VM operator<(VD a, VD b) { return {a.lo < b.lo, a.hi < b.hi}; }
inline VM operator<=(VD a, VD b) { return {a.lo <= b.lo, a.hi <= b.hi}; }
inline VM operator>(VD a, VD b) { return {a.lo > b.lo, a.hi > b.hi}; }
inline VM operator==(VD a, VD b) { return {a.lo == b.lo, a.hi == b.hi}; }
inline VM operator!=(VD a, VD b) { return {a.lo != b.lo, a.hi != b.hi}; }
inline VM operator&(VM a, VM b) { return {a.lo & b.lo, a.hi & b.hi}; }
inline VM operator|(VM a, VM b) { return {a.lo | b.lo, a.hi | b.hi}; }
inline VM operator^(VM a, VM b) { return {a.lo ^ b.lo, a.hi ^ b.hi}; }
inline VM operator~(VM a) { return {~a.lo, ~a.hi}; }
// m ? a : b, lane by lane.
inline VD select(VM m, VD a, VD b) { return {select(m.lo, a.lo, b.lo), select(m.hi, a.hi, b.hi)}; }
// Bit l set where lane l of m is set.
inline unsigned bits(VM m) { return bits(m.lo) | bits(m.hi) << kVecWidth; }
// Each lane's bits as a 64-bit unsigned integer: +, -, |, & and shifts by 32.
inline VD int_add(VD a, VD b) { return {int_add(a.lo, b.lo), int_add(a.hi, b.hi)}; }
inline VD int_sub(VD a, VD b) { return {int_sub(a.lo, b.lo), int_sub(a.hi, b.hi)}; }
inline VD int_or(VD a, VD b) { return {int_or(a.lo, b.lo), int_or(a.hi, b.hi)}; }
inline VD int_and(VD a, VD b) { return {int_and(a.lo, b.lo), int_and(a.hi, b.hi)}; }
inline VD int_shift_right_32(VD a) { return {int_shift_right_32(a.lo), int_shift_right_32(a.hi)}; }
inline VD int_shift_left_32(VD a) { return {int_shift_left_32(a.lo), int_shift_left_32(a.hi)}; }
// The lanes of a set in `lanes`, in order, to dst[0], dst[1], ...; writes up
// to kWidth doubles: the low vector's, then the high one's after them.
inline void compress(double* dst, unsigned lanes, VD a) {
  compress(dst, lanes & kLowLanes, a.lo);
  compress(dst + __builtin_popcount(lanes & kLowLanes), lanes >> kVecWidth, a.hi);
}
// The same for kWidth ints at src (the instruction set's compress_lane_ints).
inline void compress(int* dst, unsigned lanes, const int* src) { compress_lane_ints(dst, lanes, src); }

}  // namespace
}  // namespace toroid
