// SPDX-License-Identifier: Apache-2.0
// High-precision reference roots for the accuracy harness: the real roots of
// the torus quartic formed EXACTLY from the double inputs, found in MPFR at
// 768 bits. No double-precision solver takes part.
#pragma once

#include <vector>

namespace toroid::accuracy {

struct RayCase {
  double major, minor;
  double origin[3];
  double direction[3];
};

struct ReferenceRoot {
  double t;           // rounded to the nearest double
  long double t_ld;   // spare precision for error measurement near the root
  bool exact_double;  // part of an exact double root (tangent) of the quartic
};

// Real roots, ascending, with multiplicity.
std::vector<ReferenceRoot> reference_roots(const RayCase& c);

// Distance of o + t d from the quartic surface (both factors), in MPFR.
double surface_distance(const RayCase& c, double t);

}  // namespace toroid::accuracy
