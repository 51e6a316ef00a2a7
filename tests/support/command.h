// SPDX-License-Identifier: Apache-2.0
// Runs the built `toroid` binary (TOROID_BINARY) for end-to-end tests.
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace toroid::testing {

struct CommandResult {
  int exit_code = -1;  // -1 when it did not exit normally (a signal, a crash)
  std::string out, err;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// `toroid ARGS` through the shell (ARGS may quote), in folder `cwd` (empty:
// the current one), with standard input from `stdin_file` (empty: /dev/null).
inline CommandResult run_toroid(const std::string& args, const std::filesystem::path& cwd = {},
                                const std::filesystem::path& stdin_file = {}) {
  const std::filesystem::path base =
      std::filesystem::temp_directory_path() / ("toroid_cmd_" + std::to_string(::getpid()));
  const std::filesystem::path out = base.string() + ".out", err = base.string() + ".err";
  std::string cmd;
  if (!cwd.empty()) cmd += "cd '" + cwd.string() + "' && ";
  cmd += std::string(TOROID_BINARY) + " " + args;
  cmd += " <'" + (stdin_file.empty() ? std::string("/dev/null") : stdin_file.string()) + "'";
  cmd += " >'" + out.string() + "' 2>'" + err.string() + "'";
  const int status = std::system(cmd.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return r;
}

}  // namespace toroid::testing
