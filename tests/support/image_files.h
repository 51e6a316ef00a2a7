// SPDX-License-Identifier: Apache-2.0
// The numbers an 8-bit image file holds, for tests that compare formats.
#pragma once

#include <png.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace toroid::testing {

// The samples of a plain (P3) PPM held in `text`, after its header.
inline std::vector<unsigned char> ppm_samples(const std::string& text) {
  std::istringstream in(text);
  std::string magic;
  int w = 0, h = 0, maxval = 0;
  in >> magic >> w >> h >> maxval;
  std::vector<unsigned char> v;
  for (int n; in >> n;) v.push_back(static_cast<unsigned char>(n));
  return v;
}

// A PNG file's 8-bit RGB codes as stored (no colour conversion); empty when
// it cannot be read.
inline std::vector<unsigned char> png_samples(const std::filesystem::path& file) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&img, file.c_str())) return {};
  img.format = PNG_FORMAT_RGB;
  std::vector<unsigned char> px(PNG_IMAGE_SIZE(img));
  if (!png_image_finish_read(&img, nullptr, px.data(), 0, nullptr)) return {};
  return px;
}

}  // namespace toroid::testing
