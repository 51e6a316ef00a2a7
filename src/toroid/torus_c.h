/* SPDX-License-Identifier: Apache-2.0 */
/*
 * The ray-torus intersection of toroid, for C (C99 and later) and for any
 * language that calls C. Link the toroid_torus library (a C++ library:
 * link with the C++ compiler, or add its runtime, e.g. -lstdc++ -lm).
 *
 * The torus is in object space, ring in the xy-plane, axis z, centred at the
 * origin: (sqrt(x^2 + y^2) - major)^2 + z^2 = minor^2. The ray is
 * origin + t direction; the direction need not be of unit length, and t is
 * measured in its units. Any major > 0 and minor > 0 is allowed (minor >=
 * major: horn and spindle tori). The answers are those of the C++ library
 * (toroid/torus/intersect.h, default solver), bit for bit.
 *
 * Inputs, for every function:
 *  - Radii that are not finite and > 0 (<= 0, NaN, infinite): the counting
 *    calls return -1; toroid_torus_normal writes NaN.
 *  - A ray with any NaN or infinite component (origin or direction), or a
 *    zero direction: no roots (0).
 *  - Pointers: the arrays must hold the sizes given below. A NULL pointer is
 *    not an error to crash on: a counting call given one returns -1 and
 *    writes nothing; toroid_torus_normal with a NULL point writes NaN (and
 *    with a NULL normal does nothing); the batch with n == 0 reads and writes
 *    nothing, so NULL arrays are fine there.
 * Nothing is written beyond the sizes given, and nothing is read beyond them.
 */
#ifndef TOROID_TORUS_C_H
#define TOROID_TORUS_C_H

#include <stddef.h>

#ifdef __cplusplus
#define TOROID_C_NOEXCEPT noexcept
extern "C" {
#else
#define TOROID_C_NOEXCEPT
#endif

/*
 * Every real root t (negative ones too), ascending, with multiplicity where
 * the ray is tangent: returns the count, 0 to 4, written to t[0..count-1].
 * -1 for invalid radii. t[count..3] are left as they were.
 */
int toroid_torus_intersect(double major, double minor, const double origin[3], const double direction[3],
                           double t[4]) TOROID_C_NOEXCEPT;

/*
 * The nearest root in the open interval (t_min, t_max): returns 1 and writes
 * it to *t; returns 0 when there is none (also for a NaN bound or an
 * invalid ray) and -1 for invalid radii, leaving *t unchanged in both
 * cases. t_min may be -INFINITY and t_max INFINITY.
 */
int toroid_torus_nearest(double major, double minor, const double origin[3], const double direction[3], double t_min,
                         double t_max, double* t) TOROID_C_NOEXCEPT;

/*
 * The unit outward normal at a point on the surface (object space): the
 * direction from the nearest point of the centre circle to the point (on a
 * spindle's inner sheet, from the point across the axis); on the axis of a
 * horn or spindle torus, +z or -z. The same formula serves points off the
 * surface. NaN in all three components for invalid radii, a NULL or
 * non-finite point, or a point on the centre circle (where there is no
 * normal).
 */
void toroid_torus_normal(double major, double minor, const double point[3], double normal[3]) TOROID_C_NOEXCEPT;

/*
 * toroid_torus_intersect on n rays: ray i is origins[3i..3i+2] +
 * t directions[3i..3i+2]; its count goes to counts[i] and its roots to
 * roots[4i..4i+3]. The slots of a row beyond its count are set to NaN (all
 * four for a count of 0 or -1). Arrays: origins and directions n*3 doubles,
 * counts n ints, roots n*4 doubles. Invalid radii: every count -1. With n > 0
 * and a NULL array, nothing is read; every count is -1 and every root NaN in
 * the arrays that are not NULL. Where the CPU has AVX-512 or AVX2 (x86-64,
 * chosen at run time) it solves 16 or 8 rays at a time, with the same answers.
 */
void toroid_torus_intersect_batch(double major, double minor, size_t n, const double* origins, const double* directions,
                                  int* counts, double* roots) TOROID_C_NOEXCEPT;

#ifdef __cplusplus
}
#endif

#endif /* TOROID_TORUS_C_H */
