// SPDX-License-Identifier: Apache-2.0
#include "toroid/torus/float_api.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace toroid {

namespace {

void to_double(const float in[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = in[i];
}

// An infinite float bound stands for 2^128, the value that rounds to it:
// the midpoint between it and FLT_MAX is then the rounding boundary.
double bound_value(float f) { return std::isinf(f) ? std::copysign(0x1p128, f) : f; }

// Round-to-nearest-even breaks a tie towards the float whose last
// significand bit is 0 (FLT_MAX is odd, so a tie above it goes to infinity).
bool even(float f) { return std::isinf(f) || (std::bit_cast<std::uint32_t>(f) & 1u) == 0; }

}  // namespace

int intersect_torus(float major, float minor, const float origin[3], const float direction[3], float t[4],
                    TorusSolver solver) {
  double o[3], d[3], roots[4];
  to_double(origin, o);
  to_double(direction, d);
  const int n = intersect_torus(static_cast<double>(major), static_cast<double>(minor), o, d, roots, solver);
  int kept = 0;
  for (int i = 0; i < n; ++i) {
    const float f = static_cast<float>(roots[i]);
    if (std::isfinite(f)) t[kept++] = f;
  }
  return kept;
}

bool float_interval_in_double(float t_min, float t_max, double* lo, double* hi) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  if (!(t_min < t_max) || t_min == kInf || t_max == -kInf) return false;
  // The float just above t_min and the one just below t_max (both finite
  // or the infinities' stand-ins). The sum of two neighbouring floats is
  // exact in double, and so is its half.
  const float up = std::nextafter(t_min, kInf), down = std::nextafter(t_max, -kInf);
  if (!(up < t_max)) return false;
  const double lo_mid = 0.5 * (bound_value(t_min) + static_cast<double>(up));
  const double hi_mid = 0.5 * (bound_value(t_max) + static_cast<double>(down));
  // A double exactly at a midpoint rounds to the even neighbour: where that
  // is the inner one, the midpoint belongs inside the open interval.
  *lo = even(up) ? std::nextafter(lo_mid, -std::numeric_limits<double>::infinity()) : lo_mid;
  *hi = even(down) ? std::nextafter(hi_mid, std::numeric_limits<double>::infinity()) : hi_mid;
  return true;
}

bool intersect_torus_nearest(float major, float minor, const float origin[3], const float direction[3], float t_min,
                             float t_max, float* t, TorusSolver solver) {
  double lo, hi, o[3], d[3], found;
  if (!float_interval_in_double(t_min, t_max, &lo, &hi)) return false;
  to_double(origin, o);
  to_double(direction, d);
  if (!intersect_torus_nearest(static_cast<double>(major), static_cast<double>(minor), o, d, lo, hi, &found, solver))
    return false;
  *t = static_cast<float>(found);
  return true;
}

bool torus_blocks(float major, float minor, const float origin[3], const float direction[3], float t_min, float t_max,
                  TorusSolver solver) {
  double lo, hi, o[3], d[3];
  if (!float_interval_in_double(t_min, t_max, &lo, &hi)) return false;
  to_double(origin, o);
  to_double(direction, d);
  return torus_blocks(static_cast<double>(major), static_cast<double>(minor), o, d, lo, hi, solver);
}

void torus_normal(float major, float minor, const float p[3], float n[3]) {
  double q[3], m[3];
  to_double(p, q);
  torus_normal(static_cast<double>(major), static_cast<double>(minor), q, m);
  for (int i = 0; i < 3; ++i) n[i] = static_cast<float>(m[i]);
}

}  // namespace toroid
