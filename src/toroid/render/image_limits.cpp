// SPDX-License-Identifier: Apache-2.0
#include "toroid/render/image_limits.h"

namespace toroid {

std::string image_size_error(std::int64_t width, std::int64_t height) {
  const std::string range = "1.." + std::to_string(kMaxImageSide);
  if (width < 1 || width > kMaxImageSide) return "width must be in " + range + ", got " + std::to_string(width);
  if (height < 1 || height > kMaxImageSide) return "height must be in " + range + ", got " + std::to_string(height);
  if (width * height > kMaxImagePixels)
    return std::to_string(width) + "x" + std::to_string(height) + " is " + std::to_string(width * height) +
           " pixels, more than the limit of " + std::to_string(kMaxImagePixels) + " (8192x8192)";
  return {};
}

}  // namespace toroid
