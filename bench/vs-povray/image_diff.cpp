// SPDX-License-Identifier: Apache-2.0
// Counts the pixels that differ between two PPM images (P3 plain or P6
// binary, maxval < 256), as toroid (.ppm) and POV-Ray (+FP) write them.
//   image_diff A.ppm B.ppm [THRESHOLD]
// A pixel differs when some channel differs by more than THRESHOLD (0..255,
// default 127: for black/white masks, the silhouettes). Prints
// "DIFFERING TOTAL PERCENT"; exit 2 on unreadable input or different sizes.
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace {

struct Image {
  int width = 0, height = 0;
  std::vector<int> samples;  // r g b per pixel, row-major
};

// Next header token, skipping whitespace and # comments.
bool token(std::istream& in, std::string& t) {
  t.clear();
  int c;
  while ((c = in.get()) != EOF) {
    if (c == '#') {
      while ((c = in.get()) != EOF && c != '\n') {
      }
    } else if (!std::isspace(c)) {
      t.push_back(static_cast<char>(c));
      break;
    }
  }
  while ((c = in.peek()) != EOF && !std::isspace(c)) t.push_back(static_cast<char>(in.get()));
  return !t.empty();
}

bool read_ppm(const char* path, Image& img) {
  std::ifstream in(path, std::ios::binary);
  std::string magic, w, h, maxval;
  if (!in || !token(in, magic) || (magic != "P3" && magic != "P6") || !token(in, w) || !token(in, h) ||
      !token(in, maxval))
    return false;
  img.width = std::atoi(w.c_str());
  img.height = std::atoi(h.c_str());
  if (img.width <= 0 || img.height <= 0 || std::atoi(maxval.c_str()) != 255) return false;
  const std::size_t n = static_cast<std::size_t>(img.width) * img.height * 3;
  img.samples.resize(n);
  if (magic == "P6") {
    in.get();  // the single whitespace after maxval
    std::vector<unsigned char> bytes(n);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(n))) return false;
    for (std::size_t i = 0; i < n; ++i) img.samples[i] = bytes[i];
  } else {
    std::string t;
    for (std::size_t i = 0; i < n; ++i) {
      if (!token(in, t)) return false;
      img.samples[i] = std::atoi(t.c_str());
    }
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: image_diff A.ppm B.ppm [THRESHOLD]\n";
    return 2;
  }
  const int threshold = argc == 4 ? std::atoi(argv[3]) : 127;
  Image a, b;
  if (!read_ppm(argv[1], a)) {
    std::cerr << "image_diff: cannot read " << argv[1] << "\n";
    return 2;
  }
  if (!read_ppm(argv[2], b)) {
    std::cerr << "image_diff: cannot read " << argv[2] << "\n";
    return 2;
  }
  if (a.width != b.width || a.height != b.height) {
    std::cerr << "image_diff: sizes differ\n";
    return 2;
  }
  long differing = 0;
  const long total = static_cast<long>(a.width) * a.height;
  for (long p = 0; p < total; ++p)
    for (int c = 0; c < 3; ++c)
      if (std::abs(a.samples[3 * p + c] - b.samples[3 * p + c]) > threshold) {
        ++differing;
        break;
      }
  std::printf("%ld %ld %.4f\n", differing, total, 100.0 * differing / total);
  return 0;
}
