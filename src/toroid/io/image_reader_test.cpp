// SPDX-License-Identifier: Apache-2.0
// canvas.feature (texture mapping bonus chapter): canvas_from_ppm; then P6,
// PNG and the errors (beyond the book).
#include "toroid/io/image_reader.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/approx.h"
#include "support/temp_dir.h"
#include "toroid/io/image_writer.h"
#include "toroid/io/srgb.h"

namespace toroid {
namespace {

using testing::TempDir;

// The book prints 127/255 = 0.498039... as 0.498: compare at the printed
// precision (half a unit in its last place) where the book rounded.
constexpr double kPrinted3 = 5e-4;

TEST(CanvasFromPpm, ReadingAFileWithTheWrongMagicNumber) {
  EXPECT_THROW(canvas_from_ppm("P32\n1 1\n255\n0 0 0\n"), ImageReadError);
}

TEST(CanvasFromPpm, ReadingAPpmReturnsACanvasOfTheRightSize) {
  const Canvas canvas = canvas_from_ppm(
      "P3\n10 2\n255\n"
      "0 0 0  0 0 0  0 0 0  0 0 0  0 0 0\n"
      "0 0 0  0 0 0  0 0 0  0 0 0  0 0 0\n"
      "0 0 0  0 0 0  0 0 0  0 0 0  0 0 0\n"
      "0 0 0  0 0 0  0 0 0  0 0 0  0 0 0\n");
  EXPECT_EQ(canvas.width(), 10);
  EXPECT_EQ(canvas.height(), 2);
}

TEST(CanvasFromPpm, ReadingPixelDataFromAPpmFile) {
  const Canvas canvas = canvas_from_ppm(
      "P3\n4 3\n255\n"
      "255 127 0  0 127 255  127 255 0  255 255 255\n"
      "0 0 0  255 0 0  0 255 0  0 0 255\n"
      "255 255 0  0 255 255  255 0 255  127 127 127\n");
  const struct {
    int x, y;
    Color color;
  } examples[] = {
      {0, 0, {1, 0.498, 0}}, {1, 0, {0, 0.498, 1}}, {2, 0, {0.498, 1, 0}}, {3, 0, {1, 1, 1}},
      {0, 1, {0, 0, 0}},     {1, 1, {1, 0, 0}},     {2, 1, {0, 1, 0}},     {3, 1, {0, 0, 1}},
      {0, 2, {1, 1, 0}},     {1, 2, {0, 1, 1}},     {2, 2, {1, 0, 1}},     {3, 2, {0.498, 0.498, 0.498}},
  };
  for (const auto& e : examples) {
    SCOPED_TRACE(::testing::Message() << "pixel " << e.x << ", " << e.y);
    EXPECT_TRUE(approx_equal(canvas.pixel_at(e.x, e.y), e.color, kPrinted3)) << canvas.pixel_at(e.x, e.y);
  }
  EXPECT_APPROX(canvas.pixel_at(0, 0), (Color{1, 127 / 255.0, 0}));  // exactly value / maxval
}

TEST(CanvasFromPpm, PpmParsingIgnoresCommentLines) {
  const Canvas canvas = canvas_from_ppm(
      "P3\n"
      "# this is a comment\n"
      "2 1\n"
      "# this, too\n"
      "255\n"
      "# another comment\n"
      "255 255 255\n"
      "# oh, no, comments in the pixel data!\n"
      "255 0 255\n");
  EXPECT_APPROX(canvas.pixel_at(0, 0), (Color{1, 1, 1}));
  EXPECT_APPROX(canvas.pixel_at(1, 0), (Color{1, 0, 1}));
}

TEST(CanvasFromPpm, PpmParsingAllowsAnRgbTripleToSpanLines) {
  const Canvas canvas = canvas_from_ppm("P3\n1 1\n255\n51\n153\n\n204\n");
  EXPECT_APPROX(canvas.pixel_at(0, 0), (Color{0.2, 0.6, 0.8}));
}

TEST(CanvasFromPpm, PpmParsingRespectsTheScaleSetting) {
  const Canvas canvas = canvas_from_ppm("P3\n2 2\n100\n100 100 100  50 50 50\n75 50 25  0 0 0\n");
  EXPECT_APPROX(canvas.pixel_at(0, 1), (Color{0.75, 0.5, 0.25}));
}

// Beyond the book ------------------------------------------------------------

TEST(CanvasFromPpm, RawP6WithOneAndTwoBytesPerSample) {
  const std::string p6 = std::string("P6\n# raw\n2 1\n255\n") + std::string("\xff\x00\x80\x00\x33\xff", 6);
  const Canvas c = canvas_from_ppm(p6);
  EXPECT_APPROX(c.pixel_at(0, 0), (Color{1, 0, 128 / 255.0}));
  EXPECT_APPROX(c.pixel_at(1, 0), (Color{0, 51 / 255.0, 1}));
  // maxval > 255: big-endian pairs. A raw byte that looks like '#' or a
  // newline is data, not a comment or a line break.
  const std::string p6_16 = std::string("P6 1 1 1000\n") + std::string("\x03\xe8\x00\x23\x01\x0a", 6);
  const Canvas d = canvas_from_ppm(p6_16);
  EXPECT_APPROX(d.pixel_at(0, 0), (Color{1, 0.035, 0.266}));
}

TEST(CanvasFromPpm, ReadsBackWhatCanvasToPpmWrites) {
  Canvas c(3, 2);
  c.write_pixel(0, 0, Color{1, 0.2, 0});
  c.write_pixel(2, 1, Color{0.5, 0.25, 1});
  const Canvas back = canvas_from_ppm(canvas_to_ppm(c));
  ASSERT_EQ(back.width(), 3);
  ASSERT_EQ(back.height(), 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      EXPECT_TRUE(approx_equal(back.pixel_at(x, y), c.pixel_at(x, y), 0.5 / 255)) << x << ", " << y;
}

// Each error names the source and, for PPM text, the line of the problem.
TEST(CanvasFromPpm, ErrorsNameTheSourceAndLine) {
  auto error_of = [](const std::string& data) {
    try {
      canvas_from_ppm(data, "t.ppm");
    } catch (const ImageReadError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_of("P32\n1 1\n255\n0 0 0\n"), "t.ppm:1: not a PPM image: magic number 'P32' (expected P3 or P6)");
  EXPECT_EQ(error_of(""), "t.ppm: empty file: not a PPM image");
  EXPECT_EQ(error_of("P3\n# size\nten 2\n"), "t.ppm:3: expected the width (a whole number), got 'ten'");
  EXPECT_EQ(error_of("P3\n0 2\n255\n"), "t.ppm:2: the width 0 is out of range 1..16384");
  EXPECT_EQ(error_of("P3\n2 99999999999999999999999\n"), "t.ppm:2: the height 9999999999999999... is too large");
  EXPECT_EQ(error_of("P3\n1 1\n70000\n"), "t.ppm:3: the maximum value 70000 is out of range 1..65535");
  EXPECT_EQ(error_of("P3\n1 1\n"), "t.ppm:2: the file ends before the maximum value");
  EXPECT_EQ(error_of("P3\n2 1\n255\n1 2 3\n4 x 6\n"),
            "t.ppm:5: expected a whole number for the green of pixel (1, 0), got 'x'");
  EXPECT_EQ(error_of("P3\n2 1\n255\n1 2 3\n4 5 256\n"),
            "t.ppm:5: value 256 for the blue of pixel (1, 0) exceeds the maximum value 255");
  EXPECT_EQ(error_of("P3\n2 2\n255\n1 2 3\n4 5 6\n\n"),
            "t.ppm:5: the pixel data ends after 6 of 12 values (2 x 2 pixels, 3 values each)");
  EXPECT_EQ(error_of("P3\n1 1\n255\n1 2 3\n4\n"), "t.ppm:5: more pixel values than 1 x 1 pixels need ('4')");
  EXPECT_EQ(error_of(std::string("P6\n2 1\n255\n\x01\x02\x03\x04", 15)),
            "t.ppm: the pixel data ends after 4 of 6 bytes (2 x 1 pixels)");
  EXPECT_EQ(error_of(std::string("P6\n1 1\n100\n\x01\x02\xff", 14)),
            "t.ppm: value 255 for the blue of pixel (0, 0) exceeds the maximum value 100");
  EXPECT_EQ(error_of("P6\n1 1\n255#\x01\x02\x03"),
            "t.ppm:3: expected one whitespace byte between the maximum value and the pixel data");
}

TEST(ReadImage, SrgbDecodingInvertsTheWritersEncoding) {
  EXPECT_EQ(srgb8_to_linear(0), 0.0);
  EXPECT_EQ(srgb8_to_linear(255), 1.0);
  EXPECT_NEAR(srgb8_to_linear(188), 0.5029, 1e-4);            // linear_to_srgb8(0.5) == 188
  EXPECT_NEAR(srgb8_to_linear(3), 3 / 255.0 / 12.92, 1e-15);  // the linear segment
  for (int code = 0; code < 256; ++code) {
    EXPECT_EQ(linear_to_srgb8(srgb8_to_linear(static_cast<unsigned char>(code))), code);
    if (code > 0) {
      EXPECT_GT(srgb8_to_linear(static_cast<unsigned char>(code)), srgb8_to_linear(code - 1));
    }
  }
}

TEST(ReadImage, PngAndPpmFilesReadBackWhatWriteImageWrote) {
  const TempDir dir("read_image_round_trip");
  Canvas c(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) c.write_pixel(x, y, Color{x / 4.0, y / 2.0, 0.2 * ((x + y) % 3)});
  for (const char* name : {"c.png", "c.ppm"}) {
    SCOPED_TRACE(name);
    write_image(c, dir.file(name));
    const Canvas back = read_image(dir.file(name));
    ASSERT_EQ(back.width(), 5);
    ASSERT_EQ(back.height(), 3);
    for (int y = 0; y < 3; ++y)
      for (int x = 0; x < 5; ++x) {
        const Color want = c.pixel_at(x, y), got = back.pixel_at(x, y);
        // PNG: the sRGB code written decodes to the exact code's value.
        if (std::string(name) == "c.png") {
          EXPECT_APPROX(got, (Color{srgb8_to_linear(linear_to_srgb8(want.r)), srgb8_to_linear(linear_to_srgb8(want.g)),
                                    srgb8_to_linear(linear_to_srgb8(want.b))}));
        }
        EXPECT_TRUE(approx_equal(got, want, 0.01)) << x << ", " << y << ": " << got;
      }
  }
}

TEST(ReadImage, ErrorsNameTheFile) {
  const TempDir dir("read_image_errors");
  auto error_of = [](const std::string& path) {
    try {
      read_image(path);
    } catch (const ImageReadError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(dir.file(name), std::ios::binary) << bytes;
    return dir.file(name);
  };
  EXPECT_EQ(error_of(dir.file("missing.png")),
            "cannot read '" + dir.file("missing.png") + "': No such file or directory");
  EXPECT_EQ(error_of(dir.path().string()), "cannot read '" + dir.path().string() + "': it is a directory");
  const std::string empty = write("empty.ppm", "");
  EXPECT_EQ(error_of(empty), empty + ": empty file: not a PPM or PNG image");
  const std::string gif = write("x.gif", "GIF89a...");
  EXPECT_EQ(error_of(gif), gif + ": not a PPM (P3, P6) or PNG image");
  const std::string bad_ppm = write("bad.ppm", "P3\n1 1\n255\n0 0 oops\n");
  EXPECT_EQ(error_of(bad_ppm), bad_ppm + ":4: expected a whole number for the blue of pixel (0, 0), got 'oops'");

  // A PNG cut short after its header: libpng's complaint, after the name.
  Canvas c(16, 16);
  write_image(c, dir.file("whole.png"));
  std::ifstream in(dir.file("whole.png"), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string cut = write("cut.png", bytes.substr(0, 40));
  const std::string msg = error_of(cut);
  EXPECT_EQ(msg.rfind(cut + ": corrupt PNG: ", 0), 0u) << msg;
  const std::string garbled = write("garbled.png", bytes.substr(0, 8) + std::string(64, 'x'));
  EXPECT_EQ(error_of(garbled).rfind(garbled + ": corrupt PNG: ", 0), 0u) << error_of(garbled);
}

}  // namespace
}  // namespace toroid
