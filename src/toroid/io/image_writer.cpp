// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/image_writer.h"
#include "toroid/io/exr_image.h"
#include "toroid/io/srgb.h"

#include <png.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

namespace toroid {

namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

struct PngFailure {
  std::string message;
};

void png_error_fn(png_structp png, png_const_charp msg) {
  auto* err = static_cast<std::string*>(png_get_error_ptr(png));
  *err = msg;
  png_longjmp(png, 1);
}
void png_warning_fn(png_structp, png_const_charp) {}

bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(std::memory_order_relaxed); }

// 0..1 to 0..255, rounded, as canvas_to_ppm writes a component.
int ppm_byte(double component) { return static_cast<int>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0)); }

// Returns an empty string on success or when cancelled (then `stopped` is
// set), else what went wrong.
std::string write_png(const Canvas& canvas, FILE* f, const ImageWriteOptions& options, bool& stopped) {
  const std::atomic<bool>* cancel = options.cancel;
  const double scale = options.scale;
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, png_error_fn, png_warning_fn);
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return "out of memory";
  }
  const int w = canvas.width(), h = canvas.height();
  std::vector<unsigned char> row(static_cast<std::size_t>(w) * 3);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return error.empty() ? "libpng error" : error;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(w), static_cast<png_uint_32>(h), 8, PNG_COLOR_TYPE_RGB,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // A linear PNG carries no colour chunk, as the PPM carries none, so that
  // every viewer shows the two files alike. (A gAMA 1.0 chunk would be
  // honoured by some viewers and ignored by others.)
  if (!options.linear_png) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  // zlib's fastest level, rows unfiltered: at that level a row filter
  // changes a render's file by a few percent either way, and costs the
  // writer time (docs/performance.md, "PNG output").
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  for (int y = 0; y < h; ++y) {
    if (cancelled(cancel)) {
      stopped = true;
      png_destroy_write_struct(&png, &info);
      return {};
    }
    for (int x = 0; x < w; ++x) {
      const Color c = canvas.pixel_at(x, y);
      const double rgb[3] = {c.r * scale, c.g * scale, c.b * scale};
      for (int i = 0; i < 3; ++i)
        row[3 * x + i] = options.linear_png ? static_cast<unsigned char>(ppm_byte(rgb[i])) : linear_to_srgb8(rgb[i]);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return {};
}

// The book's plain PPM (canvas_to_ppm's text, byte for byte), of the
// canvas times `scale`, written a row at a time.
std::string write_ppm(const Canvas& canvas, FILE* f, double scale, const std::atomic<bool>* cancel, bool& stopped) {
  constexpr std::size_t kMaxLine = 70;  // the book's limit on a PPM line
  std::string text = "P3\n" + std::to_string(canvas.width()) + " " + std::to_string(canvas.height()) + "\n255\n";
  for (int y = 0; y < canvas.height(); ++y) {
    if (cancelled(cancel)) {
      stopped = true;
      return {};
    }
    std::size_t line_length = 0;
    for (int x = 0; x < canvas.width(); ++x) {
      const Color c = canvas.pixel_at(x, y);
      for (const double component : {c.r * scale, c.g * scale, c.b * scale}) {
        const std::string token = std::to_string(ppm_byte(component));
        if (line_length == 0) {
          line_length = token.size();
        } else if (line_length + 1 + token.size() > kMaxLine) {
          text += '\n';
          line_length = token.size();
        } else {
          text += ' ';
          line_length += 1 + token.size();
        }
        text += token;
      }
    }
    text += '\n';
    if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) return std::strerror(errno);
    text.clear();
  }
  return {};
}

}  // namespace

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw ImageWriteError("cannot write '" + path + "': " + what);
}

ImageFormat check_extension(const std::string& path) {
  const std::optional<ImageFormat> format = image_format_of(path);
  if (!format) fail(path, "unknown image format '" + lower_extension(path) + "' (use a .png, .ppm or .exr file name)");
  return *format;
}

// Creates an empty temporary file beside `path` (same folder, so that
// rename() is atomic) and returns its name; `fd` is open on it.
std::string create_temporary_beside(const std::string& path, int& fd) {
  const std::filesystem::path target(path);
  const std::filesystem::path dir = target.parent_path().empty() ? std::filesystem::path(".") : target.parent_path();
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) fail(path, "folder '" + dir.string() + "' does not exist");
  if (!std::filesystem::is_directory(dir, ec)) fail(path, "'" + dir.string() + "' is not a folder");
  if (std::filesystem::is_directory(target, ec)) fail(path, "it is a folder");
  std::string name = ".";  // appended, not "." + ...: GCC 12 warns falsely (-Wrestrict) on that
  name += target.filename().string();
  name += ".tmp-XXXXXX";
  std::string tmpl = (dir / name).string();
  fd = mkstemp(tmpl.data());
  if (fd < 0) fail(path, "cannot create a file in '" + dir.string() + "': " + std::strerror(errno));
  return tmpl;
}

}  // namespace

std::optional<ImageFormat> image_format_of(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".ppm") return ImageFormat::ppm;
  if (ext == ".exr") return ImageFormat::exr;
  return std::nullopt;
}

void check_image_path(const std::string& path) {
  check_extension(path);
  int fd = -1;
  const std::string tmp = create_temporary_beside(path, fd);
  ::close(fd);
  std::remove(tmp.c_str());
}

bool write_image(const Canvas& canvas, const std::string& path, const std::atomic<bool>* cancel) {
  ImageWriteOptions options;
  options.cancel = cancel;
  return write_image(canvas, path, options);
}

bool write_image(const Canvas& canvas, const std::string& path, const ImageWriteOptions& options) {
  const ImageFormat format = check_extension(path);
  if (canvas.width() <= 0 || canvas.height() <= 0) fail(path, "the image is empty");
  if (!std::isfinite(options.scale) || options.scale <= 0)
    fail(path, "the scale " + std::to_string(options.scale) + " is not a positive finite number");
  const std::atomic<bool>* cancel = options.cancel;
  int fd = -1;
  const std::string tmp = create_temporary_beside(path, fd);
  FILE* f = fdopen(fd, "wb");
  if (!f) {
    const int e = errno;
    ::close(fd);
    std::remove(tmp.c_str());
    fail(path, std::strerror(e));
  }
  std::string error;
  bool stopped = false;
  switch (format) {
    case ImageFormat::png: error = write_png(canvas, f, options, stopped); break;
    case ImageFormat::ppm: error = write_ppm(canvas, f, options.scale, cancel, stopped); break;
    case ImageFormat::exr: error = detail::write_exr(canvas, options.scale, f, cancel, stopped); break;
  }
  if (std::fflush(f) != 0 && error.empty()) error = std::strerror(errno);
  if (std::ferror(f) && error.empty()) error = "write error";
  if (std::fclose(f) != 0 && error.empty()) error = std::strerror(errno);
  if (error.empty() && (stopped || cancelled(cancel))) {
    std::remove(tmp.c_str());
    return false;
  }
  if (error.empty()) {
    // mkstemp creates 0600; give the image the usual permissions (umask).
    const mode_t mask = umask(0);
    umask(mask);
    ::chmod(tmp.c_str(), 0666 & ~mask);
    if (std::rename(tmp.c_str(), path.c_str()) != 0) error = std::strerror(errno);
  }
  if (!error.empty()) {
    std::remove(tmp.c_str());
    fail(path, error);
  }
  return true;
}

}  // namespace toroid
