#include "toroid/render/light.h"

#include <bit>
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

void AreaLight::jitter_at(const Tuple& p, int u, int v, double& ju, double& jv) const {
  if (!jitter) {
    ju = jv = 0.5;
    return;
  }
  const std::uint64_t key = splitmix64(std::bit_cast<std::uint64_t>(p.x) ^
                                       splitmix64(std::bit_cast<std::uint64_t>(p.y) ^
                                                  splitmix64(std::bit_cast<std::uint64_t>(p.z))));
  const std::uint64_t cell = static_cast<std::uint64_t>(v) * static_cast<std::uint64_t>(usteps) +
                             static_cast<std::uint64_t>(u);
  const std::uint64_t h1 = splitmix64(key ^ (cell * 0x632be59bd9b4e019ULL));
  ju = unit_interval(h1);
  jv = unit_interval(splitmix64(h1));
}

bool AreaLight::in_front_of(const Tuple& p, const Tuple& normalv) const {
  // The samples are convex combinations of the four corners.
  const Tuple full_u = uvec * usteps, full_v = vvec * vsteps;
  for (const Tuple& c : {corner, corner + full_u, corner + full_v, corner + full_u + full_v})
    if (dot(c - p, normalv) >= 0) return true;
  return false;
}

}  // namespace toroid
