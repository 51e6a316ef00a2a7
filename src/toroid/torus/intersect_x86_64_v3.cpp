// SPDX-License-Identifier: Apache-2.0
// The default solver compiled for AVX2, FMA, BMI1 and BMI2 (solver_copies.h).
// CMakeLists.txt gives this file those -m flags and -ffp-contract=off; the
// sources are included with the namespace renamed, as cuda/torus_kernel.cuh
// does, so that none of their functions, the inline ones of the headers
// included, shares a symbol with the baseline build: the linker can never
// hand a baseline caller a function built for these instructions.
#if TOROID_SOLVER_AVX2_COPY

// The standard headers the sources include, first, so that the rename below
// leaves them alone.
#include <algorithm>
#include <bit>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <utility>

// Before the rename: the copy's calls are declared in namespace toroid, and
// so are the closed forms. The public calls take the copy for the default
// solver only (built for these instructions the closed forms ran slower,
// CHANGELOG 2026-12-07), so its closed-form branch, never taken, calls the
// baseline's.
#include "toroid/roots/polynomial.h"
#include "toroid/torus/solver_copies.h"

namespace toroid_x86_64_v3 {
inline int solve_quartic_ferrari(double a, double b, double c, double d, double e, double roots[4]) {
  return toroid::solve_quartic_ferrari(a, b, c, d, e, roots);
}
inline int solve_quartic_tianheng(double a, double b, double c, double d, double e, double roots[4]) {
  return toroid::solve_quartic_tianheng(a, b, c, d, e, roots);
}
}  // namespace toroid_x86_64_v3

#define toroid toroid_x86_64_v3
#define TOROID_SOLVER_COPY
#include "toroid/torus/intersect.cpp"
#undef TOROID_SOLVER_COPY
#undef toroid

namespace toroid::x86_64_v3 {

namespace {
toroid_x86_64_v3::TorusSolver renamed(TorusSolver solver) {
  return static_cast<toroid_x86_64_v3::TorusSolver>(static_cast<std::uint8_t>(solver));
}
}  // namespace

int intersect_torus(double major, double minor, const double origin[3], const double direction[3], double t[4],
                    TorusSolver solver) {
  return toroid_x86_64_v3::intersect_torus(major, minor, origin, direction, t, renamed(solver));
}

bool intersect_torus_nearest(double major, double minor, const double origin[3], const double direction[3],
                             double t_min, double t_max, double* t, TorusSolver solver) {
  return toroid_x86_64_v3::intersect_torus_nearest(major, minor, origin, direction, t_min, t_max, t, renamed(solver));
}

bool torus_blocks(double major, double minor, const double origin[3], const double direction[3], double t_min,
                  double t_max, TorusSolver solver) {
  return toroid_x86_64_v3::torus_blocks(major, minor, origin, direction, t_min, t_max, renamed(solver));
}

}  // namespace toroid::x86_64_v3

#endif
