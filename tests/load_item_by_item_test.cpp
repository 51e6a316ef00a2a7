// SPDX-License-Identifier: Apache-2.0
// Every scene file we have loads to the same world item by item (the default,
// src/toroid/scene/yaml_items.h) as from its whole YAML document: the same
// small render, pixel for pixel; and every bad scene of the corpus gives the
// same message both ways.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "support/shared_dir.h"
#include "support/temp_dir.h"
#include "textures/procedural.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> files_in(const fs::path& dir, const std::vector<std::string>& extensions) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    for (const auto& ext : extensions)
      if (e.path().extension() == ext) out.push_back(e.path());
  return out;
}

Canvas render_tiny(const std::string& path, bool whole_document) {
  SceneLoadOptions options;
  options.whole_document = whole_document;
  const Scene scene = load_scene(path, options);
  Camera camera(16, 12, scene.camera.field_of_view());
  camera.set_transform(scene.camera.transform());
  RenderOptions render_options;
  render_options.threads = 1;
  return render_image(camera, scene.world, render_options);
}

void expect_same_render_both_ways(const fs::path& scene) {
  SCOPED_TRACE(scene.string());
  const Canvas by_item = render_tiny(scene.string(), false);
  const Canvas whole = render_tiny(scene.string(), true);
  ASSERT_EQ(by_item.pixels().size(), whole.pixels().size());
  int different = 0;
  for (std::size_t i = 0; i < whole.pixels().size(); ++i) {
    const Color a = by_item.pixels()[i], b = whole.pixels()[i];
    different += a.r != b.r || a.g != b.g || a.b != b.b;
  }
  EXPECT_EQ(different, 0);
}

TEST(LoadItemByItem, EveryCommittedSceneRendersAsFromTheWholeDocument) {
  const auto scenes = files_in(fs::path(TOROID_SOURCE_DIR) / "scenes", {".yaml"});
  ASSERT_GE(scenes.size(), 20u);
  for (const auto& scene : scenes) expect_same_render_both_ways(scene);
}

TEST(LoadItemByItem, EverySharedSceneRendersAsFromTheWholeDocument) {
  TOROID_REQUIRE_SHARED_DIR();
  // Beside stand-ins for the images that earth.yml and skybox.yml name.
  const testing::TempDir dir("load_item_by_item");
  textures::write_scene_textures(dir.path(), 8);
  const auto scenes = files_in(fs::path(TOROID_SHARED_DIR) / "rtc-scenes", {".yml", ".yaml"});
  ASSERT_GE(scenes.size(), 16u);
  for (const auto& scene : scenes) {
    fs::copy_file(scene, dir.path() / scene.filename());
    expect_same_render_both_ways(dir.path() / scene.filename());
  }
}

TEST(LoadItemByItem, EveryBadSceneOfTheCorpusGivesTheSameMessageBothWays) {
  const auto scenes = files_in(fs::path(TOROID_SOURCE_DIR) / "tests" / "bad-input" / "scene", {".yml"});
  ASSERT_GE(scenes.size(), 70u);
  for (const auto& scene : scenes) {
    SCOPED_TRACE(scene.string());
    std::string messages[2];
    for (const bool whole_document : {false, true}) {
      SceneLoadOptions options;
      options.whole_document = whole_document;
      try {
        load_scene(scene.string(), options);
      } catch (const SceneError& e) {
        messages[whole_document] = e.what();
      }
    }
    EXPECT_FALSE(messages[0].empty()) << "it loaded";
    EXPECT_EQ(messages[0], messages[1]);
  }
}

}  // namespace
}  // namespace toroid
