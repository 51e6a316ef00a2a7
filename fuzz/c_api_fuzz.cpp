// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the C API (toroid/torus_c.h) on any bits at all, every call.
// Arrays are heap blocks of exactly the documented size, so AddressSanitizer
// reports any read or write past them; each answer must be the documented
// value for bad input and the C++ call's answer, bit for bit, otherwise (the
// batch on every path the CPU has).
//
// Input: a flags byte, a ray count byte, then doubles (little-endian bytes,
// missing ones 0): major, minor, t_min, t_max, a point, then the rays'
// origins and directions.
//   flags bit 0..3: pass NULL for, in turn, the origin, the direction, t
//   (nearest's result) and the normal's point.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include "toroid/torus/batch.h"
#include "toroid/torus/checked.h"
#include "toroid/torus_c.h"

namespace {

// An abort that names the broken promise (libFuzzer reports the input).
[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "c_api_fuzz: %s\n", what);
  std::abort();
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

template <typename T>
std::unique_ptr<T[]> block(std::size_t n, const T& fill) {
  auto p = std::make_unique<T[]>(n);
  std::fill(p.get(), p.get() + n, fill);
  return p;
}

constexpr double kSentinel = 12345.678;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const unsigned flags = data[0];
  const std::size_t rays = data[1] % 9;
  std::vector<double> x(9 + 6 * rays, 0.0);
  std::memcpy(x.data(), data + 2, std::min(x.size() * sizeof(double), size - 2));
  const double major = x[0], minor = x[1], t_min = x[2], t_max = x[3];
  const bool radii_ok = std::isfinite(major) && std::isfinite(minor) && major > 0 && minor > 0;
  if (radii_ok != toroid::torus_radii_valid(major, minor)) fail("torus_radii_valid disagrees with its definition");

  // One ray: the first of the batch's (or zeros), through exactly-sized blocks.
  auto origin = block<double>(3, 0), direction = block<double>(3, 0);
  if (rays > 0) {
    std::copy(x.begin() + 9, x.begin() + 12, origin.get());
    std::copy(x.begin() + 12, x.begin() + 15, direction.get());
  }
  const double* o = (flags & 1) ? nullptr : origin.get();
  const double* d = (flags & 2) ? nullptr : direction.get();

  auto t = block<double>(4, kSentinel);
  const int count = toroid_torus_intersect(major, minor, o, d, t.get());
  double expected[4] = {kSentinel, kSentinel, kSentinel, kSentinel};
  if (!o || !d) {
    if (count != -1) fail("intersect: a NULL array must give -1");
  } else {
    const int want = toroid::intersect_torus_checked(major, minor, o, d, expected);
    if (count != want) fail("intersect: the count differs from the C++ call's");
    if (!radii_ok && count != -1) fail("intersect: invalid radii must give -1");
    if (radii_ok && !toroid::torus_ray_valid(o, d) && count != 0) fail("intersect: an invalid ray must give 0");
    if (count < -1 || count > 4) fail("intersect: count outside -1..4");
    for (int i = 0; i < 4; ++i) {
      if (!same_bits(t[i], expected[i])) fail("intersect: a root differs from the C++ call's (or a slot was written)");
      if (i >= count && !same_bits(t[i], kSentinel)) fail("intersect: wrote past the count");
      if (i < count && (!std::isfinite(t[i]) || (i > 0 && t[i] < t[i - 1])))
        fail("intersect: a root not finite or not ascending");
    }
  }

  auto nearest = block<double>(1, kSentinel);
  double* nearest_out = (flags & 4) ? nullptr : nearest.get();
  const int hit = toroid_torus_nearest(major, minor, o, d, t_min, t_max, nearest_out);
  if (!o || !d || !nearest_out) {
    if (hit != -1) fail("nearest: a NULL pointer must give -1");
  } else {
    double want_t = kSentinel;
    const int want = toroid::intersect_torus_nearest_checked(major, minor, o, d, t_min, t_max, &want_t);
    if (hit != want || !same_bits(*nearest_out, want_t)) fail("nearest: differs from the C++ call");
    if (hit == 1 && !(*nearest_out > t_min && *nearest_out < t_max)) fail("nearest: a root outside (t_min, t_max)");
    if (hit != 1 && !same_bits(*nearest_out, kSentinel)) fail("nearest: wrote *t without a hit");
  }

  auto point = block<double>(3, 0);
  std::copy(x.begin() + 4, x.begin() + 7, point.get());
  auto normal = block<double>(3, kSentinel);
  toroid_torus_normal(major, minor, (flags & 8) ? nullptr : point.get(), normal.get());
  const double length = std::hypot(normal[0], normal[1], normal[2]);
  const bool all_nan = std::isnan(normal[0]) && std::isnan(normal[1]) && std::isnan(normal[2]);
  if (!all_nan && !(std::abs(length - 1) < 1e-15)) fail("normal: neither unit length nor all NaN");
  if ((!radii_ok || (flags & 8)) && !all_nan) fail("normal: bad input must give NaN");
  toroid_torus_normal(major, minor, point.get(), nullptr);  // does nothing

  // The batch, rays by the exact-size blocks; every row is the single call's.
  auto origins = block<double>(3 * rays, 0), directions = block<double>(3 * rays, 0);
  for (std::size_t i = 0; i < rays; ++i) {
    std::copy(x.begin() + 9 + 6 * i, x.begin() + 12 + 6 * i, origins.get() + 3 * i);
    std::copy(x.begin() + 12 + 6 * i, x.begin() + 15 + 6 * i, directions.get() + 3 * i);
  }
  // Through the C API (the widest path), then on every other path this CPU has.
  const toroid::BatchPath paths[] = {toroid::BatchPath::Scalar, toroid::BatchPath::Avx2, toroid::BatchPath::Avx512};
  for (int p = -1; p < 3; ++p) {
    if (p >= 0 && !toroid::batch_path_available(paths[p])) continue;
    auto counts = block<int>(rays, 99);
    auto roots = block<double>(4 * rays, kSentinel);
    if (p < 0)
      toroid_torus_intersect_batch(major, minor, rays, origins.get(), directions.get(), counts.get(), roots.get());
    else
      toroid::intersect_torus_batch_on(paths[p], major, minor, rays, origins.get(), directions.get(), counts.get(),
                                       roots.get());
    for (std::size_t i = 0; i < rays; ++i) {
      double row[4] = {NAN, NAN, NAN, NAN};
      const int want =
          toroid::intersect_torus_checked(major, minor, origins.get() + 3 * i, directions.get() + 3 * i, row);
      if (counts[i] != want) fail("batch: a count differs from the single call's");
      for (int k = 0; k < 4; ++k) {
        const double got = roots[4 * i + k];
        if (k < want ? !same_bits(got, row[k]) : !std::isnan(got)) fail("batch: a root differs or a slot is not NaN");
      }
    }
  }
  return 0;
}
