// SPDX-License-Identifier: Apache-2.0
// Procedural textures for the texture-mapped scenes: stand-ins for the
// images that the RTC scenes name but do not ship (earth.yml's
// earthmap1k.ppm, skybox.yml's six faces), and the doughnut icing of
// scenes/textured-bagel.yaml. The tests write them where the scenes expect
// them; `make_textures DIR` writes them for the pictures in docs/.
//
// Each is painted through the inverse of the mapping that will read it
// (spherical_point, cube_point, the torus's own angles), from functions
// of the 3D point, so the textures have no seams where the mapping wraps.
#pragma once

#include <filesystem>
#include <string>

#include "toroid/core/canvas.h"
#include "toroid/render/uv_mapping.h"

namespace toroid::textures {

// An imaginary planet for the spherical mapping (2:1, like earthmap1k):
// oceans, continents (forest, desert, mountains), ice caps.
Canvas planet(int width, int height);

// One face (size x size) of a sky cube map for the cube mapping: blue sky
// with clouds and a sun, hazy mountains, green fields below the horizon.
Canvas sky_face(CubeFace face, int size);
// The file name that skybox.yml gives each face ("negx.ppm", ...).
std::string sky_face_file(CubeFace face);

// A glazed doughnut for the torus mapping (u around the axis, v around the
// tube): baked dough, pink icing over the top of the tube with a wavy edge,
// sprinkles. Its first and last columns (rows) are equal: it tiles.
Canvas doughnut(int width, int height);

// Writes earthmap1k.ppm (2 size x size), the six sky faces (size x size,
// PPM) and doughnut.png (2 size x size) into `dir`.
void write_scene_textures(const std::filesystem::path& dir, int size);

}  // namespace toroid::textures
