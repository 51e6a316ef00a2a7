// SPDX-License-Identifier: Apache-2.0
// Texture mapping (RTC bonus chapter): patterns that colour a point by a uv
// pattern at the point's (u, v) under a mapping.
#pragma once

#include <array>
#include <memory>

#include "toroid/render/pattern.h"
#include "toroid/render/uv_mapping.h"
#include "toroid/render/uv_pattern.h"

namespace toroid {

// The book's texture_map(uv_pattern, mapping).
class TextureMapPattern : public Pattern {
 public:
  // Precondition: uv_pattern and mapping are set.
  TextureMapPattern(std::shared_ptr<const UvPattern> uv_pattern, UvMapping mapping)
      : uv_pattern_(std::move(uv_pattern)), mapping_(std::move(mapping)) {}
  const UvPattern& uv_pattern() const { return *uv_pattern_; }
  Color pattern_at(const Tuple& p) const override;

 private:
  std::shared_ptr<const UvPattern> uv_pattern_;
  UvMapping mapping_;
};

// The book's cube_map(left, front, right, back, up, down): a uv pattern per
// face of the cube [-1, 1]^3 (face_from_point picks it, cube_uv maps it).
class CubeMapPattern : public Pattern {
 public:
  // Precondition: every face is set.
  CubeMapPattern(std::shared_ptr<const UvPattern> left, std::shared_ptr<const UvPattern> front,
                 std::shared_ptr<const UvPattern> right, std::shared_ptr<const UvPattern> back,
                 std::shared_ptr<const UvPattern> up, std::shared_ptr<const UvPattern> down);
  Color pattern_at(const Tuple& p) const override;

 private:
  std::array<std::shared_ptr<const UvPattern>, 6> faces_;  // indexed by CubeFace
};

}  // namespace toroid
