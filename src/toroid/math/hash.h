// SPDX-License-Identifier: Apache-2.0
// Deterministic pseudo-random numbers from keys: the renderer's sample
// jitter and the area lights' jitter, so images do not depend on threads.
#pragma once

#include <cstdint>

namespace toroid {

// SplitMix64's finaliser: a well-mixed 64-bit hash of z.
constexpr std::uint64_t splitmix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The top 53 bits of `bits` as a double in [0, 1).
constexpr double unit_interval(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

}  // namespace toroid
