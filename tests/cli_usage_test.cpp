// SPDX-License-Identifier: Apache-2.0
// End to end: the built `toroid` command's usage errors, --version and
// --help, as a person trying it for the first time meets them.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/command.h"
#include "toroid/version.h"

namespace {

namespace fs = std::filesystem;
using toroid::testing::CommandResult;
using toroid::testing::run_toroid;

const std::string kScene = std::string(TOROID_SOURCE_DIR) + "/scenes/bagels.yaml";
const std::string kVersionOut = "toroid " TOROID_VERSION_STRING "\n";

class CliUsage : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("toroid_cli_usage_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    out_ = (dir_ / "out.png").string();
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `toroid ARGS` and expects a usage error: status 2, nothing on
  // stdout, no image, and exactly `message` then the hint for `command`.
  void expect_usage_error(const std::string& args, const std::string& command, const std::string& message) {
    const CommandResult r = run_toroid(args, dir_);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(r.err, command + ": " + message + "\nRun '" + command + " --help' for usage.\n") << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_FALSE(fs::exists(out_)) << args;
  }

  // Runs `toroid ARGS` and expects the version line alone on stdout, status 0.
  void expect_version(const std::string& args) {
    const CommandResult r = run_toroid(args, dir_);
    EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.out, kVersionOut) << args;
    EXPECT_EQ(r.err, "") << args;
    EXPECT_FALSE(fs::exists(out_)) << args;
  }

  fs::path dir_;
  std::string out_;
};

TEST_F(CliUsage, AMisspeltSubcommandGetsTheNearestOne) {
  expect_usage_error("rendr " + kScene + " -o " + out_, "toroid",
                     "unknown subcommand 'rendr' (did you mean 'render'?)");
  expect_usage_error("intersct", "toroid", "unknown subcommand 'intersct' (did you mean 'intersect'?)");
  expect_usage_error("Render " + kScene + " -o " + out_, "toroid",
                     "unknown subcommand 'Render' (did you mean 'render'?)");
}

TEST_F(CliUsage, AnUnknownSubcommandFarFromAnyListsThem) {
  expect_usage_error("draw " + kScene + " -o " + out_, "toroid", "unknown subcommand 'draw' (use render or intersect)");
}

TEST_F(CliUsage, ASceneWithoutTheSubcommandSuggestsRender) {
  expect_usage_error("scenes/bagels.yaml -o " + out_, "toroid",
                     "unknown subcommand 'scenes/bagels.yaml' (did you mean 'toroid render scenes/bagels.yaml'?)");
}

TEST_F(CliUsage, NoSubcommandListsThem) {
  expect_usage_error("", "toroid", "A subcommand is required (use render or intersect)");
}

TEST_F(CliUsage, AMisspeltOptionGetsTheNearestOne) {
  const std::string render = "render " + kScene + " -o " + out_;
  expect_usage_error(render + " --widht 800", "toroid render", "unknown option '--widht' (did you mean '--width'?)");
  expect_usage_error(render + " --widht=800", "toroid render", "unknown option '--widht' (did you mean '--width'?)");
  expect_usage_error(render + " -width 800", "toroid render", "unknown option '-width' (did you mean '--width'?)");
  expect_usage_error(render + " --sample 4", "toroid render", "unknown option '--sample' (did you mean '--samples'?)");
  expect_usage_error(render + " --max-dpeth 2", "toroid render",
                     "unknown option '--max-dpeth' (did you mean '--max-depth'?)");
  expect_usage_error("render " + kScene + " --ouput " + out_, "toroid render",
                     "unknown option '--ouput' (did you mean '--output'?)");
  expect_usage_error("intersect --mjor 2", "toroid intersect", "unknown option '--mjor' (did you mean '--major'?)");
}

// CLI11 gives the 800 to the scene positional; the cause is the option.
TEST_F(CliUsage, AMisspeltOptionIsBlamedBeforeWhatItCaused) {
  expect_usage_error("render --widht 800 " + kScene + " -o " + out_, "toroid render",
                     "unknown option '--widht' (did you mean '--width'?)");
}

TEST_F(CliUsage, AnUnknownOptionFarFromAnyIsNamed) {
  expect_usage_error("render " + kScene + " -o " + out_ + " --fast", "toroid render", "unknown option '--fast'");
  expect_usage_error("--fast render " + kScene + " -o " + out_, "toroid", "unknown option '--fast'");
}

TEST_F(CliUsage, AnImageNamedWithoutDashOGetsTheFix) {
  expect_usage_error("render " + kScene + " out.png", "toroid render",
                     "unexpected argument 'out.png' (did you mean '-o out.png'?)");
  expect_usage_error("render " + kScene + " " + kScene + " -o " + out_, "toroid render",
                     "unexpected argument '" + kScene + "'");
}

TEST_F(CliUsage, CliElevenMessagesCarryTheSubcommandsPrefix) {
  const std::string render = "render " + kScene + " -o " + out_;
  expect_usage_error("render", "toroid render", "scene is required");
  expect_usage_error("render " + kScene, "toroid render", "--output is required");
  expect_usage_error(render + " --samples 0", "toroid render", "--samples: Value 0 not in range 1 to 65536");
  expect_usage_error("render nothing.yml -o " + out_, "toroid render", "scene: File does not exist: nothing.yml");
  expect_usage_error("intersect --major 0", "toroid intersect", "--major: must be a positive finite number, got '0'");
}

// Errors in the scene are the loader's, as they were: no hint about --help.
TEST_F(CliUsage, SceneErrorsKeepTheirFormat) {
  std::ofstream(dir_ / "bad.yml") << "- add: sphre\n";
  const CommandResult r = run_toroid("render bad.yml -o " + out_, dir_);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "toroid render: bad.yml:1:8: unknown shape 'sphre' (did you mean 'sphere'?)\n");
  EXPECT_FALSE(fs::exists(out_));
}

TEST_F(CliUsage, VersionAnywhere) {
  expect_version("--version");
  expect_version("render --version");
  expect_version("intersect --version");
  expect_version("render " + kScene + " --version");
  expect_version("render " + kScene + " -o " + out_ + " --version");
  // --version wins over errors elsewhere on the line.
  expect_version("render nothing.yml -o " + out_ + " --version");
  expect_version("render " + kScene + " -o " + out_ + " --samples 0 --version");
  expect_version("rendr --version");
  // Also over an error CLI11 throws while it parses, before it has looked at --version.
  expect_version("render --version -o");
}

TEST_F(CliUsage, HelpNamesTheProgramAndShowsAnExampleAndTheDocs) {
  for (const char* args : {"--help", "-h"}) {
    const CommandResult r = run_toroid(args, dir_);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_EQ(r.err, "") << args;
    EXPECT_EQ(r.out.find(TOROID_BINARY), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nUsage: toroid [OPTIONS] SUBCOMMAND\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nExample:\n  toroid render scenes/bagels.yaml -o bagels.png --width 800\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\nRun 'toroid SUBCOMMAND --help' for its options.\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nDocs: README.md, and docs/scene-format.md for the scene format.\n"), std::string::npos)
        << r.out;
  }
}

TEST_F(CliUsage, SubcommandHelpNamesTheProgramAndShowsAnExample) {
  // Also after an error that CLI11 would report before it looked at --help.
  for (const char* args : {"render --help", "render nothing.yml --help", "render --widht 800 -h", "render -h -o"}) {
    const CommandResult r = run_toroid(args, dir_);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_EQ(r.err, "") << args;
    EXPECT_EQ(r.out.find(TOROID_BINARY), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nUsage: toroid render [OPTIONS] scene\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nExample:\n  toroid render scenes/bagels.yaml -o bagels.png --width 800\n"),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("\nDocs: README.md, and docs/scene-format.md for the scene format.\n"
                         "Every error message and exit status: docs/errors.md.\n"),
              std::string::npos)
        << r.out;
  }
  const CommandResult r = run_toroid("intersect --help", dir_);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("\nUsage: toroid intersect [OPTIONS]\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nExample:\n  printf -- '-5 0 0 1 0 0\\n' | toroid intersect --major 1 --minor 0.25\n"),
            std::string::npos)
      << r.out;
}

// The help's example works as printed, from the top of the source tree (its
// image goes to the test's folder instead).
TEST_F(CliUsage, TheHelpsExampleRenders) {
  const std::string help = run_toroid("--help").out;
  const std::string intro = "Example:\n  toroid ";
  const std::size_t at = help.find(intro);
  ASSERT_NE(at, std::string::npos) << help;
  std::string args = help.substr(at + intro.size());
  args = args.substr(0, args.find('\n'));
  const std::string image = " -o bagels.png ";
  const std::size_t o = args.find(image);
  ASSERT_NE(o, std::string::npos) << args;
  args.replace(o, image.size(), " -o " + out_ + " ");
  const CommandResult r = run_toroid(args + " --quiet", TOROID_SOURCE_DIR);
  EXPECT_EQ(r.exit_code, 0) << args << "\n" << r.err;
  EXPECT_TRUE(fs::exists(out_)) << args;
}

}  // namespace
