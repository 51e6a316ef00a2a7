// End to end: the built `toroid render` binary.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

int run(const std::string& args, std::string* err = nullptr) {
  const fs::path errf = fs::temp_directory_path() / ("toroid_render_err_" + std::to_string(::getpid()));
  const std::string cmd = std::string(TOROID_BINARY) + " " + args + " 2>" + errf.string();
  const int status = std::system(cmd.c_str());
  if (err) {
    std::ifstream in(errf);
    std::stringstream ss;
    ss << in.rdbuf();
    *err = ss.str();
  }
  fs::remove(errf);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class RenderCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("toroid_render_cmd_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

const std::string kScene = std::string(TOROID_SOURCE_DIR) + "/scenes/bagels.yaml";

TEST_F(RenderCommand, RendersThePngAndReports) {
  const fs::path out = dir_ / "b.png";
  std::string err;
  ASSERT_EQ(run("render " + kScene + " -o " + out.string() + " --width 40 --height 30 --threads 2 --samples 4", &err), 0)
      << err;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_NE(err.find("40x30, 4 samples, 2 threads, "), std::string::npos) << err;
  EXPECT_NE(err.find(" Mrays/s"), std::string::npos) << err;
}

TEST_F(RenderCommand, UsageErrorsExit2) {
  const std::string out = (dir_ / "b.png").string();
  EXPECT_EQ(run("render " + kScene + " -o " + out + " --samples 0"), 2);
  EXPECT_EQ(run("render " + kScene + " -o " + out + " --threads 0"), 2);
  EXPECT_EQ(run("render " + kScene + " -o " + out + " --solver nope"), 2);
  EXPECT_EQ(run("render " + kScene), 2);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(RenderCommand, SceneErrorsExit2WithoutOutput) {
  const fs::path bad = dir_ / "bad.yml";
  std::ofstream(bad) << "- add: sphre\n";
  const fs::path out = dir_ / "b.png";
  std::string err;
  EXPECT_EQ(run("render " + bad.string() + " -o " + out.string(), &err), 2);
  EXPECT_NE(err.find(bad.string() + ":1:8: unknown shape 'sphre' (did you mean 'sphere'?)"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
