// SPDX-License-Identifier: Apache-2.0
#include "toroid/scene/scene_loader.h"

#include <gtest/gtest.h>

#include "support/scene_text.h"
#include "support/shared_dir.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "toroid/scene/scene_files_test_fixture.h"
#include "toroid/shapes/csg.h"
#include "toroid/shapes/group.h"
#include "toroid/shapes/torus.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

const fs::path kScenes = fs::path(TOROID_SHARED_DIR) / "rtc-scenes";

struct Expected {
  const char* file;
  std::size_t lights, objects;
  int width, height;
  double fov;
};

TEST(SceneLoader, LoadsTheSharedScenes) {
  TOROID_REQUIRE_SHARED_DIR();
  const Expected cases[] = {
      {"align-check-plane.yml", 1, 1, 400, 400, 0.5},
      {"chap7-putting-it-together.yml", 1, 6, 100, 50, 1.047},
      {"checkered-cube.yml", 4, 8, 800, 400, 0.8},
      {"checkered-cylinder.yml", 1, 1, 400, 400, 0.5},
      {"checkered-plane.yml", 1, 1, 400, 400, 0.5},
      {"checkered-sphere.yml", 1, 1, 400, 400, 0.5},
      {"cover.yml", 2, 19, 100, 100, 0.785},
      {"csg_difference.kjeldahl.yml", 1, 3, 300, 150, 1.152},
      {"cylinders.yml", 1, 11, 800, 400, 0.7854},
      {"group.yml", 4, 4, 300, 100, 0.9},
      {"reflect-refract.yml", 1, 13, 400, 200, 1.152},
      // Its one light is a 10 x 10 area light (SceneFiles.LoadsAnAreaLight).
      {"shadow-glamour-shot.yml", 0, 4, 1920, 1080, 0.7854},
      {"table.yml", 1, 18, 400, 200, 0.785},
      {"three-spheres.yml", 1, 6, 1000, 500, 1.0472},
  };
  for (const Expected& e : cases) {
    SCOPED_TRACE(e.file);
    const Scene s = load_scene((kScenes / e.file).string());
    EXPECT_EQ(s.world.lights.size(), e.lights);
    EXPECT_EQ(s.world.objects.size(), e.objects);
    EXPECT_EQ(s.camera.hsize(), e.width);
    EXPECT_EQ(s.camera.vsize(), e.height);
  }
}

TEST(SceneLoader, SharedCameraParameters) {
  TOROID_REQUIRE_SHARED_DIR();
  const Scene s = load_scene((kScenes / "cover.yml").string());
  EXPECT_DOUBLE_EQ(s.camera.field_of_view(), 0.785);
  EXPECT_TRUE(approx_equal(s.world.lights[1].position, point(-400, 50, -10)));
}

// The shared directory ships no texture images: the two scenes that need
// them stop at the first image, naming it and where it was looked for.
TEST(SceneLoader, TextureScenesWithoutTheirImagesNameTheMissingFile) {
  TOROID_REQUIRE_SHARED_DIR();
  const struct {
    const char* scene;
    const char* position;
    const char* image;
  } cases[] = {{"earth.yml", "48:15", "earthmap1k.ppm"}, {"skybox.yml", "36:15", "negx.ppm"}};
  for (const auto& c : cases) {
    const std::string path = (kScenes / c.scene).string();
    try {
      load_scene(path);
      ADD_FAILURE() << c.scene << " loaded";
    } catch (const SceneError& e) {
      EXPECT_EQ(std::string(e.what()), path + ":" + c.position + ": image file '" + c.image +
                                           "' not found (looked for '" + (kScenes / c.image).string() + "')");
    }
  }
}

TEST_F(SceneFiles, LoadsATorusWithDefinesAndCsg) {
  const std::string p = write("t.yml", kCamera +
                                           "- define: glaze\n"
                                           "  value:\n"
                                           "    color: [1, 0.5, 0.6]\n"
                                           "    specular: 0.5\n"
                                           "- define: pink\n"
                                           "  extend: glaze\n"
                                           "  value:\n"
                                           "    ambient: 0.3\n"
                                           "- define: flat\n"
                                           "  value:\n"
                                           "    - [rotate-x, 1.5708]\n"
                                           "- add: torus\n"
                                           "  major: 2\n"
                                           "  minor: 0.5\n"
                                           "  solver: tianheng\n"
                                           "  material: pink\n"
                                           "  transform: [flat, [translate, 0, 1, 0]]\n"
                                           "- add: torus\n"
                                           "- add: csg\n"
                                           "  operation: difference\n"
                                           "  left: {add: torus}\n"
                                           "  right: {type: cube, transform: [[translate, 1, 0, 0]]}\n");
  const Scene s = load_scene(p);
  ASSERT_EQ(s.world.objects.size(), 3u);
  auto* t = dynamic_cast<Torus*>(s.world.objects[0].get());
  ASSERT_NE(t, nullptr);
  EXPECT_DOUBLE_EQ(t->major(), 2);
  EXPECT_DOUBLE_EQ(t->minor(), 0.5);
  EXPECT_EQ(t->solver(), TorusSolver::Tianheng);
  EXPECT_TRUE(approx_equal(t->material().color, Color{1, 0.5, 0.6}));
  EXPECT_DOUBLE_EQ(t->material().specular, 0.5);
  EXPECT_DOUBLE_EQ(t->material().ambient, 0.3);
  // rotate-x first, then the translation.
  EXPECT_TRUE(approx_equal(t->transform() * point(0, 0, 1), point(0, 0, 0)));
  auto* d = dynamic_cast<Torus*>(s.world.objects[1].get());
  ASSERT_NE(d, nullptr);
  EXPECT_DOUBLE_EQ(d->major(), 1);
  EXPECT_DOUBLE_EQ(d->minor(), 0.25);
  EXPECT_NE(dynamic_cast<Csg*>(s.world.objects[2].get()), nullptr);
  EXPECT_EQ(s.camera.hsize(), 40);

  SceneLoadOptions o;
  o.solver = TorusSolver::Ferrari;
  const Scene f = load_scene(p, o);
  EXPECT_EQ(dynamic_cast<Torus*>(f.world.objects[0].get())->solver(), TorusSolver::Ferrari);
}

TEST_F(SceneFiles, LoadsAPartialTorusAndASpindleChoice) {
  const Scene s = load_scene(write("p.yml", kCamera + "- add: torus\n"
                                                      "  theta-max: 3.14159\n"
                                                      "  phi-min: -1.5\n"
                                                      "  phi-max: 2\n"
                                                      "- add: torus\n"
                                                      "  minor: 2\n"
                                                      "  spindle: outer\n"
                                                      "  theta-max: 6.2832\n"
                                                      "- add: torus\n"
                                                      "  spindle: whole\n"));
  ASSERT_EQ(s.world.objects.size(), 3u);
  const auto* a = dynamic_cast<const Torus*>(s.world.objects[0].get());
  ASSERT_NE(a, nullptr);
  EXPECT_DOUBLE_EQ(a->sweep().theta_max, 3.14159);
  EXPECT_DOUBLE_EQ(a->sweep().phi_min, -1.5);
  EXPECT_DOUBLE_EQ(a->sweep().phi_max, 2);
  EXPECT_EQ(a->spindle(), SpindleSurface::Whole);
  const auto* b = dynamic_cast<const Torus*>(s.world.objects[1].get());
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->spindle(), SpindleSurface::Outer);
  // 6.2832 is 2 pi as written to four decimals: the whole turn.
  EXPECT_TRUE(b->sweep().whole());
  const auto* c = dynamic_cast<const Torus*>(s.world.objects[2].get());
  ASSERT_NE(c, nullptr);
  EXPECT_TRUE(c->sweep().whole());
  EXPECT_EQ(c->spindle(), SpindleSurface::Whole);
}

TEST_F(SceneFiles, LoadsAnAreaLight) {
  const Scene s = load_scene(write("a.yml", kCamera + "- add: light\n"
                                                      "  corner: [-1, 2, 4]\n"
                                                      "  uvec: [2, 0, 0]\n"
                                                      "  vvec: [0, 2, 0]\n"
                                                      "  usteps: 4\n"
                                                      "  vsteps: 2\n"
                                                      "  jitter: true\n"
                                                      "  intensity: [1.5, 1.5, 1.5]\n"));
  ASSERT_EQ(s.world.lights.size(), 1u);  // kCamera's point light
  ASSERT_EQ(s.world.area_lights.size(), 1u);
  const AreaLight& l = s.world.area_lights[0];
  EXPECT_TRUE(approx_equal(l.corner, point(-1, 2, 4)));
  EXPECT_TRUE(approx_equal(l.uvec, vector(0.5, 0, 0)));
  EXPECT_TRUE(approx_equal(l.vvec, vector(0, 1, 0)));
  EXPECT_EQ(l.usteps, 4);
  EXPECT_EQ(l.vsteps, 2);
  EXPECT_EQ(l.samples, 8);
  EXPECT_TRUE(l.jitter);
  EXPECT_TRUE(approx_equal(l.intensity, Color{1.5, 1.5, 1.5}));
}

// Memory: shapes of equal material share one block (a shape holds a
// pointer to it).
TEST_F(SceneFiles, ShapesOfEqualMaterialShareIt) {
  const Scene s = load_scene(write("m.yml", kCamera + "- define: white-material\n"
                                                      "  value:\n"
                                                      "    color: [1, 1, 1]\n"
                                                      "    specular: 0.2\n"
                                                      "- add: torus\n"
                                                      "  material: white-material\n"
                                                      "- add: sphere\n"
                                                      "  material: white-material\n"
                                                      "- add: cube\n"
                                                      "  material: {color: [1, 1, 1], specular: 0.2}\n"
                                                      "- add: plane\n"
                                                      "  material: {color: [1, 1, 1], specular: 0.3}\n"
                                                      "- add: group\n"
                                                      "  material: white-material\n"
                                                      "  children: [{add: cone}]\n"));
  ASSERT_EQ(s.world.objects.size(), 5u);
  Shape& torus = *s.world.objects[0];
  const Shape& sphere = *s.world.objects[1];
  const Shape& cube = *s.world.objects[2];
  const Shape& plane = *s.world.objects[3];
  const auto& group = dynamic_cast<const Group&>(*s.world.objects[4]);
  ASSERT_EQ(group.children().size(), 1u);
  EXPECT_EQ(&torus.material(), &sphere.material());  // the same define
  EXPECT_EQ(&torus.material(), &cube.material());    // the same values written out
  EXPECT_EQ(&torus.material(), &group.material());
  EXPECT_EQ(&torus.material(), &group.children()[0]->material());  // inherited
  EXPECT_NE(&torus.material(), &plane.material());
  EXPECT_DOUBLE_EQ(plane.material().specular, 0.3);

  // Changing one shape's material leaves the others' alone.
  Material red = torus.material();
  red.color = Color{1, 0, 0};
  torus.set_material(red);
  EXPECT_TRUE(approx_equal(torus.material().color, Color{1, 0, 0}));
  EXPECT_TRUE(approx_equal(sphere.material().color, Color{1, 1, 1}));
  EXPECT_TRUE(approx_equal(cube.material().color, Color{1, 1, 1}));
  EXPECT_DOUBLE_EQ(sphere.material().specular, 0.2);
}

TEST_F(SceneFiles, MaterialsWithTheirOwnPatternsAreNotShared) {
  // Each use of a pattern makes its own; a torus mapping takes its torus's radii.
  const Scene s = load_scene(write("p.yml", kCamera + "- define: stripy\n"
                                                      "  value:\n"
                                                      "    pattern: {type: stripes, colors: [[1, 1, 1], [0, 0, 0]]}\n"
                                                      "- add: sphere\n"
                                                      "  material: stripy\n"
                                                      "- add: sphere\n"
                                                      "  material: stripy\n"));
  ASSERT_EQ(s.world.objects.size(), 2u);
  const Material& a = s.world.objects[0]->material();
  const Material& b = s.world.objects[1]->material();
  ASSERT_NE(a.pattern, nullptr);
  ASSERT_NE(b.pattern, nullptr);
  EXPECT_NE(a.pattern, b.pattern);
  EXPECT_NE(&a, &b);
}

TEST(SceneLoader, TheGlamourShotHasAJitteredAreaLight) {
  TOROID_REQUIRE_SHARED_DIR();
  const Scene s = load_scene((kScenes / "shadow-glamour-shot.yml").string());
  ASSERT_EQ(s.world.area_lights.size(), 1u);
  const AreaLight& l = s.world.area_lights[0];
  EXPECT_EQ(l.samples, 100);
  EXPECT_TRUE(l.jitter);
  EXPECT_TRUE(approx_equal(l.uvec, vector(0.2, 0, 0)));
}

TEST(SceneLoader, TheProjectScenesLoad) {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(TOROID_SOURCE_DIR) / "scenes")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    const Scene s = load_scene(entry.path().string());
    EXPECT_FALSE(s.world.objects.empty());
    EXPECT_FALSE(s.world.lights.empty() && s.world.area_lights.empty());
    ++scenes;
  }
  EXPECT_GE(scenes, 4);  // bagels, half-eaten-doughnut, spindle-torus, soft-shadow-doughnut
}

}  // namespace
}  // namespace toroid
