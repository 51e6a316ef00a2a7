#include "toroid/io/ray_line.h"

#include <charconv>
#include <cmath>
#include <cstdio>

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
    // from_chars rejects a leading '+'; accept it as people write it.
    const std::string_view num = token.size() > 1 && token[0] == '+' ? token.substr(1) : token;
    const auto [ptr, ec] = std::from_chars(num.data(), num.data() + num.size(), x);
    if (ec == std::errc::result_out_of_range) {
      error = "number out of range: '" + std::string(token) + "'";
      return false;
    }
    if (ec != std::errc() || ptr != num.data() + num.size()) {
      error = "not a number: '" + std::string(token) + "'";
      return false;
    }
    if (!std::isfinite(x)) {
      error = "not a finite number: '" + std::string(token) + "'";
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
