// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/texture_map.h"

namespace toroid {

Color TextureMapPattern::pattern_at(const Tuple& p) const {
  const UvCoord uv = mapping_(p);
  return uv_pattern_->uv_pattern_at(uv.u, uv.v);
}

CubeMapPattern::CubeMapPattern(std::shared_ptr<const UvPattern> left, std::shared_ptr<const UvPattern> front,
                               std::shared_ptr<const UvPattern> right, std::shared_ptr<const UvPattern> back,
                               std::shared_ptr<const UvPattern> up, std::shared_ptr<const UvPattern> down) {
  faces_[static_cast<int>(CubeFace::Left)] = std::move(left);
  faces_[static_cast<int>(CubeFace::Front)] = std::move(front);
  faces_[static_cast<int>(CubeFace::Right)] = std::move(right);
  faces_[static_cast<int>(CubeFace::Back)] = std::move(back);
  faces_[static_cast<int>(CubeFace::Up)] = std::move(up);
  faces_[static_cast<int>(CubeFace::Down)] = std::move(down);
}

Color CubeMapPattern::pattern_at(const Tuple& p) const {
  const CubeFace face = face_from_point(p);
  const UvCoord uv = cube_uv(face, p);
  return faces_[static_cast<int>(face)]->uv_pattern_at(uv.u, uv.v);
}

}  // namespace toroid
