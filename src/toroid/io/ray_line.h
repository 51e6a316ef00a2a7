// SPDX-License-Identifier: Apache-2.0
// The text format of `toroid intersect`: one ray per line, "ox oy oz dx dy dz".
#pragma once

#include <string>
#include <string_view>

namespace toroid {

struct RayLine {
  double origin[3];
  double direction[3];
};

// Parses one line. On failure returns false and sets `error` to a message
// without the "line N:" prefix (the caller knows N).
bool parse_ray_line(std::string_view line, RayLine& out, std::string& error);

// "k t1 ... tk", each t printed so that it reads back as the same double.
std::string format_roots(const double* t, int n);

}  // namespace toroid
