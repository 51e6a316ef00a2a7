// SPDX-License-Identifier: Apache-2.0
// Writes the procedural textures of tests/textures/procedural.h into a
// directory: earthmap1k.ppm, the six sky faces, doughnut.png.
// Usage: make_textures DIR [SIZE]   (SIZE: the height, default 512)
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

#include "textures/procedural.h"

int main(int argc, char** argv) {
  const int size = argc > 2 ? std::atoi(argv[2]) : 512;
  if (argc < 2 || argc > 3 || size < 2 || size > 4096) {
    std::fprintf(stderr, "usage: make_textures DIR [SIZE in 2..4096, default 512]\n");
    return 2;
  }
  try {
    std::filesystem::create_directories(argv[1]);
    toroid::textures::write_scene_textures(argv[1], size);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_textures: %s\n", e.what());
    return 2;
  }
  return 0;
}
