// SPDX-License-Identifier: Apache-2.0
// `toroid intersect`: rays on stdin, roots on stdout (see README).
#include "cmd/intersect_command.h"

#include <cmath>
#include <iostream>
#include <memory>
#include <string>

#include "cmd/cli.h"
#include "toroid/io/ray_line.h"
#include "toroid/torus/intersect.h"

namespace toroid::cmd {
namespace {

struct IntersectOptions {
  double major = 1.0;
  double minor = 0.25;
  std::string solver = "default";
};

int run_intersect(const IntersectOptions& opt) {
  const TorusSolver solver = *solver_from_name(opt.solver);
  std::ios::sync_with_stdio(false);
  std::string line, out;
  long line_no = 0;
  while (std::getline(std::cin, line)) {
    ++line_no;
    RayLine ray;
    std::string error;
    if (!parse_ray_line(line, ray, error)) {
      std::cout.flush();
      std::cerr << "toroid intersect: line " << line_no << ": " << error << "\n";
      return 2;
    }
    double t[4];
    const int n = intersect_torus(opt.major, opt.minor, ray.origin, ray.direction, t, solver);
    out = format_roots(t, n);
    out += '\n';
    std::cout << out;
  }
  if (std::cin.bad()) {
    std::cerr << "toroid intersect: error reading standard input\n";
    return 1;
  }
  return 0;
}

}  // namespace

void add_intersect_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<IntersectOptions>();
  CLI::App* sub = app.add_subcommand("intersect", "Intersect rays with a torus: rays on stdin, roots on stdout");
  add_version_flag(*sub);
  sub->footer(
      "The torus: its ring in the xy-plane, its axis z. Each line of stdin is a ray, 'ox oy oz dx dy dz';\n"
      "each line of stdout 'k t1 ... tk', its k real roots, ascending, printed to read back exactly.\n"
      "\nExample:\n  printf -- '-5 0 0 1 0 0\\n' | toroid intersect --major 1 --minor 0.25\n"
      "\nDocs: README.md (\"toroid intersect\").");
  const CLI::Validator positive(
      [](std::string& s) {
        double v = 0;
        try {
          v = std::stod(s);
        } catch (const std::exception&) {
          return std::string("must be a number, got '") + s + "'";
        }
        return std::isfinite(v) && v > 0 ? std::string{} : "must be a positive finite number, got '" + s + "'";
      },
      "POSITIVE");
  sub->add_option("--major,-R", opt->major, "Distance from the axis to the tube's centre (R > 0)")
      ->check(positive)
      ->capture_default_str();
  sub->add_option("--minor,-r", opt->minor, "Radius of the tube (r > 0; r >= R gives horn/spindle tori)")
      ->check(positive)
      ->capture_default_str();
  sub->add_option("--solver", opt->solver, "Quartic solver")
      ->check(CLI::IsMember({"default", "ferrari", "tianheng"}))
      ->capture_default_str();
  sub->callback([opt, &exit_code] { exit_code = run_intersect(*opt); });
}

}  // namespace toroid::cmd
