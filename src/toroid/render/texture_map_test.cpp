// SPDX-License-Identifier: Apache-2.0
// Texture mapping bonus chapter: texture_map and cube_map patterns; then a
// texture on a torus (beyond the book).
#include "toroid/render/texture_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "support/approx.h"
#include "toroid/math/transform.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

const Color black{0, 0, 0};
const Color white{1, 1, 1};

TEST(TextureMap, UsingATextureMapPatternWithASphericalMap) {
  const TextureMapPattern pattern(std::make_shared<UvCheckers>(16, 8, black, white), spherical_map);
  EXPECT_APPROX(pattern.pattern_at(point(0.4315, 0.4670, 0.7719)), white);
  EXPECT_APPROX(pattern.pattern_at(point(-0.9654, 0.2552, -0.0534)), black);
  EXPECT_APPROX(pattern.pattern_at(point(0.1039, 0.7090, 0.6975)), white);
  EXPECT_APPROX(pattern.pattern_at(point(-0.4986, -0.7856, -0.3663)), black);
  EXPECT_APPROX(pattern.pattern_at(point(-0.0317, -0.9395, 0.3411)), black);
  EXPECT_APPROX(pattern.pattern_at(point(0.4809, -0.7721, 0.4154)), black);
  EXPECT_APPROX(pattern.pattern_at(point(0.0285, -0.9612, -0.2745)), black);
  EXPECT_APPROX(pattern.pattern_at(point(-0.5734, -0.2162, -0.7903)), white);
  EXPECT_APPROX(pattern.pattern_at(point(0.7688, -0.1470, 0.6223)), black);
  EXPECT_APPROX(pattern.pattern_at(point(-0.7652, 0.2175, 0.6060)), black);
}

TEST(TextureMap, FindingTheColorsOnAMappedCube) {
  const Color red{1, 0, 0}, yellow{1, 1, 0}, brown{1, 0.5, 0}, green{0, 1, 0}, cyan{0, 1, 1}, blue{0, 0, 1},
      purple{1, 0, 1};
  const CubeMapPattern pattern(std::make_shared<UvAlignCheck>(yellow, cyan, red, blue, brown),      // left
                               std::make_shared<UvAlignCheck>(cyan, red, yellow, brown, green),     // front
                               std::make_shared<UvAlignCheck>(red, yellow, purple, green, white),   // right
                               std::make_shared<UvAlignCheck>(green, purple, cyan, white, blue),    // back
                               std::make_shared<UvAlignCheck>(brown, cyan, purple, red, yellow),    // up
                               std::make_shared<UvAlignCheck>(purple, brown, green, blue, white));  // down
  const struct {
    const char* id;
    Tuple p;
    Color c;
  } examples[] = {
      {"L1", point(-1, 0, 0), yellow},     {"L2", point(-1, 0.9, -0.9), cyan},  {"L3", point(-1, 0.9, 0.9), red},
      {"L4", point(-1, -0.9, -0.9), blue}, {"L5", point(-1, -0.9, 0.9), brown}, {"F1", point(0, 0, 1), cyan},
      {"F2", point(-0.9, 0.9, 1), red},    {"F3", point(0.9, 0.9, 1), yellow},  {"F4", point(-0.9, -0.9, 1), brown},
      {"F5", point(0.9, -0.9, 1), green},  {"R1", point(1, 0, 0), red},         {"R2", point(1, 0.9, 0.9), yellow},
      {"R3", point(1, 0.9, -0.9), purple}, {"R4", point(1, -0.9, 0.9), green},  {"R5", point(1, -0.9, -0.9), white},
      {"B1", point(0, 0, -1), green},      {"B2", point(0.9, 0.9, -1), purple}, {"B3", point(-0.9, 0.9, -1), cyan},
      {"B4", point(0.9, -0.9, -1), white}, {"B5", point(-0.9, -0.9, -1), blue}, {"U1", point(0, 1, 0), brown},
      {"U2", point(-0.9, 1, -0.9), cyan},  {"U3", point(0.9, 1, -0.9), purple}, {"U4", point(-0.9, 1, 0.9), red},
      {"U5", point(0.9, 1, 0.9), yellow},  {"D1", point(0, -1, 0), purple},     {"D2", point(-0.9, -1, 0.9), brown},
      {"D3", point(0.9, -1, 0.9), green},  {"D4", point(-0.9, -1, -0.9), blue}, {"D5", point(0.9, -1, -0.9), white},
  };
  for (const auto& e : examples) {
    SCOPED_TRACE(e.id);
    EXPECT_APPROX(pattern.pattern_at(e.p), e.c);
  }
}

// Beyond the book: 8 x 4 checkers around a transformed torus. The shape's
// transform is undone before the mapping (pattern_at_shape), so the squares
// follow the torus: columns are eighths of a turn round the axis, rows
// quarters of a turn round the tube.
TEST(TextureMap, ACheckeredTorusThroughItsTransform) {
  Torus torus(2, 0.5);
  // Object (x, y, z) is world (x, z + 1, -y): the axis along world +y.
  torus.set_transform(translation(0, 1, 0) * rotation_x(-std::numbers::pi / 2));
  const TextureMapPattern pattern(std::make_shared<UvCheckers>(8, 4, black, white),
                                  [](const Tuple& p) { return toroidal_map(2, 0.5, p); });
  // Object (2.5, 0.1, 0): outer equator, u = 0.006: column 0, row 0.
  EXPECT_APPROX(pattern.pattern_at_shape(torus, point(2.5, 1, -0.1)), black);
  // Object (0.1, 2.5, 0): u = 0.244, column 1.
  EXPECT_APPROX(pattern.pattern_at_shape(torus, point(0.1, 1, -2.5)), white);
  // Object (-0.1, 2.5, 0): u = 0.256, column 2.
  EXPECT_APPROX(pattern.pattern_at_shape(torus, point(-0.1, 1, -2.5)), black);
  // Object (2.01, 0, 0.5), (1.99, 0, 0.5): either side of the top of the
  // tube (v = 0.25), rows 0 and 1.
  EXPECT_APPROX(pattern.pattern_at_shape(torus, point(2.01, 1.5, 0)), black);
  EXPECT_APPROX(pattern.pattern_at_shape(torus, point(1.99, 1.5, 0)), white);
}

}  // namespace
}  // namespace toroid
