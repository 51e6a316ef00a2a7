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

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/command.h"
#include "support/image_files.h"
#include "toroid/io/exr_image.h"
#include "toroid/io/srgb.h"
#include "toroid/render/renderer.h"
#include "toroid/scene/scene_loader.h"

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

// A small scene that renders in an instant, with a light bright enough that
// some values pass 1 (an EXR keeps them, an 8-bit file clamps them).
const char kTinyScene[] = R"(- add: camera
  width: 12
  height: 9
  field-of-view: 1.0
  from: [0, 1.5, -5]
  to: [0, 1, 0]
  up: [0, 1, 0]
- add: light
  at: [-10, 10, -10]
  intensity: [2.5, 2.5, 2.5]
- add: plane
  material:
    color: [0.2, 0.3, 0.9]
- add: sphere
  transform:
    - [translate, 0, 1, 0]
  material:
    color: [1, 0.4, 0.1]
    specular: 0.9
)";

// The image of kTinyScene rendered in this process: what the command's
// files must hold.
toroid::Canvas tiny_in_process(const fs::path& scene) {
  const toroid::Scene s = toroid::load_scene(scene.string());
  toroid::RenderOptions ro;
  ro.threads = 1;
  return toroid::render_image(s.camera, s.world, ro);
}

// 8-bit codes as the PPM writes them: clamped, times 255, rounded.
unsigned char ppm_code(double v) { return static_cast<unsigned char>(std::lround(std::clamp(v, 0.0, 1.0) * 255.0)); }

std::vector<unsigned char> codes(const toroid::Canvas& c, double scale = 1) {
  std::vector<unsigned char> v;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) {
      const toroid::Color p = c.pixel_at(x, y);
      for (const double ch : {p.r, p.g, p.b}) v.push_back(ppm_code(ch * scale));
    }
  return v;
}

std::vector<unsigned char> ppm_values(const fs::path& file) {
  return toroid::testing::ppm_samples(toroid::testing::read_text(file));
}

std::vector<unsigned char> png_codes(const fs::path& file) { return toroid::testing::png_samples(file); }

class RenderCommandOutput : public RenderCommand {
 protected:
  void SetUp() override {
    RenderCommand::SetUp();
    scene_ = dir_ / "tiny.yml";
    std::ofstream(scene_) << kTinyScene;
  }
  // Renders the tiny scene to `name` in the test's folder with `args`.
  fs::path render(const std::string& name, const std::string& args = "") {
    const fs::path out = dir_ / name;
    std::string err;
    EXPECT_EQ(run("render " + scene_.string() + " -o " + out.string() + " --threads 2 --quiet " + args, &err), 0)
        << err;
    return out;
  }
  fs::path scene_;
};

TEST_F(RenderCommandOutput, ExrHoldsTheLinearFloatValuesUnclamped) {
  const toroid::Canvas exr = toroid::read_exr(render("x.exr").string());
  const toroid::Canvas expected = tiny_in_process(scene_);
  ASSERT_EQ(exr.width(), 12);
  ASSERT_EQ(exr.height(), 9);
  double brightest = 0;
  for (int y = 0; y < exr.height(); ++y)
    for (int x = 0; x < exr.width(); ++x) {
      const toroid::Color e = exr.pixel_at(x, y), c = expected.pixel_at(x, y);
      ASSERT_EQ(e.r, static_cast<float>(c.r)) << x << ", " << y;
      ASSERT_EQ(e.g, static_cast<float>(c.g)) << x << ", " << y;
      ASSERT_EQ(e.b, static_cast<float>(c.b)) << x << ", " << y;
      brightest = std::max({brightest, e.r, e.g, e.b});
    }
  EXPECT_GT(brightest, 1.0) << "no value above 1: the scene does not show that the EXR is unclamped";
  // The PPM of the same render holds the same values, in 8 bits.
  EXPECT_EQ(ppm_values(render("x.ppm")), codes(exr));
}

TEST_F(RenderCommandOutput, ExposureOneDoublesEveryValueInEveryFormat) {
  const toroid::Canvas plain = toroid::read_exr(render("plain.exr").string());
  const toroid::Canvas doubled = toroid::read_exr(render("doubled.exr", "--exposure 1").string());
  ASSERT_EQ(doubled.width(), plain.width());
  for (int y = 0; y < plain.height(); ++y)
    for (int x = 0; x < plain.width(); ++x) {
      const toroid::Color p = plain.pixel_at(x, y), d = doubled.pixel_at(x, y);
      ASSERT_EQ(d.r, 2 * p.r) << x << ", " << y;
      ASSERT_EQ(d.g, 2 * p.g) << x << ", " << y;
      ASSERT_EQ(d.b, 2 * p.b) << x << ", " << y;
    }
  EXPECT_EQ(ppm_values(render("doubled.ppm", "--exposure 1")), codes(plain, 2));
  EXPECT_EQ(png_codes(render("doubled.png", "--exposure 1 --linear")), codes(plain, 2));
  EXPECT_EQ(ppm_values(render("quarter.ppm", "--exposure=-2")), codes(plain, 0.25));
  // The sRGB PNG is scaled before its transfer curve.
  const toroid::Canvas c = tiny_in_process(scene_);
  std::vector<unsigned char> srgb;
  for (int y = 0; y < c.height(); ++y)
    for (int x = 0; x < c.width(); ++x) {
      const toroid::Color p = c.pixel_at(x, y) * 2;
      for (const double ch : {p.r, p.g, p.b}) srgb.push_back(toroid::linear_to_srgb8(ch));
    }
  EXPECT_EQ(png_codes(render("doubled-srgb.png", "--exposure 1")), srgb);
}

TEST_F(RenderCommandOutput, ALinearPngHoldsThePpmsValues) {
  const std::vector<unsigned char> ppm = ppm_values(render("x.ppm"));
  ASSERT_EQ(ppm.size(), 12u * 9u * 3u);
  EXPECT_EQ(png_codes(render("linear.png", "--linear")), ppm);
  // Without --linear the PNG is sRGB-encoded: other numbers.
  EXPECT_NE(png_codes(render("srgb.png")), ppm);
}

// Bad values: exit 2, a message naming the option, and no file.
TEST_F(RenderCommandOutput, BadValuesExit2WithTheirMessageAndNoFile) {
  struct Case {
    std::string output, args, message;
  };
  const std::vector<Case> cases{
      {"x.png", "--exposure nan", "toroid render: --exposure: must be a number of stops from -32 to 32, got 'nan'"},
      {"x.png", "--exposure inf", "--exposure: must be a number of stops from -32 to 32, got 'inf'"},
      {"x.png", "--exposure 33", "--exposure: must be a number of stops from -32 to 32, got '33'"},
      {"x.exr", "--exposure=-32.5", "--exposure: must be a number of stops from -32 to 32, got '-32.5'"},
      {"x.png", "--exposure 1e400", "--exposure: must be a number of stops from -32 to 32, got '1e400'"},
      {"x.png", "--exposure bright", "--exposure: must be a number of stops from -32 to 32, got 'bright'"},
      {"x.png", "--exposure 1x", "--exposure: must be a number of stops from -32 to 32, got '1x'"},
      {"x.ppm", "--linear",
       "toroid render: --linear is for .png output only: '" + (dir_ / "x.ppm").string() +
           "' holds linear values already (drop --linear)"},
      {"x.EXR", "--linear", "toroid render: --linear is for .png output only"},
      {"x.png", "--integrator photon", "toroid render: --integrator: photon not in {whitted,path}"},
      {"x.png", "--integrator", "--integrator: 1 required TEXT:{whitted,path} missing"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.args);
    std::string err;
    EXPECT_EQ(run("render " + scene_.string() + " -o " + (dir_ / c.output).string() + " " + c.args, &err), 2);
    EXPECT_NE(err.find(c.message), std::string::npos) << err;
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1) << "a file was written";
  }
}

// An image named without -o gets the suggestion for .exr as for .png.
TEST_F(RenderCommandOutput, AnExrNamedWithoutDashOIsSuggested) {
  std::string err;
  EXPECT_EQ(run("render " + scene_.string() + " out.exr", &err), 2);
  EXPECT_NE(err.find("toroid render: unexpected argument 'out.exr' (did you mean '-o out.exr'?)"), std::string::npos)
      << err;
}

// Exposures at the ends of the range, and 0, are accepted.
TEST_F(RenderCommandOutput, TheExposureRangeIsInclusive) {
  for (const char* e : {"-32", "32", "0", "0.5"}) {
    SCOPED_TRACE(e);
    EXPECT_TRUE(fs::exists(render(std::string("e") + e + ".exr", std::string("--exposure=") + e)));
  }
}

TEST_F(RenderCommandOutput, TheIntegratorIsChosenAndNamedInTheSummary) {
  for (const std::string integrator : {"whitted", "path"}) {
    SCOPED_TRACE(integrator);
    const fs::path out = dir_ / (integrator + ".png");
    std::string err;
    ASSERT_EQ(
        run("render " + scene_.string() + " -o " + out.string() + " --threads 2 --integrator " + integrator, &err), 0)
        << err;
    EXPECT_TRUE(fs::exists(out));
    EXPECT_EQ(err.find("12x9, 1 samples, path integrator, 2 threads, ") != std::string::npos, integrator == "path")
        << err;
    EXPECT_EQ(err.find("12x9, 1 samples, 2 threads, ") != std::string::npos, integrator == "whitted") << err;
  }
}

// The scene's `- add: integrator` is the default; --integrator overrides it.
TEST_F(RenderCommandOutput, TheScenesIntegratorUnlessTheCommandLineSaysOtherwise) {
  const fs::path scene = dir_ / "path.yml";
  std::ofstream(scene) << kTinyScene << "- add: integrator\n  type: path\n";
  struct Case {
    std::string args;
    bool path;
  };
  for (const Case& c : {Case{"", true}, Case{"--integrator whitted", false}, Case{"--integrator path", true}}) {
    SCOPED_TRACE(c.args);
    std::string err;
    ASSERT_EQ(run("render " + scene.string() + " -o " + (dir_ / "x.png").string() + " --threads 2 " + c.args, &err), 0)
        << err;
    EXPECT_EQ(err.find(", path integrator, ") != std::string::npos, c.path) << err;
  }
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
