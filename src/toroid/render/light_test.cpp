// lights.feature
#include "toroid/render/light.h"

#include <gtest/gtest.h>

#include "support/approx.h"

namespace toroid {
namespace {

TEST(Lights, APointLightHasAPositionAndIntensity) {
  const Color intensity{1, 1, 1};
  const Tuple position = point(0, 0, 0);
  const PointLight light{position, intensity};
  EXPECT_APPROX(light.position, position);
  EXPECT_APPROX(light.intensity, intensity);
}

}  // namespace
}  // namespace toroid
