// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/exr_image.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIO.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <sys/types.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "toroid/io/image_reader.h"

namespace toroid {

namespace {

// OpenEXR's output stream over write_image's temporary file. A failed write
// throws; OpenEXR passes the exception on to the writer's caller (except in
// OutputFile's destructor, which swallows it: write_image checks ferror).
class FileOStream : public Imf::OStream {
 public:
  FileOStream(std::FILE* f, const char* name) : Imf::OStream(name), f_(f) {}
  void write(const char c[], int n) override {
    if (std::fwrite(c, 1, static_cast<std::size_t>(n), f_) != static_cast<std::size_t>(n))
      throw std::runtime_error(std::strerror(errno));
  }
  uint64_t tellp() override {
    const off_t at = ftello(f_);
    if (at < 0) throw std::runtime_error(std::strerror(errno));
    return static_cast<uint64_t>(at);
  }
  void seekp(uint64_t pos) override {
    if (fseeko(f_, static_cast<off_t>(pos), SEEK_SET) != 0) throw std::runtime_error(std::strerror(errno));
  }

 private:
  std::FILE* f_;
};

// Rows converted and handed to OpenEXR at a time: ZIP compresses blocks of
// 16 rows, and a band keeps the float copy small (not a second image).
constexpr int kBandRows = 16;

bool cancelled(const std::atomic<bool>* cancel) { return cancel && cancel->load(std::memory_order_relaxed); }

}  // namespace

namespace detail {

std::string write_exr(const Canvas& canvas, double scale, std::FILE* f, const std::atomic<bool>* cancel,
                      bool& stopped) {
  const int w = canvas.width(), h = canvas.height();
  try {
    Imf::Header header(w, h);
    header.compression() = Imf::ZIP_COMPRESSION;
    for (const char* name : {"R", "G", "B"}) header.channels().insert(name, Imf::Channel(Imf::FLOAT));
    FileOStream stream(f, "toroid image");
    // One thread: the render is done, and OpenEXR's pool would start threads
    // in every process that writes an image.
    Imf::OutputFile out(stream, header, 0);
    std::vector<float> band(static_cast<std::size_t>(w) * kBandRows * 3);
    constexpr std::size_t kPixel = 3 * sizeof(float);
    const std::size_t row_bytes = kPixel * static_cast<std::size_t>(w);
    for (int y0 = 0; y0 < h; y0 += kBandRows) {
      if (cancelled(cancel)) {
        stopped = true;
        return {};
      }
      const int rows = std::min(kBandRows, h - y0);
      float* p = band.data();
      for (int y = y0; y < y0 + rows; ++y)
        for (int x = 0; x < w; ++x) {
          const Color c = canvas.pixel_at(x, y);
          *p++ = static_cast<float>(c.r * scale);
          *p++ = static_cast<float>(c.g * scale);
          *p++ = static_cast<float>(c.b * scale);
        }
      // The band holds rows y0 .. y0 + rows - 1 of the data window.
      const Imath::Box2i window(Imath::V2i(0, y0), Imath::V2i(w - 1, y0 + rows - 1));
      Imf::FrameBuffer fb;
      fb.insert("R", Imf::Slice::Make(Imf::FLOAT, band.data() + 0, window, kPixel, row_bytes));
      fb.insert("G", Imf::Slice::Make(Imf::FLOAT, band.data() + 1, window, kPixel, row_bytes));
      fb.insert("B", Imf::Slice::Make(Imf::FLOAT, band.data() + 2, window, kPixel, row_bytes));
      out.setFrameBuffer(fb);
      out.writePixels(rows);
    }
  } catch (const std::exception& e) {
    return e.what();
  }
  return {};
}

}  // namespace detail

Canvas read_exr(const std::string& path) {
  try {
    Imf::InputFile in(path.c_str(), 1);
    const Imath::Box2i window = in.header().dataWindow();
    const long long width = static_cast<long long>(window.max.x) - window.min.x + 1;
    const long long height = static_cast<long long>(window.max.y) - window.min.y + 1;
    if (width < 1 || height < 1 || width > kMaxImageReadSide || height > kMaxImageReadSide)
      throw ImageReadError(path + ": EXR of " + std::to_string(width) + " x " + std::to_string(height) +
                           " pixels (1 to " + std::to_string(kMaxImageReadSide) + " on a side are read)");
    for (const char* name : {"R", "G", "B"})
      if (in.header().channels().findChannel(name) == nullptr)
        throw ImageReadError(path + ": no '" + name + "' channel (an RGB image has R, G and B)");
    const int w = static_cast<int>(width), h = static_cast<int>(height);
    std::vector<float> rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
    constexpr std::size_t kPixel = 3 * sizeof(float);
    const std::size_t row_bytes = kPixel * static_cast<std::size_t>(w);
    Imf::FrameBuffer fb;
    fb.insert("R", Imf::Slice::Make(Imf::FLOAT, rgb.data() + 0, window, kPixel, row_bytes));
    fb.insert("G", Imf::Slice::Make(Imf::FLOAT, rgb.data() + 1, window, kPixel, row_bytes));
    fb.insert("B", Imf::Slice::Make(Imf::FLOAT, rgb.data() + 2, window, kPixel, row_bytes));
    in.setFrameBuffer(fb);
    in.readPixels(window.min.y, window.max.y);
    Canvas canvas(w, h);
    const float* p = rgb.data();
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x, p += 3) canvas.write_pixel(x, y, Color{p[0], p[1], p[2]});
    return canvas;
  } catch (const ImageReadError&) {
    throw;
  } catch (const std::exception& e) {
    throw ImageReadError(path + ": " + e.what());
  }
}

}  // namespace toroid
