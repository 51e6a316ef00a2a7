// SPDX-License-Identifier: Apache-2.0
// How the torus's roots are found, chosen by name (CLI --solver, YAML
// `solver:`, API). The default is toroid's own robust solver; the closed
// forms are there to compare against (docs/torus.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace toroid {

enum class TorusSolver : std::uint8_t {
  Default,   // robust: the exact distance function, cut into monotone pieces (torus/intersect.cpp)
  Ferrari,   // the seed paper's quartic, by textbook Ferrari with the dominant root of the resolvent cubic
  Tianheng,  // the seed paper's quartic, by its closed form with the full case table
};

std::string_view solver_name(TorusSolver s);
std::optional<TorusSolver> solver_from_name(std::string_view name);

}  // namespace toroid
