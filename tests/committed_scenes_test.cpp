// SPDX-License-Identifier: Apache-2.0
// The scenes under scenes/ (the default scene, the chapter pictures, the
// stress scenes) load and render, and the chapter-15 mesh is what its
// generator (tools/teapot_obj.py) says it is.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "toroid/render/camera.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/obj_file.h"
#include "toroid/scene/scene_loader.h"
#include "toroid/shapes/group.h"

namespace toroid {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(TOROID_SOURCE_DIR) / "scenes";

std::vector<std::filesystem::path> committed_scenes() {
  std::vector<std::filesystem::path> out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(kScenes))
    if (e.path().extension() == ".yaml") out.push_back(e.path());
  return out;
}

TEST(CommittedScenes, EveryOneLoadsAndRendersASmallImage) {
  const auto scenes = committed_scenes();
  ASSERT_GE(scenes.size(), 20u);  // 12 chapters, 8 stress scenes, the README's
  for (const auto& path : scenes) {
    SCOPED_TRACE(path.string());
    Scene scene = load_scene(path.string());
    EXPECT_FALSE(scene.world.objects.empty());
    Camera small(16, 12, scene.camera.field_of_view());
    small.set_transform(scene.camera.transform());
    const Canvas image = render(small, scene.world);
    int lit = 0;
    for (const Color& c : image.pixels()) lit += c.r + c.g + c.b > 0;
    EXPECT_GT(lit, 0) << "nothing in view";
  }
}

TEST(CommittedScenes, TheTeapotMeshHasItsNamedGroupsAndFanTriangulatedBottom) {
  const ObjFile obj = parse_obj_file(kScenes / "rtc-chapters" / "teapot.obj");
  EXPECT_EQ(obj.vertices.size(), obj.normals.size());  // one normal per vertex
  std::vector<std::string> names;
  for (const auto& [name, group] : obj.groups) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"body", "bottom", "lid", "knob", "spout", "handle"}));
  // The bottom is one 32-sided polygon: a fan of 30 triangles.
  EXPECT_EQ(obj.group("bottom")->size(), 30u);
  EXPECT_TRUE(obj.default_group->children().empty());
}

}  // namespace
}  // namespace toroid
