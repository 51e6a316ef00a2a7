// SPDX-License-Identifier: Apache-2.0
// Writing a canvas to disk: PNG (8-bit sRGB) or the book's plain PPM.
#pragma once

#include <atomic>
#include <stdexcept>
#include <string>

#include "toroid/core/canvas.h"

namespace toroid {

struct ImageWriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writes by extension: ".png" (8-bit RGB, sRGB-encoded from the canvas's
// linear colours, with an sRGB chunk) or ".ppm" (canvas_to_ppm, no gamma, as
// the book specifies). The file is written to a temporary name in the same
// directory and renamed, so `path` only ever holds a complete image. Throws
// ImageWriteError (e.g. "cannot write 'dir/x.png': No such file or
// directory") and leaves nothing behind on failure.
// With `cancel`, the write stops when it becomes true (checked between rows
// and last just before the rename): the temporary file is removed, `path` is
// left as it was, and write_image returns false. Returns true when written.
bool write_image(const Canvas& canvas, const std::string& path, const std::atomic<bool>* cancel = nullptr);

// Checks, before a long render, that write_image can save to `path`: a known
// extension, an existing folder that this process can create files in (a
// temporary file is created there and removed), and not itself a folder.
// Throws ImageWriteError with the same messages as write_image.
void check_image_path(const std::string& path);

}  // namespace toroid
