// SPDX-License-Identifier: Apache-2.0
// scenes/textured-bagel.yaml: its committed texture is what the generator
// writes, tiles in both directions, and the scene renders icing on top.
#include <gtest/gtest.h>

#include <string>

#include "support/approx.h"
#include "textures/procedural.h"
#include "toroid/io/image_reader.h"
#include "toroid/io/image_writer.h"
#include "toroid/io/srgb.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {
namespace {

const std::string kScene = TOROID_SOURCE_DIR "/scenes/textured-bagel.yaml";
const std::string kTexture = TOROID_SOURCE_DIR "/scenes/textures/doughnut.png";

// `make_textures DIR 256` writes DIR/doughnut.png: the committed file is
// that output (to the 8-bit sRGB step of PNG).
TEST(TexturedBagel, TheCommittedTextureIsTheGeneratorsOutput) {
  const Canvas committed = read_image(kTexture);
  const Canvas generated = textures::doughnut(512, 256);
  ASSERT_EQ(committed.width(), generated.width());
  ASSERT_EQ(committed.height(), generated.height());
  int different = 0;
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 512; ++x) {
      const Color g = generated.pixel_at(x, y), c = committed.pixel_at(x, y);
      const Color coded{srgb8_to_linear(linear_to_srgb8(g.r)), srgb8_to_linear(linear_to_srgb8(g.g)),
                        srgb8_to_linear(linear_to_srgb8(g.b))};
      different += !approx_equal(c, coded, 1e-12);
    }
  EXPECT_EQ(different, 0);
}

// The first and last columns are both u = 0 (= 1), the first and last rows
// v = 1 (= 0): equal, so the torus mapping shows no seam.
TEST(TexturedBagel, TheDoughnutTextureTiles) {
  const Canvas t = textures::doughnut(200, 100);
  for (int y = 0; y < t.height(); ++y) EXPECT_APPROX(t.pixel_at(0, y), t.pixel_at(t.width() - 1, y)) << "row " << y;
  for (int x = 0; x < t.width(); ++x) EXPECT_APPROX(t.pixel_at(x, 0), t.pixel_at(x, t.height() - 1)) << "column " << x;
}

TEST(TexturedBagel, TheSceneRendersTheIcingOnTopOfTheDoughnut) {
  const Scene scene = load_scene(kScene);
  Camera camera(80, 60, scene.camera.field_of_view());
  camera.set_transform(scene.camera.transform());
  RenderOptions options;
  options.threads = 1;
  const Canvas image = render_image(camera, scene.world, options);
  // Pink icing (red well above green, blue between) where the doughnut's
  // top is, around the middle of the lower half; baked dough (red > green
  // > blue) at its front edge, below.
  int pink = 0;
  for (int y = 30; y < 45; ++y)
    for (int x = 15; x < 55; ++x) {
      const Color c = image.pixel_at(x, y);
      pink += c.r > 2 * c.g && c.b > c.g;
    }
  EXPECT_GT(pink, 150);
  const Color front = image.pixel_at(40, 50);
  EXPECT_GT(front.r, front.g) << front;
  EXPECT_GT(front.g, front.b) << front;
}

}  // namespace
}  // namespace toroid
