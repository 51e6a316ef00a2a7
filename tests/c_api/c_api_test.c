/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The C API from C99: every function of toroid/torus_c.h against known
 * answers. Exits 0 when all pass, 1 (after listing each failure) otherwise.
 */
#include <math.h>
#include <stdio.h>

#include "toroid/torus_c.h"

static int failures = 0;

static void check(int ok, const char* what, int line) {
  if (!ok) {
    fprintf(stderr, "c_api_test.c:%d: failed: %s\n", line, what);
    ++failures;
  }
}
#define CHECK(cond) check((cond) ? 1 : 0, #cond, __LINE__)

static void test_intersect(void) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0}, zero[3] = {0, 0, 0};
  double nan_dir[3], inf_origin[3], t[4] = {0, 0, 0, 0};
  nan_dir[0] = NAN, nan_dir[1] = 0, nan_dir[2] = 0;
  inf_origin[0] = -INFINITY, inf_origin[1] = 0, inf_origin[2] = 0;
  CHECK(toroid_torus_intersect(1, 0.25, o, d, t) == 4);
  CHECK(t[0] == 3.75 && t[1] == 4.25 && t[2] == 5.75 && t[3] == 6.25);
  CHECK(toroid_torus_intersect(0, 0.25, o, d, t) == -1);
  CHECK(toroid_torus_intersect(1, -0.25, o, d, t) == -1);
  CHECK(toroid_torus_intersect(NAN, 0.25, o, d, t) == -1);
  CHECK(toroid_torus_intersect(1, INFINITY, o, d, t) == -1);
  CHECK(toroid_torus_intersect(1, 0.25, o, nan_dir, t) == 0);
  CHECK(toroid_torus_intersect(1, 0.25, o, zero, t) == 0);
  CHECK(toroid_torus_intersect(1, 0.25, inf_origin, d, t) == 0);
  CHECK(toroid_torus_intersect(1, 0.25, NULL, d, t) == -1);
}

static void test_nearest(void) {
  const double o[3] = {-5, 0, 0}, d[3] = {1, 0, 0}, miss[3] = {-5, 5, 0};
  double t = -1;
  CHECK(toroid_torus_nearest(1, 0.25, o, d, 0, INFINITY, &t) == 1 && t == 3.75);
  CHECK(toroid_torus_nearest(1, 0.25, o, d, 3.75, INFINITY, &t) == 1 && t == 4.25);
  CHECK(toroid_torus_nearest(1, 0.25, o, d, 5, 6, &t) == 1 && t == 5.75);
  t = -1;
  CHECK(toroid_torus_nearest(1, 0.25, o, d, 6.25, INFINITY, &t) == 0 && t == -1);
  CHECK(toroid_torus_nearest(1, 0.25, miss, d, -INFINITY, INFINITY, &t) == 0 && t == -1);
  CHECK(toroid_torus_nearest(1, 0.25, o, d, NAN, INFINITY, &t) == 0 && t == -1);
  CHECK(toroid_torus_nearest(1, 0.25, o, d, 0, NAN, &t) == 0 && t == -1);
  CHECK(toroid_torus_nearest(-1, 0.25, o, d, 0, INFINITY, &t) == -1 && t == -1);
}

static void test_normal(void) {
  const double p[3] = {1.25, 0, 0}, top[3] = {0, 1, 0.25}, centre[3] = {1, 0, 0};
  double n[3];
  toroid_torus_normal(1, 0.25, p, n);
  CHECK(n[0] == 1 && n[1] == 0 && n[2] == 0);
  toroid_torus_normal(1, 0.25, top, n);
  CHECK(n[0] == 0 && n[1] == 0 && n[2] == 1);
  toroid_torus_normal(0, 0.25, p, n);
  CHECK(isnan(n[0]) && isnan(n[1]) && isnan(n[2]));
  toroid_torus_normal(1, 0.25, centre, n);
  CHECK(isnan(n[0]) && isnan(n[1]) && isnan(n[2]));
}

static void test_batch(void) {
  /* hit through the hole, miss, NaN direction, zero direction */
  const double origins[12] = {-5, 0, 0, -5, 5, 0, -5, 0, 0, -5, 0, 0};
  const double directions[12] = {1, 0, 0, 1, 0, 0, NAN, 0, 0, 0, 0, 0};
  int counts[4] = {7, 7, 7, 7}, i;
  double roots[16];
  for (i = 0; i < 16; ++i) roots[i] = 7;
  toroid_torus_intersect_batch(1, 0.25, 4, origins, directions, counts, roots);
  CHECK(counts[0] == 4 && counts[1] == 0 && counts[2] == 0 && counts[3] == 0);
  CHECK(roots[0] == 3.75 && roots[1] == 4.25 && roots[2] == 5.75 && roots[3] == 6.25);
  for (i = 4; i < 16; ++i) CHECK(isnan(roots[i]));
  toroid_torus_intersect_batch(-1, 0.25, 4, origins, directions, counts, roots);
  CHECK(counts[0] == -1 && counts[1] == -1 && counts[2] == -1 && counts[3] == -1);
  for (i = 0; i < 16; ++i) CHECK(isnan(roots[i]));
  toroid_torus_intersect_batch(1, 0.25, 0, NULL, NULL, NULL, NULL);
}

int main(void) {
  test_intersect();
  test_nearest();
  test_normal();
  test_batch();
  if (failures != 0) {
    fprintf(stderr, "%d C API check(s) failed\n", failures);
    return 1;
  }
  printf("C API: all checks passed\n");
  return 0;
}
