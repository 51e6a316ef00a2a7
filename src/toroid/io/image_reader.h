// SPDX-License-Identifier: Apache-2.0
// Reading images into canvases (texture maps): the book's PPM (plain P3 and
// raw P6) and PNG (libpng).
//
// Colours: a canvas holds linear colours. PPM samples are read as the book's
// canvas_from_ppm specifies, value / maxval with no gamma, the inverse of
// canvas_to_ppm (which writes no gamma either). PNG samples are decoded from
// 8-bit sRGB to linear with the exact sRGB curve, the inverse of
// write_image's PNG encoding, so a PNG that toroid wrote reads back to within
// rounding of the colours it came from. libpng converts other PNGs first
// (palette, grey, 16-bit, gAMA) to 8-bit sRGB; alpha is composited on black.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include "toroid/core/canvas.h"

namespace toroid {

// what() names the image: "FILE:LINE: what is wrong" for PPM text (the line
// where the problem is), "FILE: what is wrong" otherwise.
struct ImageReadError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The largest width or height accepted (as for rendered images).
inline constexpr int kMaxImageReadSide = 16384;

// The book's canvas_from_ppm: a P3 or P6 image held in `data`; `source`
// names it in messages. Comments (# to the end of the line) may appear
// anywhere in a P3 file and in a P6 header. Throws ImageReadError.
Canvas canvas_from_ppm(std::string_view data, const std::string& source = "PPM data");

// Reads a PPM (P3, P6) or PNG file, told apart by its first bytes. Throws
// ImageReadError ("cannot read 'x.png': No such file or directory", ...).
Canvas read_image(const std::string& path);

}  // namespace toroid
