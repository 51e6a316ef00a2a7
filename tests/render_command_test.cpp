// End to end: the built `toroid render` binary.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "support/command.h"

namespace {

namespace fs = std::filesystem;

int run(const std::string& args, std::string* err = nullptr) {
  const toroid::testing::CommandResult r = toroid::testing::run_toroid(args);
  if (err) *err = r.err;
  return r.exit_code;
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

// Starts `toroid ARGS...` (stderr to `err`) and returns its process id.
pid_t spawn_toroid(const std::vector<std::string>& args, const fs::path& err) {
  std::vector<std::string> argv_s{TOROID_BINARY};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, TOROID_BINARY, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// Waits up to `limit` for the process; false if it is still running.
bool wait_for(pid_t pid, std::chrono::seconds limit, int& status) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (waitpid(pid, &status, WNOHANG) == pid) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

TEST_F(RenderCommand, InterruptStopsTheRenderWithoutOutput) {
  // A render that would take many minutes: 800x600 pixels, 4096 samples each.
  const fs::path out = dir_ / "slow.png";
  const fs::path err = fs::temp_directory_path() / ("toroid_interrupt_err_" + std::to_string(::getpid()));
  const pid_t pid = spawn_toroid({"render", kScene, "-o", out.string(), "--width", "800", "--height", "600",
                                  "--samples", "4096", "--threads", "2"},
                                 err);
  ASSERT_GT(pid, 0);
  // Let it load the scene and start rendering.
  std::this_thread::sleep_for(std::chrono::seconds(2));
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, WNOHANG), 0) << "the render ended before the interrupt";
  ASSERT_EQ(kill(pid, SIGINT), 0);
  // A generous guard against a hang, not a timing goal: the workers stop
  // after their current 16x16 tile.
  const bool ended = wait_for(pid, std::chrono::seconds(60), status);
  if (!ended) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
  ASSERT_TRUE(ended) << "still running 60 s after SIGINT";
  const std::string message = toroid::testing::read_text(err);
  fs::remove(err);
  ASSERT_TRUE(WIFEXITED(status)) << "killed by signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_NE(message.find("toroid render: interrupted; nothing written"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_empty(dir_)) << "the render left a file behind";
}

}  // namespace
