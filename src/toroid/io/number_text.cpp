// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/number_text.h"

#include <charconv>
#include <cmath>

namespace toroid {

NumberText read_finite_double(std::string_view token, double& value) {
  // from_chars rejects a leading '+'.
  const std::string_view num = token.size() > 1 && token[0] == '+' ? token.substr(1) : token;
  const char* end = num.data() + num.size();
  const auto [ptr, ec] = std::from_chars(num.data(), end, value);
  if (ec == std::errc::result_out_of_range) return NumberText::OutOfRange;
  if (ec != std::errc() || ptr != end || num.empty()) return NumberText::NotANumber;
  if (!std::isfinite(value)) return NumberText::NotFinite;
  return NumberText::Ok;
}

std::string describe(NumberText result, std::string_view token) {
  std::string quoted = "'";  // appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on that
  quoted += token;
  quoted += '\'';
  switch (result) {
    case NumberText::Ok: return {};
    case NumberText::NotANumber: return "not a number: " + quoted;
    case NumberText::OutOfRange: return "number out of range: " + quoted;
    case NumberText::NotFinite: return "not a finite number: " + quoted;
  }
  return {};
}

}  // namespace toroid
