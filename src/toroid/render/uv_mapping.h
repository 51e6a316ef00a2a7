// SPDX-License-Identifier: Apache-2.0
// Mappings from a point in pattern space to (u, v) in [0, 1] x [0, 1] (RTC
// bonus chapter "Texture Mapping"), plus the torus mapping, and the inverse
// maps that procedural textures are painted with.
#pragma once

#include <functional>

#include "toroid/math/tuple.h"

namespace toroid {

struct UvCoord {
  double u = 0, v = 0;
};

using UvMapping = std::function<UvCoord(const Tuple&)>;

// Unit sphere at the origin: u = 0 at -z going round through +x, v = 0 at the
// south pole (-y) to 1 at the north pole.
UvCoord spherical_map(const Tuple& p);
// The xz-plane: u = x mod 1, v = z mod 1 (repeats every unit).
UvCoord planar_map(const Tuple& p);
// Around the y axis: u as for the sphere, v = y mod 1.
UvCoord cylindrical_map(const Tuple& p);

// A torus as the Torus shape lays it out (ring in the xy-plane, axis z):
// u = angle around the axis from +x towards +y, v = angle around the tube
// from the outer equator over the top (+z), both in turns, in [0, 1). Both
// wrap around continuously, so an image whose left and right (top and
// bottom) edges match wraps a bagel without a seam. The direction from the
// tube's centre circle is the torus's own normal (torus_normal), so spindle
// tori map too; only the radii of the torus being mapped are needed.
UvCoord toroidal_map(double major, double minor, const Tuple& p);

// Cube [-1, 1]^3 at the origin: each face is a uv square of its own.
enum class CubeFace { Left, Right, Front, Back, Up, Down };
// The face whose axis has the largest coordinate (ties: x, then y, then z).
CubeFace face_from_point(const Tuple& p);
// Front is +z, back -z, left -x, right +x, up +y, down -y. The four sides
// read left to right as seen from outside with +y at the top; the up face
// has -z at its top edge, the down face +z (the layout of OpenGL cube maps).
UvCoord cube_uv_front(const Tuple& p);
UvCoord cube_uv_back(const Tuple& p);
UvCoord cube_uv_left(const Tuple& p);
UvCoord cube_uv_right(const Tuple& p);
UvCoord cube_uv_up(const Tuple& p);
UvCoord cube_uv_down(const Tuple& p);
UvCoord cube_uv(CubeFace face, const Tuple& p);

// Inverses, for painting procedural textures: the point of the unit sphere
// at (u, v), and the point of face `face` of the cube at (u, v), so that
// spherical_map(spherical_point(uv)) == uv and likewise for the cube.
Tuple spherical_point(UvCoord uv);
Tuple cube_point(CubeFace face, UvCoord uv);

}  // namespace toroid
