// SPDX-License-Identifier: Apache-2.0
// The `toroid` command line: a thin layer over the library.
#include <CLI/CLI.hpp>

#include "cmd/intersect_command.h"
#include "cmd/render_command.h"
#include "toroid/version.h"

int main(int argc, char** argv) {
  CLI::App app{"toroid: a ray tracer with an exact, analytic torus"};
  app.set_version_flag("--version", "toroid " TOROID_VERSION_STRING);
  app.require_subcommand(1);
  int exit_code = 0;
  toroid::cmd::add_intersect_command(app, exit_code);
  toroid::cmd::add_render_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version exit 0; every usage error exits 2.
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  return exit_code;
}
