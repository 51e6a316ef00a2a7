// SPDX-License-Identifier: Apache-2.0
// Light sources: the point light (RTC chapter 6) and the rectangular area
// light of the bonus chapter "Soft shadows".
#pragma once

#include <cstdint>

#include "toroid/math/color.h"
#include "toroid/math/tuple.h"

namespace toroid {

struct PointLight {
  Tuple position = point(0, 0, 0);
  Color intensity{1, 1, 1};
};

// A parallelogram of light from `corner` along the full edges full_uvec and
// full_vvec, cut into usteps x vsteps cells with one sample each: a shade
// sends one shadow ray per cell and averages the cells' diffuse and specular
// light. With `jitter` each sample lies at a pseudo-random place in its cell,
// a hash of the shaded point and the cell (see sample), which trades the
// banding of fixed samples for noise and keeps every render identical.
struct AreaLight {
  // Preconditions: usteps >= 1, vsteps >= 1.
  AreaLight(const Tuple& corner, const Tuple& full_uvec, int usteps, const Tuple& full_vvec, int vsteps,
            const Color& intensity, bool jitter = false);

  Tuple corner;
  Tuple uvec;  // one cell's edge: full_uvec / usteps
  int usteps;
  Tuple vvec;  // full_vvec / vsteps
  int vsteps;
  int samples;  // usteps * vsteps
  Color intensity;
  bool jitter;

  // The sample of cell (u, v) at offset (ju, jv) in [0, 1) within the cell;
  // the cell's centre by default.
  Tuple point_on_light(int u, int v, double ju = 0.5, double jv = 0.5) const {
    return corner + uvec * (u + ju) + vvec * (v + jv);
  }
  // What places every cell's jittered sample when shading `point`: a hash of
  // the point's coordinates read to about 2^-36 of its size, so that the
  // noise does not move with the last bits of the point (computed once per
  // shade).
  std::uint64_t jitter_key(const Tuple& point) const;
  // The sample of cell (u, v) for a jitter key: the cell's centre without
  // jitter, else an offset in [0, 1)^2 within the cell hashed from the key and
  // the cell.
  Tuple sample(std::uint64_t jitter_key, int u, int v) const;
  // Whether some of the light lies in front of (or on) the plane through
  // `point` with normal `normalv`: if not, no sample can light the point.
  bool in_front_of(const Tuple& point, const Tuple& normalv) const;
};

}  // namespace toroid
