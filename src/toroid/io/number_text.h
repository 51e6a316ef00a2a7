// SPDX-License-Identifier: Apache-2.0
// Reading one number from a word of text (OBJ records, `toroid intersect`
// lines), with the reason when it is not a usable one.
#pragma once

#include <string>
#include <string_view>

namespace toroid {

enum class NumberText { Ok, NotANumber, OutOfRange, NotFinite };

// The whole of `token` as a finite double ("1", "-2.5e3", "+4"; a leading
// '+' is accepted, as people write it).
NumberText read_finite_double(std::string_view token, double& value);

// "not a number: 'x'", "number out of range: '1e999'" or "not a finite
// number: 'nan'"; empty for Ok.
std::string describe(NumberText result, std::string_view token);

}  // namespace toroid
