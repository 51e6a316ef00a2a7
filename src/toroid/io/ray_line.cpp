// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/ray_line.h"

#include <cstdio>

#include "toroid/io/number_text.h"

namespace toroid {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

}  // namespace

bool parse_ray_line(std::string_view line, RayLine& out, std::string& error) {
  double v[6];
  size_t pos = 0;
  int count = 0;
  while (true) {
    while (pos < line.size() && is_space(line[pos])) ++pos;
    if (pos == line.size()) break;
    size_t end = pos;
    while (end < line.size() && !is_space(line[end])) ++end;
    const std::string_view token = line.substr(pos, end - pos);
    if (count == 6) {
      error = "expected 6 numbers (ox oy oz dx dy dz), found more: '" + std::string(token) + "'";
      return false;
    }
    double x = 0;
    if (const NumberText r = read_finite_double(token, x); r != NumberText::Ok) {
      error = describe(r, token);
      return false;
    }
    v[count++] = x;
    pos = end;
  }
  if (count < 6) {
    error = "expected 6 numbers (ox oy oz dx dy dz), found " + std::to_string(count);
    return false;
  }
  if (v[3] == 0 && v[4] == 0 && v[5] == 0) {
    error = "the direction is the zero vector";
    return false;
  }
  for (int i = 0; i < 3; ++i) {
    out.origin[i] = v[i];
    out.direction[i] = v[3 + i];
  }
  return true;
}

std::string format_roots(const double* t, int n) {
  std::string s = std::to_string(n);
  char buf[32];
  for (int i = 0; i < n; ++i) {
    // %.17g round-trips every double.
    std::snprintf(buf, sizeof buf, " %.17g", t[i]);
    s += buf;
  }
  return s;
}

}  // namespace toroid
