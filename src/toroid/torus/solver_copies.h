// SPDX-License-Identifier: Apache-2.0
// The scalar solver's copy for x86-64 processors with AVX2, FMA, BMI1 and
// BMI2 (torus/intersect_x86_64_v3.cpp): intersect.cpp compiled a second time
// for those instructions, in a namespace of its own, and chosen at run time
// by the public calls of intersect.h for the default solver (the closed
// forms run the baseline build).
// Without contraction of a * b + c into fused multiply-adds, every operation
// rounds as in the baseline build, so the copy's answers are the same bits;
// it is faster because its double-double products use the FMA instruction
// and AVX's three-operand forms save moves. Internal: not installed.
#pragma once

#include <cstdint>

namespace toroid {

enum class TorusSolver : std::uint8_t;

namespace x86_64_v3 {

// Whether this build has the copy and this processor runs it.
bool available();
// Tests only: whether the public calls take the copy (where available) or
// the baseline code, to compare the two.
void set_enabled_for_testing(bool enabled);
bool enabled();

// The copy's intersect_torus, intersect_torus_nearest and torus_blocks.
int intersect_torus(double major, double minor, const double origin[3], const double direction[3], double t[4],
                    TorusSolver solver);
bool intersect_torus_nearest(double major, double minor, const double origin[3], const double direction[3],
                             double t_min, double t_max, double* t, TorusSolver solver);
bool torus_blocks(double major, double minor, const double origin[3], const double direction[3], double t_min,
                  double t_max, TorusSolver solver);

}  // namespace x86_64_v3
}  // namespace toroid
