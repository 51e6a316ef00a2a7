// SPDX-License-Identifier: Apache-2.0
#include "toroid/io/image_writer.h"
#include "toroid/io/srgb.h"

#include <gtest/gtest.h>
#include <png.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/image_files.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

fs::path temp_dir(const char* name) {
  const fs::path d = fs::temp_directory_path() /
                     ("toroid_image_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

TEST(ImageWriter, SrgbEncoding) {
  EXPECT_EQ(linear_to_srgb8(0.0), 0);
  EXPECT_EQ(linear_to_srgb8(-1.0), 0);
  EXPECT_EQ(linear_to_srgb8(1.0), 255);
  EXPECT_EQ(linear_to_srgb8(7.0), 255);
  EXPECT_EQ(linear_to_srgb8(0.5), 188);  // 0.7354 * 255
  EXPECT_EQ(linear_to_srgb8(0.001), 3);  // linear segment: 12.92 * 0.001 * 255
}

TEST(ImageWriter, PngRoundTrip) {
  const fs::path d = temp_dir("png");
  Canvas c(3, 2);
  c.write_pixel(0, 0, Color{1, 0, 0});
  c.write_pixel(1, 0, Color{0, 1, 0});
  c.write_pixel(2, 0, Color{0, 0, 1.5});
  c.write_pixel(0, 1, Color{0.5, 0.5, 0.5});
  const std::string path = (d / "x.png").string();
  write_image(c, path);

  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&img, path.c_str())) << img.message;
  EXPECT_EQ(img.width, 3u);
  EXPECT_EQ(img.height, 2u);
  img.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> px(PNG_IMAGE_SIZE(img));
  ASSERT_TRUE(png_image_finish_read(&img, nullptr, px.data(), 0, nullptr)) << img.message;
  const std::vector<unsigned char> expected{255, 0, 0, 0, 255, 0, 0, 0, 255, 188, 188, 188, 0, 0, 0, 0, 0, 0};
  EXPECT_EQ(px, expected);
  // Only the image: no temporary file left behind.
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
  fs::remove_all(d);
}

TEST(ImageWriter, ACancelledWriteLeavesThePathAsItWas) {
  const fs::path d = temp_dir("cancel");
  Canvas c(4, 4);
  const std::atomic<bool> cancel{true}, go_on{false};
  for (const char* name : {"x.png", "x.ppm", "x.exr"}) {
    SCOPED_TRACE(name);
    const std::string path = (d / name).string();
    EXPECT_FALSE(write_image(c, path, &cancel));
    EXPECT_FALSE(fs::exists(path));
    {
      std::ofstream before(path);
      before << "an image from before";
    }
    EXPECT_FALSE(write_image(c, path, &cancel));
    std::ifstream in(path);
    std::stringstream ss;
    ss << in.rdbuf();
    EXPECT_EQ(ss.str(), "an image from before");
    EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1) << "a temporary file was left";
    EXPECT_TRUE(write_image(c, path, &go_on));
    EXPECT_NE(fs::file_size(path), std::string("an image from before").size());
    fs::remove(path);
  }
  fs::remove_all(d);
}

TEST(ImageWriter, Ppm) {
  const fs::path d = temp_dir("ppm");
  Canvas c(2, 1);
  c.write_pixel(0, 0, Color{1, 0.5, 0});
  write_image(c, (d / "x.ppm").string());
  std::ifstream in(d / "x.ppm");
  std::stringstream ss;
  ss << in.rdbuf();
  EXPECT_EQ(ss.str(), canvas_to_ppm(c));
  fs::remove_all(d);
}

// Values out of [0, 1], NaN-free, on rows long enough that the book's
// 70-character lines wrap.
Canvas wide_canvas() {
  Canvas c(31, 3);
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) c.write_pixel(x, y, Color{x / 20.0 - 0.2, y * 0.37 + x / 97.0, 0.5 + x * 0.01});
  return c;
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(ImageWriter, PpmIsTheBooksTextRowByRow) {
  const fs::path d = temp_dir("ppmwide");
  const Canvas c = wide_canvas();
  ASSERT_TRUE(write_image(c, (d / "x.ppm").string()));
  EXPECT_EQ(file_text(d / "x.ppm"), canvas_to_ppm(c));
  fs::remove_all(d);
}

Canvas scaled(const Canvas& c, double s) {
  Canvas out(c.width(), c.height());
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) out.write_pixel(x, y, c.pixel_at(x, y) * s);
  return out;
}

TEST(ImageWriter, TheScaleMultipliesEveryPixelBeforeEncoding) {
  const fs::path d = temp_dir("scale");
  const Canvas c = wide_canvas();
  ImageWriteOptions options;
  options.scale = 0.25;
  ASSERT_TRUE(write_image(c, (d / "x.ppm").string(), options));
  EXPECT_EQ(file_text(d / "x.ppm"), canvas_to_ppm(scaled(c, 0.25)));
  ASSERT_TRUE(write_image(c, (d / "x.png").string(), options));
  ASSERT_TRUE(write_image(scaled(c, 0.25), (d / "y.png").string()));
  EXPECT_EQ(file_text(d / "x.png"), file_text(d / "y.png"));
  fs::remove_all(d);
}

// The chunk types of a PNG file, in order.
std::vector<std::string> png_chunks(const std::string& data) {
  std::vector<std::string> types;
  for (std::size_t at = 8; at + 8 <= data.size();) {
    const auto byte = [&](std::size_t i) { return static_cast<std::uint32_t>(static_cast<unsigned char>(data[i])); };
    const std::uint32_t length = byte(at) << 24 | byte(at + 1) << 16 | byte(at + 2) << 8 | byte(at + 3);
    types.push_back(data.substr(at + 4, 4));
    at += 12 + length;
  }
  return types;
}

TEST(ImageWriter, ALinearPngHoldsThePpmsNumbersAndNoColourChunk) {
  const fs::path d = temp_dir("linear");
  const Canvas c = wide_canvas();
  ImageWriteOptions options;
  options.linear_png = true;
  ASSERT_TRUE(write_image(c, (d / "x.png").string(), options));
  const std::vector<unsigned char> px = toroid::testing::png_samples(d / "x.png");
  ASSERT_EQ(px.size(), 31u * 3u * 3u);
  EXPECT_EQ(px, toroid::testing::ppm_samples(canvas_to_ppm(c)));
  const std::vector<std::string> chunks = png_chunks(file_text(d / "x.png"));
  for (const char* colour : {"sRGB", "gAMA", "cHRM", "iCCP"})
    EXPECT_EQ(std::count(chunks.begin(), chunks.end(), colour), 0) << colour;
  // The sRGB PNG, by contrast, says it is sRGB.
  ASSERT_TRUE(write_image(c, (d / "s.png").string()));
  const std::vector<std::string> srgb = png_chunks(file_text(d / "s.png"));
  EXPECT_EQ(std::count(srgb.begin(), srgb.end(), "sRGB"), 1);
  EXPECT_NE(toroid::testing::png_samples(d / "s.png"), px);
  fs::remove_all(d);
}

TEST(ImageWriter, Errors) {
  const fs::path d = temp_dir("err");
  Canvas c(2, 2);
  try {
    write_image(c, (d / "x.jpg").string());
    ADD_FAILURE();
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + (d / "x.jpg").string() +
                                         "': unknown image format '.jpg' (use a .png, .ppm or .exr file name)");
  }
  const std::string missing = (d / "nodir" / "x.png").string();
  try {
    write_image(c, missing);
    ADD_FAILURE();
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write '" + missing + "': folder '" + (d / "nodir").string() + "' does not exist");
  }
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

TEST(ImageWriter, EncodesCodesTheWayEachFormatHoldsThem) {
  const Color pixels[] = {{0.5, 0.25, 2}, {-1, std::nan(""), 0.001}};
  unsigned char srgb[6], linear[6];
  encode_codes(pixels, 2, 1.0, true, srgb);
  encode_codes(pixels, 2, 1.0, false, linear);
  EXPECT_EQ(std::vector<int>(srgb, srgb + 6), (std::vector<int>{188, 137, 255, 0, 0, 3}));
  EXPECT_EQ(std::vector<int>(linear, linear + 6), (std::vector<int>{128, 64, 255, 0, 0, 0}));
  encode_codes(pixels, 1, 2.0, false, linear);  // the scale comes first
  EXPECT_EQ(std::vector<int>(linear, linear + 3), (std::vector<int>{255, 128, 255}));
  ImageWriteOptions options;
  EXPECT_TRUE(srgb_codes(ImageFormat::png, options));
  EXPECT_FALSE(srgb_codes(ImageFormat::ppm, options));
  options.linear_png = true;
  EXPECT_FALSE(srgb_codes(ImageFormat::png, options));
}

// A render writes its PNG or PPM from codes it encoded a tile at a time:
// the file is the one write_image makes of the canvas.
TEST(ImageWriter, AnImageOfCodesWritesTheCanvassFile) {
  const fs::path d = temp_dir("codes");
  Canvas c(3, 2);
  c.write_pixel(0, 0, Color{1, 0.2, 0});
  c.write_pixel(2, 1, Color{0.5, 0.5, 3});
  for (const char* name : {"x.png", "x.ppm"}) {
    SCOPED_TRACE(name);
    ImageWriteOptions options;
    options.scale = 0.5;
    const ImageFormat format = *image_format_of(name);
    Image8 image(3, 2, srgb_codes(format, options));
    for (int y = 0; y < 2; ++y)
      for (int x = 0; x < 3; ++x) {
        const Color pixel = c.pixel_at(x, y);
        encode_codes(&pixel, 1, options.scale, image.srgb(), image.row(y) + 3 * x);
      }
    const std::string from_canvas = (d / ("canvas-" + std::string(name))).string();
    const std::string from_codes = (d / ("codes-" + std::string(name))).string();
    ASSERT_TRUE(write_image(c, from_canvas, options));
    ASSERT_TRUE(write_image(image, from_codes));
    EXPECT_EQ(file_text(from_canvas), file_text(from_codes));
  }
  fs::remove_all(d);
}

TEST(ImageWriter, AnImageOfCodesIsAPngOrALinearPpm) {
  const fs::path d = temp_dir("codes-err");
  const std::string exr = (d / "x.exr").string(), ppm = (d / "x.ppm").string();
  try {
    write_image(Image8(2, 2, false), exr);
    ADD_FAILURE();
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write '" + exr + "': an 8-bit image is written as .png or .ppm, not OpenEXR");
  }
  try {
    write_image(Image8(2, 2, true), ppm);
    ADD_FAILURE();
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + ppm + "': a PPM holds linear codes, not sRGB ones");
  }
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

std::string check_error(const std::string& path) {
  try {
    check_image_path(path);
  } catch (const ImageWriteError& e) {
    return e.what();
  }
  return "";
}

TEST(ImageWriter, CheckingAWritablePathLeavesNothingBehind) {
  const fs::path d = temp_dir("check");
  EXPECT_EQ(check_error((d / "x.png").string()), "");
  EXPECT_EQ(check_error((d / "x.ppm").string()), "");
  EXPECT_EQ(check_error((d / "x.exr").string()), "");
  EXPECT_TRUE(fs::is_empty(d));
  std::ofstream(d / "old.png") << "old";
  EXPECT_EQ(check_error((d / "old.png").string()), "");
  std::ifstream in(d / "old.png");
  std::string content;
  in >> content;
  EXPECT_EQ(content, "old");
  fs::remove_all(d);
}

TEST(ImageWriter, CheckingNamesWhatCannotBeWritten) {
  const fs::path d = temp_dir("checkbad");
  const std::string jpg = (d / "x.jpg").string();
  EXPECT_EQ(check_error(jpg),
            "cannot write '" + jpg + "': unknown image format '.jpg' (use a .png, .ppm or .exr file name)");
  const std::string nodir = (d / "nodir" / "x.png").string();
  EXPECT_EQ(check_error(nodir), "cannot write '" + nodir + "': folder '" + (d / "nodir").string() + "' does not exist");
  std::ofstream(d / "file") << "x";
  const std::string under_file = (d / "file" / "x.png").string();
  EXPECT_EQ(check_error(under_file),
            "cannot write '" + under_file + "': '" + (d / "file").string() + "' is not a folder");
  fs::create_directories(d / "dir.png");
  const std::string dir = (d / "dir.png").string();
  EXPECT_EQ(check_error(dir), "cannot write '" + dir + "': it is a folder");
  // A folder nobody may create files in (even root: procfs).
  EXPECT_EQ(check_error("/proc/toroid.png").rfind("cannot write '/proc/toroid.png': ", 0), 0u);
  fs::remove_all(d);
}

}  // namespace
}  // namespace toroid
