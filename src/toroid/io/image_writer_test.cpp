#include "toroid/io/image_writer.h"
#include "toroid/io/srgb.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

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

TEST(ImageWriter, Errors) {
  const fs::path d = temp_dir("err");
  Canvas c(2, 2);
  try {
    write_image(c, (d / "x.jpg").string());
    ADD_FAILURE();
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + (d / "x.jpg").string() +
                                         "': unknown image format '.jpg' (use a .png or .ppm file name)");
  }
  const std::string missing = (d / "nodir" / "x.png").string();
  try {
    write_image(c, missing);
    ADD_FAILURE();
  } catch (const ImageWriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write '" + missing + "': No such file or directory");
  }
  EXPECT_FALSE(fs::exists(missing));
  EXPECT_TRUE(fs::is_empty(d));
  fs::remove_all(d);
}

}  // namespace
}  // namespace toroid
