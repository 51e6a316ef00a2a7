// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/light.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>

#include "toroid/math/hash.h"

namespace toroid {

AreaLight::AreaLight(const Tuple& corner_, const Tuple& full_uvec, int usteps_, const Tuple& full_vvec, int vsteps_,
                     const Color& intensity_, bool jitter_)
    : corner(corner_),
      uvec(full_uvec / usteps_),
      usteps(usteps_),
      vvec(full_vvec / vsteps_),
      vsteps(vsteps_),
      samples(usteps_ * vsteps_),
      intensity(intensity_),
      jitter(jitter_) {}

std::uint64_t AreaLight::jitter_key(const Tuple& p) const {
  if (!jitter) return 0;
  // The point on a grid of 2^-36 times its largest coordinate's power of
  // two: a point that moves by a few roundings (another order of
  // operations, a fused multiply-add, another way to intersect a shape)
  // keeps its cell, and so its samples, but for the rare one beside a
  // cell's edge; the points of neighbouring pixels lie many cells apart.
  const double largest = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  std::uint64_t cell[3] = {0, 0, 0};
  if (largest > 0 && std::isfinite(largest)) {
    const int shift = 36 - std::ilogb(largest);
    const double coordinates[3] = {p.x, p.y, p.z};
    for (int i = 0; i < 3; ++i)
      cell[i] = static_cast<std::uint64_t>(std::llround(std::scalbn(coordinates[i], shift)));  // |.| < 2^38
  }
  return splitmix64(cell[0] ^ splitmix64(cell[1] ^ splitmix64(cell[2])));
}

Tuple AreaLight::sample(std::uint64_t key, int u, int v) const {
  if (!jitter) return point_on_light(u, v);
  const std::uint64_t cell =
      static_cast<std::uint64_t>(v) * static_cast<std::uint64_t>(usteps) + static_cast<std::uint64_t>(u);
  // One hash per sample; its two 32-bit halves are the offsets.
  const std::uint64_t h = splitmix64(key ^ (cell * 0x632be59bd9b4e019ULL));
  constexpr double k2to32 = 0x1.0p-32;
  return point_on_light(u, v, static_cast<double>(h >> 32) * k2to32, static_cast<double>(h & 0xffffffffULL) * k2to32);
}

bool AreaLight::in_front_of(const Tuple& p, const Tuple& normalv) const {
  // The samples are convex combinations of the four corners.
  const Tuple full_u = uvec * usteps, full_v = vvec * vsteps;
  for (const Tuple& c : {corner, corner + full_u, corner + full_v, corner + full_u + full_v})
    if (dot(c - p, normalv) >= 0) return true;
  return false;
}

}  // namespace toroid
