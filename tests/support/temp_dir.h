// SPDX-License-Identifier: Apache-2.0
// A fresh, empty directory for a test's files, unique to the test run and
// the given name, removed (with its contents) when the object goes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace toroid::testing {

class TempDir {
 public:
  explicit TempDir(const std::string& name)
      : path_(std::filesystem::temp_directory_path() /
              ("toroid_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" + name)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace toroid::testing
