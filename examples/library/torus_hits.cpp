// SPDX-License-Identifier: Apache-2.0
// The torus library from C++: every root of a ray, the nearest hit in a
// window, the normal there, and the float entry point an engine with float
// rays would call. Exits 1 when an answer is not the one expected.
#include <toroid/torus/checked.h>
#include <toroid/torus/float_api.h>
#include <toroid/torus/intersect.h>

#include <cmath>
#include <cstdio>

int main() {
  // A ring of major radius 1 and tube radius 0.25 about the z axis; a ray
  // along x through the middle of the tube crosses it four times.
  const double major = 1.0, minor = 0.25;
  const double origin[3] = {-2, 0, 0}, direction[3] = {1, 0, 0};
  const double expected[4] = {0.75, 1.25, 2.75, 3.25};
  int failures = 0;

  double t[4];
  const int count = toroid::intersect_torus(major, minor, origin, direction, t);
  std::printf("roots:");
  for (int i = 0; i < count; ++i) std::printf(" %.17g", t[i]);
  std::printf("\n");
  failures += count != 4;
  for (int i = 0; i < count && i < 4; ++i) failures += std::fabs(t[i] - expected[i]) > 1e-15;

  // The nearest root beyond t = 1: the far wall of the first crossing.
  double nearest = 0;
  failures += !toroid::intersect_torus_nearest(major, minor, origin, direction, 1.0, INFINITY, &nearest);
  failures += std::fabs(nearest - 1.25) > 1e-15;

  // That point is on the inner equator: the unit outward normal points into
  // the hole, along +x.
  const double hit[3] = {origin[0] + nearest * direction[0], 0, 0};
  double normal[3];
  toroid::torus_unit_normal(major, minor, hit, normal);
  std::printf("nearest after t = 1: %.17g, normal (%g, %g, %g)\n", nearest, normal[0], normal[1], normal[2]);
  failures += std::fabs(normal[0] - 1.0) > 1e-15 || normal[1] != 0 || normal[2] != 0;

  // Float rays are answered in double inside.
  const float origin_f[3] = {-2, 0, 0}, direction_f[3] = {1, 0, 0};
  float t_f[4];
  failures += toroid::intersect_torus(1.0f, 0.25f, origin_f, direction_f, t_f) != 4 || t_f[0] != 0.75f;

  // Checked calls report bad input instead of answering it.
  failures += toroid::intersect_torus_checked(-1.0, minor, origin, direction, t) != -1;

  std::printf(failures == 0 ? "ok\n" : "FAILED: %d checks\n", failures);
  return failures == 0 ? 0 : 1;
}
