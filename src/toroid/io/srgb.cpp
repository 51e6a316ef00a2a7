// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/srgb.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace toroid {
namespace {

// The sRGB formula, rounded to a code. Used once per code boundary below.
int encode_by_formula(double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
  return static_cast<int>(std::lround(s * 255.0));
}

// boundary[k]: the least double c with encode_by_formula(c) > k, found by
// bisection on the doubles; encoding is then a count of boundaries <= c.
std::array<double, 255> make_boundaries() {
  std::array<double, 255> b{};
  for (int k = 0; k < 255; ++k) {
    double lo = 0, hi = 1;  // encode(lo) <= k < encode(hi)
    while (true) {
      const double mid = lo + (hi - lo) / 2;
      if (mid == lo || mid == hi) break;
      (encode_by_formula(mid) > k ? hi : lo) = mid;
    }
    b[k] = hi;
  }
  return b;
}

std::array<double, 256> make_decoding() {
  std::array<double, 256> t{};
  for (int i = 0; i < 256; ++i) {
    const double s = i / 255.0;
    t[i] = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
  }
  return t;
}

// The code at the start of each of 4096 equal buckets of [0, 1]; the sRGB
// curve rises by less than one code per bucket, so a step or two along the
// boundaries finishes the job.
constexpr int kBuckets = 4096;

struct Encoding {
  std::array<double, 256> boundary;  // boundary[255] = +inf, a sentinel
  std::array<unsigned char, kBuckets> code_at_bucket;
};

Encoding make_encoding() {
  Encoding e{};
  const std::array<double, 255> b = make_boundaries();
  std::copy(b.begin(), b.end(), e.boundary.begin());
  e.boundary[255] = INFINITY;
  for (int i = 0; i < kBuckets; ++i) {
    const double start = static_cast<double>(i) / kBuckets;
    e.code_at_bucket[i] = static_cast<unsigned char>(std::upper_bound(b.begin(), b.end(), start) - b.begin());
  }
  return e;
}

const Encoding& encoding() {
  static const Encoding e = make_encoding();
  return e;
}

inline unsigned char encode(const Encoding& e, double c) {
  if (!(c > 0)) return 0;  // also NaN
  if (c >= 1) return 255;
  int code = e.code_at_bucket[static_cast<int>(c * kBuckets)];
  while (c >= e.boundary[code]) ++code;
  return static_cast<unsigned char>(code);
}

}  // namespace

unsigned char linear_to_srgb8(double c) { return encode(encoding(), c); }

void linear_to_srgb8(const double* linear, int n, unsigned char* codes) {
  const Encoding& e = encoding();
  for (int i = 0; i < n; ++i) codes[i] = encode(e, linear[i]);
}

double srgb8_to_linear(unsigned char code) {
  static const std::array<double, 256> table = make_decoding();
  return table[code];
}

}  // namespace toroid
