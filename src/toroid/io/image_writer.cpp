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
#include <functional>
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
unsigned char ppm_byte(double component) {
  return static_cast<unsigned char>(std::lround(std::clamp(component, 0.0, 1.0) * 255.0));
}

// Returns an empty string on success or when cancelled (then `stopped` is
// set), else what went wrong.
std::string write_png(const Image8& image, FILE* f, const std::atomic<bool>* cancel, bool& stopped) {
  std::string error;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &error, png_error_fn, png_warning_fn);
  if (!png) return "out of memory";
  png_infop info = png_create_info_struct(png);
  if (!info) {
    png_destroy_write_struct(&png, nullptr);
    return "out of memory";
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    return error.empty() ? "libpng error" : error;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width()), static_cast<png_uint_32>(image.height()), 8,
               PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // A linear PNG carries no colour chunk, as the PPM carries none, so that
  // every viewer shows the two files alike. (A gAMA 1.0 chunk would be
  // honoured by some viewers and ignored by others.)
  if (image.srgb()) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  // zlib's fastest level, rows unfiltered: at that level a row filter
  // changes a render's file by a few percent either way, and costs the
  // writer time (docs/performance.md, "PNG output").
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_write_info(png, info);
  for (int y = 0; y < image.height(); ++y) {
    if (cancelled(cancel)) {
      stopped = true;
      png_destroy_write_struct(&png, &info);
      return {};
    }
    png_write_row(png, image.row(y));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return {};
}

// The book's plain PPM (canvas_to_ppm's text, byte for byte) of linear
// codes, written a row at a time.
std::string write_ppm(const Image8& image, FILE* f, const std::atomic<bool>* cancel, bool& stopped) {
  constexpr std::size_t kMaxLine = 70;  // the book's limit on a PPM line
  std::string text = "P3\n" + std::to_string(image.width()) + " " + std::to_string(image.height()) + "\n255\n";
  for (int y = 0; y < image.height(); ++y) {
    if (cancelled(cancel)) {
      stopped = true;
      return {};
    }
    std::size_t line_length = 0;
    const unsigned char* codes = image.row(y);
    for (int i = 0; i < 3 * image.width(); ++i) {
      const std::string token = std::to_string(codes[i]);
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

Image8::Image8(int width, int height, bool srgb)
    : width_(width),
      height_(height),
      srgb_(srgb),
      codes_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3) {}

bool srgb_codes(ImageFormat format, const ImageWriteOptions& options) {
  return format == ImageFormat::png && !options.linear_png;
}

void encode_codes(const Color* pixels, int count, double scale, bool srgb, unsigned char* codes) {
  if (!srgb) {
    for (int i = 0; i < count; ++i) {
      const Color& c = pixels[i];
      for (const double v : {c.r * scale, c.g * scale, c.b * scale}) *codes++ = ppm_byte(v);
    }
    return;
  }
  // A chunk of scaled channels at a time, through the row form of the sRGB
  // encoding (one table lookup per chunk, not per channel).
  constexpr int kChunk = 128;
  double values[3 * kChunk];
  for (int first = 0; first < count; first += kChunk) {
    const int n = std::min(kChunk, count - first);
    for (int i = 0; i < n; ++i) {
      const Color& c = pixels[first + i];
      values[3 * i] = c.r * scale;
      values[3 * i + 1] = c.g * scale;
      values[3 * i + 2] = c.b * scale;
    }
    linear_to_srgb8(values, 3 * n, codes);
    codes += 3 * n;
  }
}

namespace {

// Writes the file through `write` (which returns what went wrong, or "" and
// sets `stopped` when cancelled) to a temporary name beside `path`, then
// renames it; see write_image.
bool write_file(const std::string& path, const std::atomic<bool>* cancel,
                const std::function<std::string(FILE*, bool&)>& write) {
  int fd = -1;
  const std::string tmp = create_temporary_beside(path, fd);
  FILE* f = fdopen(fd, "wb");
  if (!f) {
    const int e = errno;
    ::close(fd);
    std::remove(tmp.c_str());
    fail(path, std::strerror(e));
  }
  bool stopped = false;
  std::string error = write(f, stopped);
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

}  // namespace

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
  if (format == ImageFormat::exr)
    return write_file(path, options.cancel, [&](FILE* f, bool& stopped) {
      return detail::write_exr(canvas, options.scale, f, options.cancel, stopped);
    });
  Image8 image(canvas.width(), canvas.height(), srgb_codes(format, options));
  for (int y = 0; y < canvas.height(); ++y)
    encode_codes(canvas.pixels().data() + static_cast<std::size_t>(y) * static_cast<std::size_t>(canvas.width()),
                 canvas.width(), options.scale, image.srgb(), image.row(y));
  return write_image(image, path, options.cancel);
}

bool write_image(const Image8& image, const std::string& path, const std::atomic<bool>* cancel) {
  const ImageFormat format = check_extension(path);
  if (format == ImageFormat::exr) fail(path, "an 8-bit image is written as .png or .ppm, not OpenEXR");
  if (format == ImageFormat::ppm && image.srgb()) fail(path, "a PPM holds linear codes, not sRGB ones");
  if (image.width() <= 0 || image.height() <= 0) fail(path, "the image is empty");
  return write_file(path, cancel, [&](FILE* f, bool& stopped) {
    return format == ImageFormat::png ? write_png(image, f, cancel, stopped) : write_ppm(image, f, cancel, stopped);
  });
}

}  // namespace toroid
