// SPDX-License-Identifier: Apache-2.0
// End to end: the built `toroid render` binary.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/inotify.h>
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
  ASSERT_EQ(run("render " + kScene + " -o " + out.string() + " --width 40 --height 30 --threads 2 --samples 4", &err),
            0)
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

// A warning does not stop the render; it has the prefix that errors have,
// and --quiet does not hide it.
TEST_F(RenderCommand, WarningsCarryThePrefixAndTheRenderGoesOn) {
  const fs::path scene = dir_ / "degrees.yml";
  std::ofstream(scene) << "- add: camera\n  width: 8\n  height: 6\n  field-of-view: 0.8\n"
                          "  from: [0, 2, -5]\n  to: [0, 0, 0]\n  up: [0, 1, 0]\n"
                          "- add: sphere\n  transform:\n    - [rotate-x, 90]\n";
  const fs::path out = dir_ / "d.png";
  std::string err;
  EXPECT_EQ(run("render " + scene.string() + " -o " + out.string() + " --quiet", &err), 0) << err;
  EXPECT_EQ(err, "toroid render: " + scene.string() +
                     ":10:18: warning: rotate-x angle 90 is more than 2 pi radians (a full turn); if it is in "
                     "degrees, write 1.5708 (angles are in radians)\n");
  EXPECT_TRUE(fs::exists(out));
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

// A scene that renders fast and writes slowly: a fine checkerboard (the PNG
// does not compress to nothing), 3000x2000 pixels.
const char kPlaneScene[] = R"(- add: camera
  width: 100
  height: 100
  field-of-view: 1.2
  from: [0, 1.5, -5]
  to: [0, 0, 0]
  up: [0, 1, 0]
- add: light
  at: [-10, 10, -10]
  intensity: [1, 1, 1]
- add: plane
  material:
    pattern:
      type: checkers
      colors:
        - [1, 1, 1]
        - [0, 0, 0]
      transform:
        - [scale, 0.01, 0.01, 0.01]
)";

// When to interrupt: while the image is being written (the first write to
// the temporary file that write_image renames into place), or, to show that
// the test can tell, once the image is in place.
enum class InterruptAt { Write, AfterRename };

struct InterruptResult {
  bool signalled = false;     // SIGINT was sent at the moment asked for
  bool during_write = false;  // the temporary file was there, the image not, after the signal
  bool ended = false;
  int status = 0;
  std::string message;
};

// Renders kPlaneScene into `out_dir`/slow.png, watches the folder (inotify)
// and sends SIGINT at `at`.
InterruptResult interrupt_render(const fs::path& scene_dir, const fs::path& out_dir, InterruptAt at) {
  InterruptResult res;
  const fs::path scene = scene_dir / "plane.yml", out = out_dir / "slow.png";
  std::ofstream(scene) << kPlaneScene;
  const int in = inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (in < 0) return res;
  inotify_add_watch(in, out_dir.c_str(), IN_MODIFY | IN_MOVED_TO | IN_CREATE);
  const fs::path err = scene_dir / "stderr.txt";
  const pid_t pid = spawn_toroid(
      {"render", scene.string(), "-o", out.string(), "--width", "3000", "--height", "2000", "--threads", "2"}, err);
  if (pid <= 0) {
    close(in);
    return res;
  }
  // Appended, not "." + string: GCC 12 at -O3 warns falsely on that (-Wrestrict, GCC bug 105329).
  std::string tmp_prefix = ".";
  tmp_prefix += out.filename().string();
  tmp_prefix += ".tmp-";
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  alignas(inotify_event) char buf[4096];
  while (!res.signalled && std::chrono::steady_clock::now() < end) {
    pollfd p{in, POLLIN, 0};
    if (poll(&p, 1, 100) <= 0) {
      if (waitpid(pid, &res.status, WNOHANG) == pid) break;  // ended without the moment coming
      continue;
    }
    const ssize_t len = read(in, buf, sizeof buf);
    for (ssize_t i = 0; i < len && !res.signalled;) {
      const auto* ev = reinterpret_cast<const inotify_event*>(buf + i);
      const std::string name = ev->len ? ev->name : "";
      const bool write_of_tmp = (ev->mask & IN_MODIFY) && name.rfind(tmp_prefix, 0) == 0;
      const bool renamed = (ev->mask & IN_MOVED_TO) && name == out.filename().string();
      if ((at == InterruptAt::Write && write_of_tmp) || (at == InterruptAt::AfterRename && renamed)) {
        kill(pid, SIGINT);
        res.signalled = true;
        res.during_write = fs::exists(out_dir / name) && !fs::exists(out);
      }
      i += static_cast<ssize_t>(sizeof(inotify_event) + ev->len);
    }
  }
  close(in);
  res.ended = wait_for(pid, std::chrono::seconds(60), res.status);
  if (!res.ended) {
    kill(pid, SIGKILL);
    waitpid(pid, &res.status, 0);
  }
  res.message = toroid::testing::read_text(err);
  return res;
}

// Ctrl-C while the PNG is being written: the write is abandoned, the
// temporary file removed, nothing is left in the folder, and the command
// exits 130 as it does when interrupted while rendering.
TEST_F(RenderCommand, InterruptDuringTheImageWriteLeavesNoFile) {
  const fs::path out_dir = dir_ / "out";
  fs::create_directories(out_dir);
  const InterruptResult r = interrupt_render(dir_, out_dir, InterruptAt::Write);
  ASSERT_TRUE(r.signalled) << "the render never wrote its temporary file: " << r.message;
  ASSERT_TRUE(r.during_write) << "the image was already in place when SIGINT was sent (the write was too fast)";
  ASSERT_TRUE(r.ended) << "still running 60 s after SIGINT";
  ASSERT_TRUE(WIFEXITED(r.status)) << "killed by signal " << (WIFSIGNALED(r.status) ? WTERMSIG(r.status) : 0);
  EXPECT_EQ(WEXITSTATUS(r.status), 130) << r.message;
  EXPECT_NE(r.message.find("toroid render: interrupted; nothing written"), std::string::npos) << r.message;
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(out_dir)) left.push_back(e.path().filename().string());
  EXPECT_TRUE(left.empty()) << "left behind: " << ::testing::PrintToString(left);
}

}  // namespace
