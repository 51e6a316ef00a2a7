// SPDX-License-Identifier: Apache-2.0
// OpenEXR images: linear float RGB, for HDR work. write_image writes them
// (".exr"); read_exr reads them back. OpenEXR's headers stay in
// exr_image.cpp, so that toroid_lib links OpenEXR privately.
#pragma once

#include <atomic>
#include <cstdio>
#include <string>

#include "toroid/core/canvas.h"

namespace toroid {

// Reads the R, G and B channels of a scan-line or tiled OpenEXR file into a
// canvas (HALF and UINT channels are converted to float by OpenEXR; the data
// window's top left becomes pixel 0, 0). Throws ImageReadError
// ("x.exr: Cannot open image file ...", "x.exr: no 'G' channel", ...).
Canvas read_exr(const std::string& path);

namespace detail {

// write_image's EXR encoder (call write_image, which makes the write atomic):
// writes `canvas` times `scale` to `f` as a scan-line OpenEXR file with three
// 32-bit FLOAT channels R, G and B, ZIP-compressed (lossless), the values as
// they are (no clamping, no transfer curve). Checks `cancel` between blocks
// of rows; when it is set, stops and sets `stopped`. Returns an empty string
// on success or when stopped, else what went wrong.
std::string write_exr(const Canvas& canvas, double scale, std::FILE* f, const std::atomic<bool>* cancel, bool& stopped);

}  // namespace detail

}  // namespace toroid
