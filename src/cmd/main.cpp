// The `toroid` command line: a thin layer over the library.
#include <CLI/CLI.hpp>

#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"toroid: a ray tracer with an exact, analytic torus"};
  app.require_subcommand(1);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
