// SPDX-License-Identifier: Apache-2.0
// The fixture of the scene loader's tests that load scene files: writes
// text to a temporary folder and loads it with load_scene.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/scene_text.h"
#include "toroid/scene/scene_loader.h"

namespace toroid {

class SceneFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("toroid_scene_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const std::filesystem::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // Loads and returns the SceneError message ("" if it loaded).
  std::string error_of(const std::string& text) {
    const std::string p = write("bad.yml", text);
    path_ = p;
    try {
      load_scene(p);
    } catch (const SceneError& e) {
      return e.what();
    }
    return "";
  }

  void expect_error(const std::string& text, const std::string& prefix) {
    const std::string msg = error_of(text);
    EXPECT_EQ(msg.rfind(path_ + ":" + prefix, 0), 0u) << "message: " << msg << "\nexpected prefix: " << prefix;
  }

  std::filesystem::path dir_;
  std::string path_;
};

// 10 lines: the items below start on line 11.
const std::string kCamera = testing::kSceneCamera + testing::kSceneLight;

}  // namespace toroid
