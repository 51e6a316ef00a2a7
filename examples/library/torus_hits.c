/* SPDX-License-Identifier: Apache-2.0 */
/* The torus library from C99: every function of <toroid/torus_c.h>.
 * Exits 1 when an answer is not the one expected. */
#include <math.h>
#include <stdio.h>
#include <toroid/torus_c.h>

static int near(double a, double b) { return fabs(a - b) <= 1e-15; }

int main(void) {
  const double major = 1.0, minor = 0.25;
  const double origin[3] = {-2, 0, 0}, direction[3] = {1, 0, 0};
  int failures = 0;
  int i;

  /* All roots of one ray. */
  double t[4];
  int count = toroid_torus_intersect(major, minor, origin, direction, t);
  printf("roots:");
  for (i = 0; i < count; ++i) printf(" %.17g", t[i]);
  printf("\n");
  failures += count != 4 || !near(t[0], 0.75) || !near(t[1], 1.25) || !near(t[2], 2.75) || !near(t[3], 3.25);

  /* The nearest root in (1, inf), and the unit normal there. */
  double nearest = 0, normal[3];
  failures += toroid_torus_nearest(major, minor, origin, direction, 1.0, INFINITY, &nearest) != 1;
  failures += !near(nearest, 1.25);
  {
    const double hit[3] = {-0.75, 0, 0};
    toroid_torus_normal(major, minor, hit, normal);
  }
  printf("nearest after t = 1: %.17g, normal (%g, %g, %g)\n", nearest, normal[0], normal[1], normal[2]);
  failures += !near(normal[0], 1.0) || normal[1] != 0 || normal[2] != 0;

  /* A batch: the ray above, one that misses, one with a zero direction. */
  {
    const double origins[9] = {-2, 0, 0, -2, 0, 1, 0, 0, 0};
    const double directions[9] = {1, 0, 0, 1, 0, 0, 0, 0, 0};
    int counts[3];
    double roots[12];
    toroid_torus_intersect_batch(major, minor, 3, origins, directions, counts, roots);
    printf("batch counts: %d %d %d\n", counts[0], counts[1], counts[2]);
    failures += counts[0] != 4 || counts[1] != 0 || counts[2] != 0 || !near(roots[3], 3.25) || !isnan(roots[4]);
  }

  /* Bad radii: -1 from the counting calls, NaN from the normal. */
  failures += toroid_torus_intersect(0.0, minor, origin, direction, t) != -1;
  failures += toroid_torus_nearest(major, NAN, origin, direction, 0, INFINITY, &nearest) != -1;
  toroid_torus_normal(-1.0, minor, origin, normal);
  failures += !isnan(normal[0]);

  printf(failures == 0 ? "ok\n" : "FAILED: %d checks\n", failures);
  return failures == 0 ? 0 : 1;
}
