// SPDX-License-Identifier: Apache-2.0
// The SIMD batch: the default solver's common case (intersect.cpp) on
// kWidth rays at a time, included by batch_avx2.cpp and batch_avx512.cpp
// after each defines its vector of doubles VD, its lane mask VM and their
// operations, and TOROID_BATCH_ENTRY and TOROID_BATCH_SEED_ENTRY, the entry
// points' names. Everything
// here has internal linkage, so the two instruction sets never share code.
//
// Every lane performs the scalar solver's operations in the scalar order,
// so each root is the scalar root, bit for bit; intersect_torus_batch's tests
// compare every row. A ray that leaves the common case goes to the scalar
// code (intersect_torus_row), which answers it as the single-ray call does:
// a spindle or horn torus, a torus or direction outside the solver's range,
// an invalid ray, a ray through or within rounding of the axis, an exact
// zero of h at a cut, a near-tangent pair.
//
// The rays of a chunk go through four stages, each on full vectors:
//  1. the move to the point nearest the centre, and the chord inside the
//     ball and the slab: most misses end here;
//  2. the convexity cuts and h at every cut, and each piece's case: one
//     root (a root search) or none-or-two (a pair search);
//  3. the pair searches: where the end tangents cross, until the pair is
//     split or shown empty; where half a vector's pairs or more split at
//     once, their two roots' searches start there, while the vector holds
//     their rays, and most end there;
//  4. the root searches left (Halley guarded by bisection); a lane whose
//     search ends takes the next one, so that no lane idles while work is
//     left.
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>

#include "toroid/math/cube_root.h"
#include "toroid/torus/batch.h"
#include "toroid/torus/checked.h"
#include "toroid/torus/hole.h"

namespace toroid {
namespace {

constexpr double kBatchEps = std::numeric_limits<double>::epsilon();
constexpr double kBatchNaN = std::numeric_limits<double>::quiet_NaN();
// Rays per chunk: the stages' lists of a chunk stay in the second-level caches.
constexpr int kChunk = 256;
// Roots per piece (two) times pieces (at most three): a candidate's slots.
constexpr int kSlots = 6;
static_assert(kSlots == 6, "first_roots (the instruction sets' files) reads six slots");

template <class F>
inline void for_each_lane(unsigned lanes, F&& f) {
  while (lanes != 0) {
    f(__builtin_ctz(lanes));
    lanes &= lanes - 1;
  }
}

// The vector of values[index[l]] over the lanes l. (Loads lane by lane:
// the CPU's gather instructions were slower here, on AMD EPYC with AVX2 and
// with AVX-512.)
inline VD gather(const double* values, const int* index) {
  alignas(64) double lanes[kWidth];
  for (int l = 0; l < kWidth; ++l) lanes[l] = values[index[l]];
  return load(lanes);
}

// A vector whose every lane holds the bit pattern `bits`.
inline VD splat_bits(std::uint64_t bits) { return splat(std::bit_cast<double>(bits)); }

// cube_root_seed (math/cube_root.h) on every lane, bit for bit: the lane's
// bits u = hi 2^32 + lo divided by 3 as q 2^32 + (r 2^32 + lo) / 3, with hi
// = 3 q + r. Each quotient is of integers below 2^34, found in double:
// y / 3 - 1/3 rounded to the nearest integer is floor(y / 3), since its
// fraction is 0 or +-1/3 up to rounding far below 1/6. Adding 1.5 2^52
// rounds a double of magnitude below 2^51 to an integer, whose bits are then
// those of 1.5 2^52 plus the integer; or-ing an integer below 2^52 into
// 2^52's bits is 2^52 plus it.
inline VD cube_root_seed(VD a) {
  const VD two52 = splat(0x1p52), two52_bits = splat_bits(0x4330000000000000ull);
  const VD round = splat(0x1.8p52), round_bits = splat_bits(0x4338000000000000ull);
  const auto to_double = [&](VD i) { return int_or(i, two52_bits) - two52; };
  const auto to_int = [&](VD d) { return int_sub(d + round, round_bits); };
  const VD third = splat(1.0 / 3);
  const auto div3 = [&](VD y) { return ((y * third - third) + round) - round; };
  const VD hi = to_double(int_shift_right_32(a));
  const VD lo = to_double(int_and(a, splat_bits(0xFFFFFFFFull)));
  const VD q = div3(hi);
  const VD t = (hi - splat(3.0) * q) * splat(0x1p32) + lo;
  const VD quotient = int_add(int_shift_left_32(to_int(q)), to_int(div3(t)));
  return int_add(quotient, splat_bits(kCubeRootSeedBias));
}

struct SampleV {
  VD s, h, dh, d2h, d3h;
};

// The outer factor h_out along the shifted ray, as TorusFactor holds it.
struct FactorV {
  VD oh[3], ol[3], d[3], dd, kc;  // kc = -2 R K
};

// RootSearch's state on kWidth lanes.
struct SearchV {
  VD lo, hi, x, tol, iterations;
  VM lo_negative;
};

// The rays of a chunk that reach stage 2, by column. Each column of doubles
// has kWidth spare entries, which compress() may write past the last one.
struct Candidates {
  static constexpr int kColumn = kChunk + kWidth;
  alignas(64) double oh[3][kColumn], ol[3][kColumn], d[3][kColumn];
  alignas(64) double dd[kColumn], kc[kColumn], lo[kColumn], hi[kColumn], tol_root[kColumn], t_shift[kColumn];
  int ray[kColumn];  // its index in the chunk
  bool fallback[kColumn];
  // Slot k's root, NaN where the slot holds none. The last row is never a
  // candidate's: stores for lanes that have no root to keep go there.
  double roots[kColumn][kSlots];
  int n;
};

// Brackets where h changes sign once, for stage 4: RootSearch's state,
// from its start or after some steps. The columns of doubles have kWidth
// spare entries, which compress() may write past the last one.
struct RootJobs {
  static constexpr int kMax = kChunk * kSlots;
  double lo[kMax + kWidth], hi[kMax + kWidth], x[kMax + kWidth], tol[kMax + kWidth], iterations[kMax + kWidth];
  double lo_negative[kMax + kWidth];  // 1 or 0
  int candidate[kMax + kWidth], slot[kMax + kWidth];
  int n;
};

// Pieces whose ends have g = sigma h > 0 and a minimum between, for stage 3.
// Padded to whole vectors with copies of the first job (pad_pairs).
struct PairJobs {
  static constexpr int kMax = kChunk * 3;
  alignas(64) double a[4][kMax + kWidth], b[4][kMax + kWidth];  // s, h, h', h'' at each end
  alignas(64) double sigma[kMax + kWidth];
  int candidate[kMax + kWidth], slot[kMax + kWidth];
  int n;
};

struct Workspace {
  Candidates cand;
  RootJobs roots;
  PairJobs pairs;
  int fallback_rays[kChunk + kWidth];  // the rays of the chunk that stage 1 hands to the scalar code
  int n_fallback;
};

class BatchSolver {
 public:
  BatchSolver(double major, double minor) : R_(major), r_(minor) {}

  // Rays [0, m) of the chunk at origins, directions (m <= kChunk).
  long long chunk(std::size_t m, const double* origins, const double* directions, int* counts, double* roots) {
    ws_.cand.n = 0;
    ws_.roots.n = 0;
    ws_.pairs.n = 0;
    ws_.n_fallback = 0;
    for (std::size_t base = 0; base < m; base += kWidth) chords(base, m, origins, directions);
    pad_candidates();
    for (int base = 0; base < ws_.cand.n; base += kWidth) cuts(base);
    pair_searches();
    root_searches();
    return write_rows(m, origins, directions, counts, roots);
  }

 private:
  FactorV factor_at(int base) const {
    const Candidates& c = ws_.cand;
    FactorV f;
    for (int k = 0; k < 3; ++k) {
      f.oh[k] = load(&c.oh[k][base]);
      f.ol[k] = load(&c.ol[k][base]);
      f.d[k] = load(&c.d[k][base]);
    }
    f.dd = load(&c.dd[base]);
    f.kc = load(&c.kc[base]);
    return f;
  }

  FactorV factor_of(const int* candidate) const {
    const Candidates& c = ws_.cand;
    FactorV f;
    for (int k = 0; k < 3; ++k) {
      f.oh[k] = gather(c.oh[k], candidate);
      f.ol[k] = gather(c.ol[k], candidate);
      f.d[k] = gather(c.d[k], candidate);
    }
    f.dd = gather(c.dd, candidate);
    f.kc = gather(c.kc, candidate);
    return f;
  }

  // TorusFactor::sample for h_out; rho_zero marks the lanes where rho = 0,
  // which the scalar code treats apart.
  SampleV sample(const FactorV& f, VD s, VM* rho_zero) const {
    VD p[3];
    for (int k = 0; k < 3; ++k) p[k] = f.oh[k] + (s * f.d[k] + f.ol[k]);
    const VD rho = sqrt(p[0] * p[0] + p[1] * p[1]);
    const VD a = rho + splat(-R_);
    const VD h = (a - splat(r_)) * (a + splat(r_)) + p[2] * p[2];
    *rho_zero = rho == splat(0.0);
    const VD inv_rho = splat(1.0) / rho;
    const VD drho = (p[0] * f.d[0] + p[1] * f.d[1]) * inv_rho;
    const VD k = f.kc * ((inv_rho * inv_rho) * inv_rho);
    return {s, h, splat(2.0) * (a * drho + p[2] * f.d[2]), splat(2.0) * f.dd + k, ((splat(-3.0) * k) * drho) * inv_rho};
  }

  // first_guess of intersect.cpp.
  static VD first_guess(const SampleV& from, VD lo, VD hi) {
    const VD halley =
        from.s - ((splat(2.0) * from.h) * from.dh) / ((splat(2.0) * from.dh) * from.dh - from.h * from.d2h);
    const VD newton = from.s - from.h / from.dh;
    const VM halley_inside = (halley > lo) & (halley < hi);
    const VM newton_inside = (newton > lo) & (newton < hi);
    return select(halley_inside, halley, select(newton_inside, newton, splat(0.5) * (lo + hi)));
  }

  // Queues, for the lanes in `lanes`, the root search on (lo, hi) that
  // starts from `start`, as RootSearch's constructor sets it up.
  void push_roots(unsigned lanes, const int* candidate, int slot_offset, const int* slot, const SampleV& start, VD lo,
                  VD hi, VM lo_negative, VD tol_root) {
    enqueue(lanes, start_search(start, lo, hi, lo_negative, tol_root), candidate, slot, slot_offset);
  }

  // Queues the searches of the lanes in `lanes` for stage 4, in their state.
  void enqueue(unsigned lanes, const SearchV& st, const int* candidate, const int* slot, int slot_offset) {
    RootJobs& q = ws_.roots;
    compress(q.lo + q.n, lanes, st.lo);
    compress(q.hi + q.n, lanes, st.hi);
    compress(q.x + q.n, lanes, st.x);
    compress(q.tol + q.n, lanes, st.tol);
    compress(q.iterations + q.n, lanes, st.iterations);
    compress(q.lo_negative + q.n, lanes, select(st.lo_negative, splat(1.0), splat(0.0)));
    int slot_l[kWidth];
    for (int l = 0; l < kWidth; ++l) slot_l[l] = slot[l] + slot_offset;
    compress(q.candidate + q.n, lanes, candidate);
    compress(q.slot + q.n, lanes, slot_l);
    q.n += __builtin_popcount(lanes);
  }

  // Stage 1 on rays [base, base + kWidth) of the chunk (those below m).
  void chords(std::size_t base, std::size_t m, const double* origins, const double* directions) {
    int index[kWidth];  // of each lane's ray's x in origins + 3 base, directions + 3 base
    unsigned live = 0;
    for (int l = 0; l < kWidth; ++l) {
      if (base + l < m) live |= 1u << l;
      index[l] = base + l < m ? 3 * l : 0;
    }
    VD o[3], d[3];
    VM finite = splat(0.0) == splat(0.0);
    for (int k = 0; k < 3; ++k) {
      o[k] = gather(origins + 3 * base + k, index);
      d[k] = gather(directions + 3 * base + k, index);
      finite = finite & (abs(o[k]) <= splat(std::numeric_limits<double>::max())) &
               (abs(d[k]) <= splat(std::numeric_limits<double>::max()));
    }
    const VD zero = splat(0.0);
    const VM has_direction = (d[0] != zero) | (d[1] != zero) | (d[2] != zero);
    // shift_to_nearest_centre_point and in_solver_range.
    const VD dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const VM in_range = (dd > splat(0x1p-400)) & (dd < splat(0x1p400));
    VM fallback = ~(finite & has_direction & in_range);
    const VD od = o[0] * d[0] + o[1] * d[1] + o[2] * d[2];
    const VD t_shift = -od / dd;
    VD oh[3], ol[3];
    for (int k = 0; k < 3; ++k) {  // add_scaled(origin, t_shift, d)
      const VD p = t_shift * d[k];
      const VD p_err = fma(t_shift, d[k], -p);
      const VD s = o[k] + p;
      const VD bb = s - o[k];
      const VD s_lo = (o[k] - (s - bb)) + (p - bb);
      const VD lo = s_lo + p_err;
      oh[k] = s + lo;
      ol[k] = lo - (oh[k] - s);
    }
    // factor_roots: the chord inside the ball of radius R + r, then the slab.
    const VD b = oh[0] * d[0] + oh[1] * d[1] + oh[2] * d[2];
    const VD oo = oh[0] * oh[0] + oh[1] * oh[1] + oh[2] * oh[2];
    const double rad = (R_ + r_) * (1 + 1e-9) + 1e-300;
    const VD disc = b * b - dd * (oo - splat(rad * rad));
    VM miss = disc < zero;
    const VD w = sqrt(disc);
    VD lo = (-b - w) / dd;
    VD hi = (-b + w) / dd;
    const VD zo = oh[2] + ol[2];
    const VD slab_face = splat(r_ * (1 + 1e-9) + 1e-300);
    const VD slab_rounding = splat(r_) + splat(8 * kBatchEps) * abs(zo);
    const VD slab = select(slab_face < slab_rounding, slab_rounding, slab_face);
    const VM oblique = d[2] != zero;
    VD z_lo = (-slab - zo) / d[2], z_hi = (slab - zo) / d[2];
    const VM swap = z_lo > z_hi;
    const VD z_first = select(swap, z_hi, z_lo), z_last = select(swap, z_lo, z_hi);
    lo = select(oblique & (lo < z_first), z_first, lo);
    hi = select(oblique & (z_last < hi), z_last, hi);
    miss = miss | (~oblique & (abs(zo) > slab)) | (hi < lo);
    // A ray through a ring torus's hole (hole.h), as factor_roots tests it.
    VD end_rho2[2];
    for (int e = 0; e < 2; ++e) {
      const VD s = e == 0 ? lo : hi;
      const VD x = oh[0] + (s * d[0] + ol[0]), y = oh[1] + (s * d[1] + ol[1]);
      end_rho2[e] = x * x + y * y;
    }
    const VD limit = splat(hole_limit(R_, r_));
    miss = miss | ((end_rho2[0] < limit) & (end_rho2[1] < limit));
    // The tolerance of the roots, from RootCollector.
    const VD tol_root = splat(2 * kBatchEps) * (splat(r_) / sqrt(dd));

    const unsigned fallback_lanes = bits(fallback) & live;
    const unsigned candidate_lanes = bits(~fallback & ~miss) & live;
    int ray[kWidth];
    for (int l = 0; l < kWidth; ++l) ray[l] = static_cast<int>(base + l);
    if (fallback_lanes != 0) {
      compress(ws_.fallback_rays + ws_.n_fallback, fallback_lanes, ray);
      ws_.n_fallback += __builtin_popcount(fallback_lanes);
    }
    if (candidate_lanes == 0) return;
    Candidates& c = ws_.cand;
    for (int k = 0; k < 3; ++k) {
      compress(c.oh[k] + c.n, candidate_lanes, oh[k]);
      compress(c.ol[k] + c.n, candidate_lanes, ol[k]);
      compress(c.d[k] + c.n, candidate_lanes, d[k]);
    }
    compress(c.dd + c.n, candidate_lanes, dd);
    compress(c.lo + c.n, candidate_lanes, lo);
    compress(c.hi + c.n, candidate_lanes, hi);
    compress(c.tol_root + c.n, candidate_lanes, tol_root);
    compress(c.t_shift + c.n, candidate_lanes, t_shift);
    compress(c.ray + c.n, candidate_lanes, ray);
    for (int j = c.n; j < c.n + kWidth; ++j) {  // (kc is set in stage 2)
      c.fallback[j] = false;
      for (int k = 0; k < kSlots; ++k) c.roots[j][k] = kBatchNaN;
    }
    c.n += __builtin_popcount(candidate_lanes);
  }

  // Fills the candidates' columns up to a whole vector with copies of the
  // first, so that stage 2's last vector reads real rays.
  void pad_candidates() {
    Candidates& c = ws_.cand;
    if (c.n == 0) return;
    for (int j = c.n; j % kWidth != 0; ++j) {
      for (int k = 0; k < 3; ++k) c.oh[k][j] = c.oh[k][0], c.ol[k][j] = c.ol[k][0], c.d[k][j] = c.d[k][0];
      c.dd[j] = c.dd[0];
      c.kc[j] = 0;
      c.lo[j] = c.lo[0];
      c.hi[j] = c.hi[0];
      c.tol_root[j] = c.tol_root[0];
    }
  }

  // Stage 2 on candidates [base, base + kWidth).
  void cuts(int base) {
    Candidates& c = ws_.cand;
    unsigned live = 0;
    int candidate[kWidth], zero_slot[kWidth] = {};
    for (int l = 0; l < kWidth; ++l) {
      candidate[l] = base + l;
      if (base + l < c.n) live |= 1u << l;
    }
    FactorV f = factor_at(base);
    const VD zero = splat(0.0);
    const VD lo = load(&c.lo[base]), hi = load(&c.hi[base]);
    // The TorusFactor's constants, and factor_roots's convexity cuts.
    const VD cc = f.d[0] * f.d[0] + f.d[1] * f.d[1];
    const VD cross = f.oh[0] * f.d[1] - f.oh[1] * f.d[0];
    const VD K = cross * cross;
    f.kc = splat(-2.0 * R_) * K;
    store(&c.kc[base], f.kc);
    const VM not_vertical = cc > zero;
    VM fallback = not_vertical & (K == zero);  // a ray through the axis
    const VD s_axis = -(f.oh[0] * f.d[0] + f.oh[1] * f.d[1]) / cc;
    const VD rho_i3 = (splat(R_) * K) / f.dd, rho_min2 = K / cc;
    const VD square = rho_i3 * rho_i3;
    const VM has_concave = not_vertical & (K != zero) & (square > (rho_min2 * rho_min2) * rho_min2);
    // Where the square and cube underflow, the scalar code decides with
    // cube roots: those rays go to it.
    fallback = fallback | (not_vertical & (K != zero) & ~has_concave & (square < splat(0x1p-1000)));
    const unsigned concave_lanes = bits(has_concave) & live;
    VD concave_lo = zero, concave_hi = zero;
    VM cut_lo = splat(1.0) == zero, cut_hi = cut_lo;
    if (concave_lanes != 0) {
      // cube_root on the vector; a lane outside the iteration's range
      // takes the scalar cube_root (the other lanes' values are not used).
      const VM in_range = (splat(0x1p-900) <= rho_i3) & (rho_i3 <= splat(0x1p900));
      const unsigned outside = ~bits(in_range) & ((1u << kWidth) - 1);
      const VD a = select(in_range, rho_i3, splat(1.0));
      VD rho_i = cube_root_refine(a, cube_root_seed(a));
      if ((outside & concave_lanes) != 0) {
        alignas(64) double a_l[kWidth], roots_l[kWidth];
        store(roots_l, rho_i);
        store(a_l, rho_i3);
        for_each_lane(outside & concave_lanes, [&](int l) { roots_l[l] = cube_root(a_l[l]); });
        rho_i = load(roots_l);
      }
      // Where the concave stretch is too narrow for rho's rounding, the
      // scalar code cuts the axis passage as a kink (intersect.cpp's
      // kAxisBlur, 2^-32): those rays go to it.
      fallback = fallback | (has_concave & (rho_i <= splat(0x1p-32) * (abs(f.oh[0]) + abs(f.oh[1]))));
      const VD excess = rho_i * rho_i - rho_min2;
      const VD hw = sqrt(select(zero < excess, excess, zero) / cc);
      concave_lo = select(has_concave, s_axis - hw, zero);
      concave_hi = select(has_concave, s_axis + hw, zero);
      cut_lo = has_concave & (concave_lo > lo) & (concave_lo < hi);
      cut_hi = has_concave & (concave_hi > lo) & (concave_hi < hi);
    }
    // The cuts in order, hi repeated where a lane has fewer.
    const VD at[4] = {lo, select(cut_lo, concave_lo, select(cut_hi, concave_hi, hi)),
                      select(cut_lo & cut_hi, concave_hi, hi), hi};
    const VM pieces[3] = {splat(0.0) == zero, cut_lo | cut_hi, cut_lo & cut_hi};
    const int n_pieces = bits(pieces[2]) & live ? 3 : bits(pieces[1]) & live ? 2 : 1;
    SampleV s[4];
    for (int i = 0; i <= n_pieces; ++i) {
      VM rho_zero;
      s[i] = sample(f, at[i], &rho_zero);
      // rho = 0 or an exact zero at a cut: the scalar code's special cases.
      const VM used = i == 0 ? pieces[0] : pieces[i - 1];
      fallback = fallback | (used & (rho_zero | (s[i].h == zero)));
    }
    for (int i = 0; i < n_pieces; ++i) fallback = fallback | (pieces[i] & (at[i] == at[i + 1]));
    const unsigned fallback_lanes = bits(fallback) & live;
    for_each_lane(fallback_lanes, [&](int l) { c.fallback[base + l] = true; });

    const VD tol_root = load(&c.tol_root[base]);
    for (int i = 0; i < n_pieces; ++i) {
      const unsigned lanes = bits(pieces[i]) & live & ~fallback_lanes;
      if (lanes == 0) continue;
      const SampleV& a = s[i];
      const SampleV& b = s[i + 1];
      const VD mid = splat(0.5) * (a.s + b.s);
      const VM concave = (mid > concave_lo) & (mid < concave_hi);
      const VD sigma = select(concave, splat(-1.0), splat(1.0));
      const VM pos_a = sigma * a.h > zero, pos_b = sigma * b.h > zero;
      const VM one = pos_a ^ pos_b;
      const unsigned one_lanes = bits(one) & lanes;
      if (one_lanes != 0) {
        SampleV start;
        start.s = select(pos_a, a.s, b.s);
        start.h = select(pos_a, a.h, b.h);
        start.dh = select(pos_a, a.dh, b.dh);
        start.d2h = select(pos_a, a.d2h, b.d2h);
        const VM lo_negative = ~(pos_a ^ concave);  // pos_a == (sigma < 0)
        push_roots(one_lanes, candidate, 2 * i, zero_slot, start, a.s, b.s, lo_negative, tol_root);
      }
      const unsigned pair_lanes =
          bits(~one & pos_a & (sigma * a.dh < zero) & (sigma * b.dh > zero)) & lanes & ~one_lanes;
      if (pair_lanes != 0) push_pairs(pair_lanes, candidate, 2 * i, a, b, sigma);
    }
  }

  void push_pairs(unsigned lanes, const int* candidate, int slot, const SampleV& a, const SampleV& b, VD sigma) {
    const VD a_v[4] = {a.s, a.h, a.dh, a.d2h}, b_v[4] = {b.s, b.h, b.dh, b.d2h};
    PairJobs& q = ws_.pairs;
    for (int k = 0; k < 4; ++k) compress(q.a[k] + q.n, lanes, a_v[k]), compress(q.b[k] + q.n, lanes, b_v[k]);
    compress(q.sigma + q.n, lanes, sigma);
    compress(q.candidate + q.n, lanes, candidate);
    for (int l = 0; l < kWidth; ++l) q.slot[q.n + l] = slot;
    q.n += __builtin_popcount(lanes);
  }

  // Fills the pair jobs up to a whole vector with copies of the first.
  void pad_pairs() {
    PairJobs& q = ws_.pairs;
    for (int j = q.n; j % kWidth != 0; ++j) {
      for (int k = 0; k < 4; ++k) q.a[k][j] = q.a[k][0], q.b[k][j] = q.b[k][0];
      q.sigma[j] = q.sigma[0];
      q.candidate[j] = q.candidate[0];
      q.slot[j] = q.slot[0];
    }
  }

  // Stage 3: RootCollector::two_or_none on kWidth pairs at a time. A pair
  // whose minimum comes within 1e-6 r^2 of zero, or that is not split in 8
  // steps, is a near-tangent pair: its ray goes to the scalar code.
  void pair_searches() {
    PairJobs& q = ws_.pairs;
    const VD zero = splat(0.0);
    const VD near_tangent = splat(1e-6 * (r_ * r_));
    pad_pairs();
    for (int base = 0; base < q.n; base += kWidth) {
      unsigned active = 0;
      const int* candidate = q.candidate + base;
      const int* slot = q.slot + base;
      for (int l = 0; l < kWidth; ++l)
        if (base + l < q.n) active |= 1u << l;
      const FactorV f = factor_of(candidate);
      const VD tol_root = gather(ws_.cand.tol_root, candidate);
      const VD sigma = load(q.sigma + base);
      SampleV a{load(q.a[0] + base), load(q.a[1] + base), load(q.a[2] + base), load(q.a[3] + base), zero};
      SampleV b{load(q.b[0] + base), load(q.b[1] + base), load(q.b[2] + base), load(q.b[3] + base), zero};
      for (int it = 0; it < 8 && active != 0; ++it) {
        const VD ga = sigma * a.h, gb = sigma * b.h, dga = sigma * a.dh, dgb = sigma * b.dh;
        VD x = (((gb - ga) + dga * a.s) - dgb * b.s) / (dga - dgb);
        x = select((x > a.s) & (x < b.s), x, splat(0.5) * (a.s + b.s));
        active &= ~bits(ga + dga * (x - a.s) > zero);  // the lower bound stays positive: none
        if (active == 0) break;
        VM rho_zero;
        const SampleV m = sample(f, x, &rho_zero);
        const VD gm = sigma * m.h;
        const unsigned to_scalar = bits(rho_zero | (abs(gm) < near_tangent)) & active;
        for_each_lane(to_scalar, [&](int l) { ws_.cand.fallback[candidate[l]] = true; });
        active &= ~to_scalar;
        const unsigned split = bits(gm < zero) & active;
        if (2 * __builtin_popcount(split) >= kWidth) {
          search_pair_roots(split, f, candidate, slot, a, m, b, sigma, tol_root);
        } else if (split != 0) {
          push_roots(split, candidate, 0, slot, a, a.s, m.s, sigma < zero, tol_root);
          push_roots(split, candidate, 1, slot, b, m.s, b.s, sigma > zero, tol_root);
        }
        active &= ~split;
        const VD dgm = sigma * m.dh;
        active &= ~bits(dgm == zero);  // the minimum, and it is positive: none
        const VM left = dgm < zero;
        a = {select(left, m.s, a.s), select(left, m.h, a.h), select(left, m.dh, a.dh), select(left, m.d2h, a.d2h),
             zero};
        b = {select(left, b.s, m.s), select(left, b.h, m.h), select(left, b.dh, m.dh), select(left, b.d2h, m.d2h),
             zero};
      }
      for_each_lane(active, [&](int l) { ws_.cand.fallback[candidate[l]] = true; });
    }
  }

  // RootSearch's constructor on every lane: Halley's iteration on (lo, hi)
  // from `start`'s step.
  static SearchV start_search(const SampleV& start, VD lo, VD hi, VM lo_negative, VD tol_root) {
    const VD x = first_guess(start, lo, hi);
    return {lo, hi, x, tol_root * splat(0.5) + splat(2 * kBatchEps) * abs(x), splat(0.0), lo_negative};
  }

  // RootSearch::step on every lane. Returns the lanes whose search ends, and
  // in *to_scalar those where x lies on the axis (the scalar code's case).
  unsigned step(const FactorV& f, SearchV& st, unsigned* to_scalar) const {
    const VD zero = splat(0.0);
    VM rho_zero;
    const SampleV v = sample(f, st.x, &rho_zero);
    const VM root_hit = v.h == zero;
    const VM to_lo = ~((v.h < zero) ^ st.lo_negative);
    const VD lo = select(to_lo, st.x, st.lo);
    const VD hi = select(to_lo, st.hi, st.x);
    const VD step = ((splat(2.0) * v.h) * v.dh) / ((splat(2.0) * v.dh) * v.dh - v.h * v.d2h);
    VD next_x = st.x - step;
    // As the scalar RootSearch::step: Halley's step only where it is
    // close to Newton's, and a step below x's resolution settles x.
    const VM halley = abs(v.h * v.d2h) <= v.dh * v.dh;
    const VM settled = halley & (next_x == st.x);
    const VM inside = halley & (next_x > lo) & (next_x < hi);
    next_x = select(inside, next_x, splat(0.5) * (lo + hi));
    const VD inv_dh = splat(1.0) / v.dh;
    const VD qv = splat(0.5) * (v.d2h * inv_dh);
    const VD cv = abs(qv * qv - (v.d3h * inv_dh) * splat(1.0 / 6));
    const VM converged = inside & ((cv * (step * step)) * abs(step) <= splat(0.25) * st.tol);
    const VD moved = abs(next_x - st.x);
    st.iterations = st.iterations + splat(1.0);
    const VM stays = root_hit | settled;
    const VM done = stays | converged | (moved <= st.tol) | (hi - lo <= st.tol) | (st.iterations == splat(100.0));
    st.lo = select(root_hit, st.lo, lo);
    st.hi = select(root_hit, st.hi, hi);
    st.x = select(stays, st.x, next_x);
    *to_scalar = bits(rho_zero);
    return bits(done | rho_zero);
  }

  // A finished search's answer: its root in its slot, or its ray to the
  // scalar code.
  void finish(int candidate, int slot, double x, bool to_scalar) {
    Candidates& c = ws_.cand;
    if (to_scalar) {
      c.fallback[candidate] = true;
    } else {
      c.roots[candidate][slot] = x;
    }
  }

  // finish() on the lanes `ended` of a vector of searches, whose slots are
  // slot[l] + k. Every lane stores, those without a root to keep to the
  // roots' spare last row: no branch on how many ended.
  void finish_lanes(unsigned ended, unsigned to_scalar, const int* candidate, const int* slot, int k, VD x) {
    Candidates& c = ws_.cand;
    alignas(64) double x_l[kWidth];
    store(x_l, x);
    const unsigned keep = ended & ~to_scalar;
    double* const roots = &c.roots[0][0];
    constexpr int kSpare = (Candidates::kColumn - 1) * kSlots;
    for (int l = 0; l < kWidth; ++l) roots[(keep >> l) & 1 ? candidate[l] * kSlots + slot[l] + k : kSpare] = x_l[l];
    for_each_lane(ended & to_scalar, [&](int l) { c.fallback[candidate[l]] = true; });
  }

  // The two root searches of the pairs split at m, on the lanes `split`,
  // while their factor is at hand: RootCollector::root_pair's two searches
  // side by side for kPairSteps steps, which end most; the rest go to stage 4.
  void search_pair_roots(unsigned split, const FactorV& f, const int* candidate, const int* slot, const SampleV& a,
                         const SampleV& m, const SampleV& b, VD sigma, VD tol_root) {
    constexpr int kPairSteps = 2;
    const VD zero = splat(0.0);
    SearchV st[2] = {start_search(a, a.s, m.s, sigma < zero, tol_root),
                     start_search(b, m.s, b.s, sigma > zero, tol_root)};
    unsigned open[2] = {split, split};
    for (int it = 0; it < kPairSteps; ++it) {
      for (int k = 0; k < 2; ++k) {
        if (open[k] == 0) continue;
        unsigned to_scalar;
        const unsigned ended = step(f, st[k], &to_scalar) & open[k];
        if (ended == 0) continue;
        finish_lanes(ended, to_scalar, candidate, slot, k, st[k].x);
        open[k] &= ~ended;
      }
    }
    for (int k = 0; k < 2; ++k)
      if (open[k] != 0) enqueue(open[k], st[k], candidate, slot, k);
  }

  // Stage 4: the root searches left, kGroups vectors of them at a time (the
  // groups' chains of square roots and divisions overlap), each lane taking
  // the next search as soon as its own ends. (One group where a vector is
  // already two of the instruction set's.)
  void root_searches() {
    constexpr int kGroups = kWidth > 8 ? 1 : 2, kLanes = kGroups * kWidth;
    static_assert(kLanes < 32, "the lanes' mask is an unsigned int");
    constexpr unsigned kAll = (1u << kLanes) - 1;
    const RootJobs& q = ws_.roots;
    const Candidates& c = ws_.cand;
    // Each lane's search and its ray's factor, by column.
    alignas(64) double lo_l[kLanes], hi_l[kLanes], x_l[kLanes], tol_l[kLanes], neg_l[kLanes], it_l[kLanes];
    alignas(64) double oh_l[3][kLanes], ol_l[3][kLanes], d_l[3][kLanes], dd_l[kLanes], kc_l[kLanes];
    int job[kLanes];
    int next = 0;
    unsigned busy = 0;
    const auto take = [&](int l) {
      if (next == q.n) {
        busy &= ~(1u << l);
        return;
      }
      const int j = next++;
      job[l] = j;
      busy |= 1u << l;
      lo_l[l] = q.lo[j], hi_l[l] = q.hi[j], x_l[l] = q.x[j], tol_l[l] = q.tol[j];
      neg_l[l] = q.lo_negative[j], it_l[l] = q.iterations[j];
      const int k = q.candidate[j];
      for (int i = 0; i < 3; ++i) oh_l[i][l] = c.oh[i][k], ol_l[i][l] = c.ol[i][k], d_l[i][l] = c.d[i][k];
      dd_l[l] = c.dd[k];
      kc_l[l] = c.kc[k];
    };
    for (int l = 0; l < kLanes; ++l) take(l);
    if (busy == 0) return;
    // Idle lanes keep a copy of a busy one, so that they compute on real values.
    const auto fill_idle = [&]() {
      const int from = __builtin_ctz(busy);
      for_each_lane(~busy & kAll, [&](int l) {
        lo_l[l] = lo_l[from], hi_l[l] = hi_l[from], x_l[l] = x_l[from], tol_l[l] = tol_l[from];
        neg_l[l] = neg_l[from], it_l[l] = it_l[from];
        for (int i = 0; i < 3; ++i) oh_l[i][l] = oh_l[i][from], ol_l[i][l] = ol_l[i][from], d_l[i][l] = d_l[i][from];
        dd_l[l] = dd_l[from], kc_l[l] = kc_l[from];
      });
    };
    fill_idle();
    const VD zero = splat(0.0);
    while (busy != 0) {
      unsigned finished = 0, to_scalar = 0;
      for (int g = 0; g < kGroups; ++g) {
        const int o = g * kWidth;
        if (((busy >> o) & ((1u << kWidth) - 1)) == 0) continue;
        FactorV f;
        for (int i = 0; i < 3; ++i) f.oh[i] = load(oh_l[i] + o), f.ol[i] = load(ol_l[i] + o), f.d[i] = load(d_l[i] + o);
        f.dd = load(dd_l + o);
        f.kc = load(kc_l + o);
        SearchV st{load(lo_l + o),  load(hi_l + o), load(x_l + o),
                   load(tol_l + o), load(it_l + o), load(neg_l + o) != zero};
        unsigned axis;
        finished |= step(f, st, &axis) << o;
        to_scalar |= axis << o;
        store(lo_l + o, st.lo);
        store(hi_l + o, st.hi);
        store(x_l + o, st.x);
        store(it_l + o, st.iterations);
      }
      finished &= busy;
      if (finished == 0) continue;
      for_each_lane(finished, [&](int l) {
        finish(q.candidate[job[l]], q.slot[job[l]], x_l[l], (to_scalar >> l) & 1);
        take(l);
      });
      if (busy != 0) fill_idle();
    }
  }

  // The chunk's rows: the candidates' roots in slot order (the scalar code's
  // push order), the rest from the scalar code or empty.
  long long write_rows(std::size_t m, const double* origins, const double* directions, int* counts, double* roots) {
    const Candidates& c = ws_.cand;
    long long total = 0;
    // Every row empty first (most are misses), then the others' rows: no
    // branch on whether a ray hit, which no predictor foresees.
    for (std::size_t i = 0; i < m; ++i) {
      counts[i] = 0;
      for (int k = 0; k < 4; ++k) roots[4 * i + k] = kBatchNaN;
    }
    for (int f = 0; f < ws_.n_fallback; ++f) {
      const int i = ws_.fallback_rays[f];
      counts[i] = intersect_torus_row(R_, r_, origins + 3 * i, directions + 3 * i, roots + 4 * i);
      total += counts[i];
    }
    for (int j = 0; j < c.n; ++j) {
      const int i = c.ray[j];
      double* row = roots + 4 * i;
      int n = 0;
      if (c.fallback[j]) {
        n = intersect_torus_row(R_, r_, origins + 3 * i, directions + 3 * i, row);
      } else {
        n = first_roots(c.roots[j], c.t_shift[j], row);
      }
      counts[i] = n;
      total += n;
    }
    return total;
  }

  double R_, r_;
  Workspace ws_;
};

}  // namespace

long long TOROID_BATCH_ENTRY(double major, double minor, std::size_t n, const double* origins, const double* directions,
                             int* counts, double* roots) {
  // The common case is a ring torus (minor < major) of a size the solver
  // takes unscaled; any other torus is the scalar code's throughout.
  const double size = major + minor;
  if (!torus_radii_valid(major, minor) || !(minor < major) || !(size > 0x1p-100 && size < 0x1p100))
    return intersect_torus_batch_on(BatchPath::Scalar, major, minor, n, origins, directions, counts, roots);
  const auto solver = std::make_unique<BatchSolver>(major, minor);
  long long total = 0;
  for (std::size_t base = 0; base < n; base += kChunk) {
    const std::size_t m = n - base < static_cast<std::size_t>(kChunk) ? n - base : kChunk;
    total += solver->chunk(m, origins + 3 * base, directions + 3 * base, counts + base, roots + 4 * base);
  }
  return total;
}

// cube_root_seed on vectors (batch.h: cube_root_seeds_on), for the tests.
void TOROID_BATCH_SEED_ENTRY(std::size_t n, const double* in, double* out) {
  for (std::size_t i = 0; i < n; i += kWidth) {
    alignas(64) double lanes[kWidth];
    for (int l = 0; l < kWidth; ++l) lanes[l] = i + l < n ? in[i + l] : 1.0;
    store(lanes, cube_root_seed(load(lanes)));
    for (int l = 0; l < kWidth && i + l < n; ++l) out[i + l] = lanes[l];
  }
}

}  // namespace toroid
