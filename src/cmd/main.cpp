// SPDX-License-Identifier: Apache-2.0
// The `toroid` command line: a thin layer over the library.
#include <CLI/CLI.hpp>
#include <iostream>
#include <sstream>

#include "cmd/cli.h"
#include "cmd/intersect_command.h"
#include "cmd/mpi_launch.h"
#include "cmd/render_command.h"

int main(int argc, char** argv) {
  // Named here, so that help shows "toroid", not argv[0]'s path.
  CLI::App app{"toroid: a ray tracer with an exact, analytic torus", "toroid"};
  toroid::cmd::add_version_flag(app);
  app.require_subcommand(1);
  app.failure_message(toroid::cmd::usage_error);
  app.footer(std::string("Example:\n  ") + toroid::cmd::kRenderExample +
             "\n\nRun 'toroid SUBCOMMAND --help' for its options.\n" + toroid::cmd::kDocsLine);
  int exit_code = 0;
  toroid::cmd::add_render_command(app, exit_code);
  toroid::cmd::add_intersect_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // Under mpirun every rank reads the same command line: rank 0 alone says
    // what is wrong (or prints the help), and every rank exits with the same
    // status.
    static std::ostringstream discard;  // outlives the streams' use at exit
    if (toroid::cmd::launcher_rank() != 0) {
      std::cout.rdbuf(discard.rdbuf());
      std::cerr.rdbuf(discard.rdbuf());
    }
    // --help and --version exit 0; every usage error exits 2.
    return toroid::cmd::exit_on_parse_error(app, e);
  }
  return exit_code;
}
