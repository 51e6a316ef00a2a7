// SPDX-License-Identifier: Apache-2.0
// The largest image toroid renders, checked before the canvas is allocated
// (a canvas holds three doubles a pixel: the pixel limit is 1.5 GiB).
#pragma once

#include <cstdint>
#include <string>

namespace toroid {

inline constexpr int kMaxImageSide = 16384;
inline constexpr std::int64_t kMaxImagePixels = std::int64_t{8192} * 8192;

// Empty when width x height can be rendered, else what is wrong, e.g.
// "width must be in 1..16384, got 0".
std::string image_size_error(std::int64_t width, std::int64_t height);

}  // namespace toroid
