// SPDX-License-Identifier: Apache-2.0
// OpenEXR output (write_image's ".exr") and read_exr.
#include "toroid/io/exr_image.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "toroid/io/image_reader.h"
#include "toroid/io/image_writer.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const char* name) {
  const fs::path d = fs::temp_directory_path() / ("toroid_exr_test_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::size_t entries(const fs::path& d) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(d), fs::directory_iterator()));
}

// Values a HALF channel could not hold (more than 11 significant bits, above
// 65504, below its smallest subnormal), negative and above 1: the file
// holds them as 32-bit floats, unclamped, with each channel in its place.
Canvas hdr_canvas() {
  Canvas c(37, 21);  // more rows than one 16-row band, a last band of 5
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x)
      c.write_pixel(x, y, Color{0.1 + x * 1.0000001, -0.25 * y + 1e-30, 70000.0 + x * y + 1.0 / 3.0});
  c.write_pixel(0, 0, Color{1, 0, 0});
  c.write_pixel(1, 0, Color{0, 1, 0});
  c.write_pixel(2, 0, Color{0, 0, 1});
  return c;
}

void expect_float_pixels(const Canvas& read, const Canvas& written, double scale) {
  ASSERT_EQ(read.width(), written.width());
  ASSERT_EQ(read.height(), written.height());
  for (int y = 0; y < read.height(); ++y)
    for (int x = 0; x < read.width(); ++x) {
      const Color r = read.pixel_at(x, y), w = written.pixel_at(x, y);
      ASSERT_EQ(r.r, static_cast<float>(w.r * scale)) << x << ", " << y;
      ASSERT_EQ(r.g, static_cast<float>(w.g * scale)) << x << ", " << y;
      ASSERT_EQ(r.b, static_cast<float>(w.b * scale)) << x << ", " << y;
    }
}

TEST(Exr, WritesFloatRgbThatReadsBackBitExact) {
  const fs::path d = temp_dir("roundtrip");
  const Canvas c = hdr_canvas();
  const std::string path = (d / "x.exr").string();
  ASSERT_TRUE(write_image(c, path));
  expect_float_pixels(read_exr(path), c, 1);
  // Only the image: the temporary file was renamed.
  EXPECT_EQ(entries(d), 1u);
  fs::remove_all(d);
}

TEST(Exr, TheExtensionIsCaseBlind) {
  const fs::path d = temp_dir("case");
  const Canvas c = hdr_canvas();
  ASSERT_TRUE(write_image(c, (d / "x.EXR").string()));
  expect_float_pixels(read_exr((d / "x.EXR").string()), c, 1);
  fs::remove_all(d);
}

TEST(Exr, TheScaleMultipliesEveryValue) {
  const fs::path d = temp_dir("scale");
  const Canvas c = hdr_canvas();
  ImageWriteOptions options;
  options.scale = 0.5;
  ASSERT_TRUE(write_image(c, (d / "half.exr").string(), options));
  expect_float_pixels(read_exr((d / "half.exr").string()), c, 0.5);
  fs::remove_all(d);
}

TEST(Exr, ACancelledWriteLeavesThePathAsItWas) {
  const fs::path d = temp_dir("cancel");
  const std::atomic<bool> cancel{true};
  const std::string path = (d / "x.exr").string();
  EXPECT_FALSE(write_image(hdr_canvas(), path, &cancel));
  EXPECT_TRUE(fs::is_empty(d));
  std::ofstream(path) << "an image from before";
  EXPECT_FALSE(write_image(hdr_canvas(), path, &cancel));
  EXPECT_EQ(fs::file_size(path), std::string("an image from before").size());
  EXPECT_EQ(entries(d), 1u);
  fs::remove_all(d);
}

// The encoder itself stops between bands (write_image checks once more
// before its rename, which would hide an encoder that wrote to the end).
TEST(Exr, TheEncoderStopsWhenCancelled) {
  std::FILE* f = std::tmpfile();
  ASSERT_NE(f, nullptr);
  const std::atomic<bool> cancel{true};
  bool stopped = false;
  EXPECT_EQ(detail::write_exr(hdr_canvas(), 1, f, &cancel, stopped), "");
  EXPECT_TRUE(stopped);
  std::fclose(f);
}

std::string write_error(const Canvas& c, const std::string& path) {
  try {
    write_image(c, path);
  } catch (const ImageWriteError& e) {
    return e.what();
  }
  return "";
}

TEST(Exr, AFailedWriteSaysWhyAndLeavesNoFile) {
  const fs::path d = temp_dir("fail");
  const Canvas c = hdr_canvas();
  const std::string missing = (d / "nodir" / "x.exr").string();
  EXPECT_EQ(write_error(c, missing),
            "cannot write '" + missing + "': folder '" + (d / "nodir").string() + "' does not exist");
  fs::create_directories(d / "dir.exr");
  EXPECT_EQ(write_error(c, (d / "dir.exr").string()),
            "cannot write '" + (d / "dir.exr").string() + "': it is a folder");
  EXPECT_EQ(write_error(c, "/proc/toroid.exr").rfind("cannot write '/proc/toroid.exr': cannot create a file in", 0),
            0u);
  EXPECT_EQ(entries(d), 1u);  // dir.exr alone
  fs::remove_all(d);
}

// A write that fails part way (as on a full disk): a file-size limit of 4 KiB
// in a child process, with SIGXFSZ ignored so that the write fails with
// EFBIG. The child reports through its exit status: 0 when write_image threw
// the error, naming it, and left nothing behind.
TEST(Exr, AWriteThatFailsPartWayLeavesNoFile) {
  const fs::path d = temp_dir("efbig");
  const std::string path = (d / "big.exr").string();
  const pid_t pid = ::fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    Canvas c(256, 256);
    for (int y = 0; y < 256; ++y)
      for (int x = 0; x < 256; ++x) c.write_pixel(x, y, Color{x * 0.37, y * 0.11, (x ^ y) * 0.013});
    int code = 1;
    try {
      write_image(c, path);
    } catch (const ImageWriteError& e) {
      // The encoder's own error (the failed write's errno), not only the
      // stream's error flag that write_image checks afterwards.
      const std::string what = e.what();
      code = what.rfind("cannot write '" + path + "': ", 0) == 0 && what.find("File too large") != std::string::npos &&
                     fs::is_empty(d)
                 ? 0
                 : 2;
    }
    std::_Exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: written whole; 2: the wrong message, or a file was left";
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

TEST(Exr, ABadScaleIsRefused) {
  const fs::path d = temp_dir("badscale");
  ImageWriteOptions options;
  for (const double scale : {0.0, -1.0, std::numeric_limits<double>::infinity(), std::nan("")}) {
    options.scale = scale;
    EXPECT_THROW(write_image(hdr_canvas(), (d / "x.exr").string(), options), ImageWriteError) << scale;
  }
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

std::string read_error(const std::string& path) {
  try {
    read_exr(path);
  } catch (const ImageReadError& e) {
    return e.what();
  }
  return "";
}

TEST(Exr, ReadingSaysWhatIsWrongWithTheFile) {
  const fs::path d = temp_dir("read");
  const std::string missing = (d / "none.exr").string();
  EXPECT_EQ(read_error(missing).rfind(missing + ": ", 0), 0u) << read_error(missing);
  const std::string junk = (d / "junk.exr").string();
  std::ofstream(junk) << "not an OpenEXR file";
  EXPECT_EQ(read_error(junk).rfind(junk + ": ", 0), 0u) << read_error(junk);
  // A PPM with the wrong name is not an EXR either.
  const std::string ppm = (d / "x.ppm").string();
  ASSERT_TRUE(write_image(Canvas(2, 2), ppm));
  EXPECT_EQ(read_error(ppm).rfind(ppm + ": ", 0), 0u) << read_error(ppm);
  fs::remove_all(d);
}

}  // namespace
}  // namespace toroid
