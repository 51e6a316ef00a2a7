// SPDX-License-Identifier: Apache-2.0
// Writing a canvas to disk: PNG (8-bit sRGB, or the linear values), the
// book's plain PPM, or OpenEXR (linear float).
#pragma once

#include <atomic>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

// An image as an 8-bit file holds it: 3 codes (R, G, B) a pixel, row-major,
// top row first; sRGB codes or linear ones (see encode_codes). A PNG or PPM
// is written from it; a render can fill it a tile at a time, without a
// canvas of linear colours (24 bytes a pixel against 3).
class Image8 {
 public:
  // Every code 0. Precondition: width, height >= 0.
  Image8(int width, int height, bool srgb);

  int width() const { return width_; }
  int height() const { return height_; }
  bool srgb() const { return srgb_; }
  unsigned char* row(int y) { return codes_.data() + static_cast<std::size_t>(y) * row_size(); }
  const unsigned char* row(int y) const { return codes_.data() + static_cast<std::size_t>(y) * row_size(); }

 private:
  std::size_t row_size() const { return static_cast<std::size_t>(width_) * 3; }

  int width_;
  int height_;
  bool srgb_;
  std::vector<unsigned char> codes_;
};

// Whether an 8-bit file of `format` holds sRGB codes: a PNG unless
// options.linear_png; a PPM never (the book's file is linear).
bool srgb_codes(ImageFormat format, const ImageWriteOptions& options);

// The codes of `count` linear colours, each channel times `scale` first:
// the sRGB curve's (linear_to_srgb8) when `srgb`, else the PPM's (clamped to
// [0, 1], times 255, rounded). Writes 3 * count codes.
void encode_codes(const Color* pixels, int count, double scale, bool srgb, unsigned char* codes);

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

// The same for the codes of an 8-bit image: a ".png" (with the sRGB chunk
// when image.srgb()) or a ".ppm" of linear codes. Throws ImageWriteError for
// any other file name, and for sRGB codes in a PPM. write_image(canvas)
// writes a PNG or PPM through this.
bool write_image(const Image8& image, const std::string& path, const std::atomic<bool>* cancel = nullptr);

// Checks, before a long render, that write_image can save to `path`: a known
// extension, an existing folder that this process can create files in (a
// temporary file is created there and removed), and not itself a folder.
// Throws ImageWriteError with the same messages as write_image.
void check_image_path(const std::string& path);

}  // namespace toroid
