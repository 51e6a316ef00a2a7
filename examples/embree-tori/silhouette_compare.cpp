// SPDX-License-Identifier: Apache-2.0
// silhouette-compare A.png B.png: whether the two images show an object in
// the same pixels. A pixel shows one when it is not black (both renderers
// give every surface some ambient light and leave the background black).
// Prints the counts; exits 0 when the masks match and are not empty, 1 when
// they differ, 2 for an unreadable image or a size mismatch.
#include <png.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Image {
  unsigned width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Image read_png(const char* path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&image, path))
    throw std::runtime_error(std::string("cannot read '") + path + "': " + image.message);
  image.format = PNG_FORMAT_RGB;
  Image out;
  out.width = image.width;
  out.height = image.height;
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  if (!png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr)) {
    png_image_free(&image);
    throw std::runtime_error(std::string("cannot read '") + path + "': " + image.message);
  }
  return out;
}

bool lit(const Image& im, std::size_t i) { return im.rgb[3 * i] || im.rgb[3 * i + 1] || im.rgb[3 * i + 2]; }

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: silhouette-compare A.png B.png\n");
    return 2;
  }
  try {
    const Image a = read_png(argv[1]), b = read_png(argv[2]);
    if (a.width != b.width || a.height != b.height) {
      std::fprintf(stderr, "silhouette-compare: %s is %ux%u, %s is %ux%u\n", argv[1], a.width, a.height, argv[2],
                   b.width, b.height);
      return 2;
    }
    const std::size_t n = std::size_t(a.width) * a.height;
    std::size_t in_a = 0, in_b = 0, differ = 0, shown = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const bool la = lit(a, i), lb = lit(b, i);
      in_a += la, in_b += lb;
      if (la != lb) {
        ++differ;
        if (shown++ < 20)
          std::printf("  pixel (%zu, %zu): %s in %s only\n", i % a.width, i / a.width, "object",
                      la ? argv[1] : argv[2]);
      }
    }
    std::printf("%ux%u pixels; object pixels: %zu in %s, %zu in %s; differing: %zu\n", a.width, a.height, in_a, argv[1],
                in_b, argv[2], differ);
    if (in_a == 0) {
      std::fprintf(stderr, "silhouette-compare: %s shows nothing\n", argv[1]);
      return 1;
    }
    return differ == 0 ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "silhouette-compare: %s\n", e.what());
    return 2;
  }
}
