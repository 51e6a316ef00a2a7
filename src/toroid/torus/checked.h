// SPDX-License-Identifier: Apache-2.0
// The torus queries with their inputs checked, and the batch call: what the
// C API (toroid/torus_c.h) promises, in C++. The functions of intersect.h
// and surface.h assume valid radii and a ray with a direction; these give
// every input an answer instead:
//   - radii that are not finite and > 0: -1 (the batch: every count -1);
//   - a ray with a non-finite component (NaN or infinite, origin or
//     direction) or a zero direction: no roots;
//   - otherwise exactly what intersect_torus / intersect_torus_nearest answer
//     with the default solver.
#pragma once

#include <cstddef>

#include "toroid/math/device.h"

namespace toroid {

// major and minor finite and > 0.
TOROID_HD bool torus_radii_valid(double major, double minor);

// Every component of origin and direction finite, and direction not zero.
TOROID_HD bool torus_ray_valid(const double origin[3], const double direction[3]);

// -1 for invalid radii, 0 for an invalid ray, else intersect_torus's count
// and roots (ascending). t is written only where a count > 0 says so.
TOROID_HD int intersect_torus_checked(double major, double minor, const double origin[3], const double direction[3],
                                      double t[4]);

// -1 for invalid radii; 0 for an invalid ray, a NaN bound, or no root in
// (t_min, t_max); 1 and *t, the nearest root in the interval, otherwise.
// *t is written only when 1 is returned.
TOROID_HD int intersect_torus_nearest_checked(double major, double minor, const double origin[3],
                                              const double direction[3], double t_min, double t_max, double* t);

// torus_normal scaled to unit length. The scaling first divides by a power of
// two near the largest component, which is exact, so that no square
// overflows or underflows: where the plain n / sqrt(n . n) does neither, the
// result is the same bits. NaN in every component for invalid radii, a
// non-finite point, or a point where the normal is zero (the centre circle,
// not on the surface).
TOROID_HD void torus_unit_normal(double major, double minor, const double p[3], double n[3]);

// One row of intersect_torus_batch: intersect_torus_checked's count,
// returned, and its roots in row[0..3], the slots beyond the count set to
// NaN. The CPU batch (for the rays its SIMD paths leave to the scalar code)
// and the CUDA kernel (cuda/) call it per ray.
TOROID_HD int intersect_torus_row(double major, double minor, const double origin[3], const double direction[3],
                                  double row[4]);

// intersect_torus_checked on each of n rays: ray i is origins[3i..3i+2],
// directions[3i..3i+2]; its count goes to counts[i] and its roots to
// roots[4i..4i+3], the slots beyond its count set to NaN (so are all four of a
// ray with count -1 or 0). Every row is the single-ray call's answer, bit for
// bit. It runs 8 or 16 rays at a time where the CPU allows (batch.h), one
// at a time elsewhere, with the same answers. Returns -1 for invalid radii, else the number of roots of
// all the rays together (a long long: 4 n overflows an int for n > 2^29). n == 0 touches no array.
long long intersect_torus_batch(double major, double minor, std::size_t n, const double* origins,
                                const double* directions, int* counts, double* roots);

}  // namespace toroid
