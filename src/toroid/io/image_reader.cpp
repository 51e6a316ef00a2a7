// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/image_reader.h"
#include "toroid/io/srgb.h"

#include <png.h>

#include <array>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace toroid {

namespace {

// A word of the input as it can be shown in a message.
std::string printable(std::string_view s) {
  std::string out;
  for (const char c : s.substr(0, 16)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  if (s.size() > 16) out += "...";
  return out;
}

// Splits PPM data into whitespace-separated words, skipping comments and
// counting lines for messages.
class PpmScanner {
 public:
  PpmScanner(std::string_view data, const std::string& source) : data_(data), source_(source) {}

  // The next word (empty at the end of the data).
  std::string_view word() {
    while (pos_ < data_.size()) {
      const char c = data_[pos_];
      if (c == '#') {
        while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        break;
      }
    }
    const std::size_t start = pos_;
    while (pos_ < data_.size() && data_[pos_] != '#' && !std::isspace(static_cast<unsigned char>(data_[pos_]))) ++pos_;
    if (pos_ > start) word_line_ = line_;
    return data_.substr(start, pos_ - start);
  }
  // The line of the last word read: at the end of the data, where it ends.
  int word_line() const { return word_line_; }

  // An unsigned integer word in [min, max]; `what` names it in messages.
  unsigned long number(const std::string& what, unsigned long min, unsigned long max) {
    const std::string_view w = word();
    if (w.empty()) fail(word_line_, "the file ends before " + what);
    unsigned long v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec == std::errc::result_out_of_range) fail(word_line_, what + " " + printable(w) + " is too large");
    if (ec != std::errc() || end != w.data() + w.size())
      fail(word_line_, "expected " + what + " (a whole number), got '" + printable(w) + "'");
    if (v < min || v > max)
      fail(word_line_,
           what + " " + std::to_string(v) + " is out of range " + std::to_string(min) + ".." + std::to_string(max));
    return v;
  }

  // Raw data begins after the single whitespace byte that ends the header.
  std::string_view raw_data() {
    if (pos_ >= data_.size() || !std::isspace(static_cast<unsigned char>(data_[pos_])))
      fail(word_line_, "expected one whitespace byte between the maximum value and the pixel data");
    return data_.substr(pos_ + 1);
  }

  [[noreturn]] void fail(int line, const std::string& what) const {
    throw ImageReadError(source_ + ":" + std::to_string(line) + ": " + what);
  }
  [[noreturn]] void fail(const std::string& what) const { throw ImageReadError(source_ + ": " + what); }

 private:
  std::string_view data_;
  const std::string& source_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int word_line_ = 1;
};

const char* const kChannel[3] = {"red", "green", "blue"};

std::string sample_name(std::size_t i, int width) {
  const std::size_t pixel = i / 3;
  return std::string(kChannel[i % 3]) + " of pixel (" + std::to_string(pixel % width) + ", " +
         std::to_string(pixel / width) + ")";
}

// Every sample of a P3 file, checked against maxval.
std::vector<std::uint16_t> plain_samples(PpmScanner& in, int width, int height, unsigned long maxval) {
  const std::size_t count = std::size_t{3} * width * height;
  std::vector<std::uint16_t> samples;
  while (samples.size() < count) {
    const std::string_view w = in.word();
    if (w.empty())
      in.fail(in.word_line(), "the pixel data ends after " + std::to_string(samples.size()) + " of " +
                                  std::to_string(count) + " values (" + std::to_string(width) + " x " +
                                  std::to_string(height) + " pixels, 3 values each)");
    unsigned long v = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), v);
    if (ec != std::errc() || end != w.data() + w.size())
      in.fail(in.word_line(),
              "expected a whole number for the " + sample_name(samples.size(), width) + ", got '" + printable(w) + "'");
    if (v > maxval)
      in.fail(in.word_line(), "value " + std::to_string(v) + " for the " + sample_name(samples.size(), width) +
                                  " exceeds the maximum value " + std::to_string(maxval));
    samples.push_back(static_cast<std::uint16_t>(v));
  }
  if (const std::string_view extra = in.word(); !extra.empty())
    in.fail(in.word_line(), "more pixel values than " + std::to_string(width) + " x " + std::to_string(height) +
                                " pixels need ('" + printable(extra) + "')");
  return samples;
}

// Every sample of a P6 file: one byte each, or two (big-endian) when
// maxval > 255.
std::vector<std::uint16_t> raw_samples(PpmScanner& in, int width, int height, unsigned long maxval) {
  const std::string_view raw = in.raw_data();
  const std::size_t count = std::size_t{3} * width * height;
  const std::size_t bytes_per_sample = maxval > 255 ? 2 : 1;
  if (raw.size() < count * bytes_per_sample)
    in.fail("the pixel data ends after " + std::to_string(raw.size()) + " of " +
            std::to_string(count * bytes_per_sample) + " bytes (" + std::to_string(width) + " x " +
            std::to_string(height) + " pixels)");
  std::vector<std::uint16_t> samples(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto* b = reinterpret_cast<const unsigned char*>(raw.data()) + i * bytes_per_sample;
    const unsigned v = bytes_per_sample == 2 ? (b[0] << 8 | b[1]) : b[0];
    if (v > maxval)
      in.fail("value " + std::to_string(v) + " for the " + sample_name(i, width) + " exceeds the maximum value " +
              std::to_string(maxval));
    samples[i] = static_cast<std::uint16_t>(v);
  }
  return samples;
}

Canvas read_png(const std::string& data, const std::string& path) {
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  auto fail = [&](const std::string& what) -> ImageReadError {
    png_image_free(&image);
    return ImageReadError(path + ": " + what);
  };
  if (!png_image_begin_read_from_memory(&image, data.data(), data.size()))
    throw fail(std::string("corrupt PNG: ") + image.message);
  if (image.width > static_cast<png_uint_32>(kMaxImageReadSide) ||
      image.height > static_cast<png_uint_32>(kMaxImageReadSide))
    throw fail("PNG of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
               " pixels is larger than " + std::to_string(kMaxImageReadSide) + " on a side");
  image.format = PNG_FORMAT_RGB;  // 8-bit sRGB
  std::vector<unsigned char> rgb(PNG_IMAGE_SIZE(image));
  const png_color black{0, 0, 0};
  if (!png_image_finish_read(&image, &black, rgb.data(), 0, nullptr))
    throw fail(std::string("corrupt PNG: ") + image.message);
  const int width = static_cast<int>(image.width), height = static_cast<int>(image.height);
  png_image_free(&image);
  Canvas canvas(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const unsigned char* p = &rgb[(static_cast<std::size_t>(y) * width + x) * 3];
      canvas.write_pixel(x, y, Color{srgb8_to_linear(p[0]), srgb8_to_linear(p[1]), srgb8_to_linear(p[2])});
    }
  return canvas;
}

}  // namespace

Canvas canvas_from_ppm(std::string_view data, const std::string& source) {
  PpmScanner in(data, source);
  const std::string_view magic = in.word();
  if (magic.empty()) in.fail("empty file: not a PPM image");
  if (magic != "P3" && magic != "P6")
    in.fail(in.word_line(), "not a PPM image: magic number '" + printable(magic) + "' (expected P3 or P6)");
  const int width = static_cast<int>(in.number("the width", 1, kMaxImageReadSide));
  const int height = static_cast<int>(in.number("the height", 1, kMaxImageReadSide));
  const unsigned long maxval = in.number("the maximum value", 1, 65535);
  const std::vector<std::uint16_t> samples =
      magic == "P3" ? plain_samples(in, width, height, maxval) : raw_samples(in, width, height, maxval);
  Canvas canvas(width, height);
  const double scale = 1.0 / static_cast<double>(maxval);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * width + x) * 3;
      canvas.write_pixel(x, y, Color{samples[i] * scale, samples[i + 1] * scale, samples[i + 2] * scale});
    }
  return canvas;
}

Canvas read_image(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw ImageReadError("cannot read '" + path + "': it is a directory");
  // A device or a pipe (/dev/zero) could be read forever.
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw ImageReadError("cannot read '" + path + "': not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImageReadError("cannot read '" + path + "': " + std::strerror(errno));
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw ImageReadError("cannot read '" + path + "': read error");
  const std::string data = std::move(ss).str();
  static constexpr char kPngSignature[] = "\x89PNG\r\n\x1a\n";
  if (data.empty()) throw ImageReadError(path + ": empty file: not a PPM or PNG image");
  if (data.compare(0, 8, kPngSignature, 8) == 0) return read_png(data, path);
  if (data[0] == 'P') return canvas_from_ppm(data, path);
  throw ImageReadError(path + ": not a PPM (P3, P6) or PNG image");
}

}  // namespace toroid
