// SPDX-License-Identifier: Apache-2.0
// Writing a canvas to disk: PNG (8-bit sRGB, or the linear values), the
// book's plain PPM, or OpenEXR (linear float).
#pragma once

#include <atomic>
#include <optional>
#include <stdexcept>
#include <string>

#include "toroid/core/canvas.h"

namespace toroid {

struct ImageWriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The formats write_image knows, by the file name's extension (any case).
enum class ImageFormat { png, ppm, exr };
std::optional<ImageFormat> image_format_of(const std::string& path);

struct ImageWriteOptions {
  // Every channel is multiplied by this before it is encoded (toroid
  // render's --exposure E gives 2^E). A positive finite number.
  double scale = 1;
  // PNG only: the canvas's values as 8-bit codes the way the PPM writes them
  // (clamped to [0, 1], times 255, rounded), with no sRGB transfer and no
  // colour chunk (no sRGB, gAMA or cHRM), so that the PNG and the PPM of an
  // image hold the same numbers. The other formats are linear already and
  // ignore it. (read_image takes a PNG without a colour chunk for sRGB, as
  // viewers do: a linear PNG is not a texture of the values it holds.)
  bool linear_png = false;
  // When given, the write stops once it is set (see write_image).
  const std::atomic<bool>* cancel = nullptr;
};

// Writes by extension: ".png" (8-bit RGB, sRGB-encoded from the canvas's
// linear colours, with an sRGB chunk; or linear, see ImageWriteOptions),
// ".ppm" (canvas_to_ppm, no gamma, as the book specifies) or ".exr" (OpenEXR,
// 32-bit float R, G, B, the values unclamped). The file is written to a
// temporary name in the same directory and renamed, so `path` only ever
// holds a complete image. Throws ImageWriteError (e.g. "cannot write
// 'dir/x.png': No such file or directory") and leaves nothing behind on
// failure.
// With `cancel`, the write stops when it becomes true (checked between rows
// and last just before the rename): the temporary file is removed, `path` is
// left as it was, and write_image returns false. Returns true when written.
bool write_image(const Canvas& canvas, const std::string& path, const ImageWriteOptions& options);
bool write_image(const Canvas& canvas, const std::string& path, const std::atomic<bool>* cancel = nullptr);

// Checks, before a long render, that write_image can save to `path`: a known
// extension, an existing folder that this process can create files in (a
// temporary file is created there and removed), and not itself a folder.
// Throws ImageWriteError with the same messages as write_image.
void check_image_path(const std::string& path);

}  // namespace toroid
