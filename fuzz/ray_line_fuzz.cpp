// SPDX-License-Identifier: Apache-2.0
// Fuzz target: the `toroid intersect` line format, line by line as the
// command reads it, and the torus intersection of every ray it accepts:
// 0..4 roots, finite, ascending, each on the surface (torus_root_checks.h).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "toroid/io/ray_line.h"
#include "toroid/torus/intersect.h"
#include "torus_root_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view text(reinterpret_cast<const char*>(data), size);
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view{} : text.substr(end + 1);
    toroid::RayLine ray;
    std::string error;
    if (!toroid::parse_ray_line(line, ray, error)) {
      if (error.empty()) std::abort();  // a rejection must say why
      continue;
    }
    for (int i = 0; i < 3; ++i)
      if (!std::isfinite(ray.origin[i]) || !std::isfinite(ray.direction[i])) std::abort();
    double t[4];
    const int n = toroid::intersect_torus(1.0, 0.25, ray.origin, ray.direction, t);
    toroid::fuzz::check_torus_roots(1.0, 0.25, ray.origin, ray.direction, t, n);
    toroid::format_roots(t, n);
  }
  return 0;
}
