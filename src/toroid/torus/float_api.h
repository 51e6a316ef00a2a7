// SPDX-License-Identifier: Apache-2.0
// Float entry points, for engines whose rays are float (Embree, GPU-style
// APIs): the inputs convert to double exactly, the double functions of
// intersect.h and surface.h do the work, and the results round to the
// nearest float. So the answers are the double answers, rounded.
#pragma once

#include "toroid/torus/intersect.h"
#include "toroid/torus/surface.h"

namespace toroid {

// intersect_torus's roots, each rounded to float; ascending. A root whose
// float is infinite (beyond FLT_MAX: possible with a tiny direction) is left
// out, so every root returned is finite.
int intersect_torus(float major, float minor, const float origin[3], const float direction[3], float t[4],
                    TorusSolver solver = TorusSolver::Default);

// The open interval (*lo, *hi) of the doubles whose nearest float lies in the
// open interval (t_min, t_max) and is finite. Returns false, leaving *lo and
// *hi unchanged, when there is no such double (t_min >= t_max, NaN, no float
// strictly between them).
bool float_interval_in_double(float t_min, float t_max, double* lo, double* hi);

// The nearest root, as a float, that lies in the open interval (t_min,
// t_max) in float: the double nearest root in float_interval_in_double's
// interval, rounded. A root within half a float ulp of a bound rounds onto
// that bound and does not count (the next root is taken, if it rounds
// inside). Returns false and leaves *t unchanged when there is none.
bool intersect_torus_nearest(float major, float minor, const float origin[3], const float direction[3], float t_min,
                             float t_max, float* t, TorusSolver solver = TorusSolver::Default);

// Whether the float intersect_torus_nearest finds a root: the double
// torus_blocks on the same interval as it searches.
bool torus_blocks(float major, float minor, const float origin[3], const float direction[3], float t_min, float t_max,
                  TorusSolver solver = TorusSolver::Default);

// torus_normal (not normalised), each component rounded to float.
void torus_normal(float major, float minor, const float p[3], float n[3]);

}  // namespace toroid
