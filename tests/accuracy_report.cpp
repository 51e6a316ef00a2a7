// SPDX-License-Identifier: Apache-2.0
// Prints the accuracy table of every solver on every ray family
// (docs/torus.md shows its output), and the default solver's through each
// SIMD batch path this CPU has. Usage: accuracy_report [rays-per-family]
#include <cstdio>
#include <cstdlib>
#include <string>

#include "accuracy/harness.h"

int main(int argc, char** argv) {
  using namespace toroid;
  using namespace toroid::accuracy;
  const int n = argc > 1 ? std::atoi(argv[1]) : 2000;
  if (n <= 0) {
    std::fprintf(stderr, "usage: accuracy_report [rays-per-family > 0]\n");
    return 2;
  }
  std::printf(
      "| family | solver | rays | roots | missed | sub-visible missed | spurious | extra | p50 | p99 | max | grazing "
      "pairs found |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const Family& f : make_families(n)) {
    const ReferenceSet ref = compute_references(f);
    const auto row = [&](const std::string& solver, const Metrics& m) {
      std::printf("| %s | %s | %d | %d | %d | %d | %d | %d | %.1e | %.1e | %.1e | %d/%d |\n", f.name.c_str(),
                  solver.c_str(), m.rays, m.reference_roots, m.missed - m.missed_subvisible, m.missed_subvisible,
                  m.spurious, m.extra, m.p50, m.p99, m.max, m.grazing_pairs_found, m.grazing_pairs);
    };
    for (TorusSolver s : {TorusSolver::Default, TorusSolver::Ferrari, TorusSolver::Tianheng})
      row(std::string(solver_name(s)), measure(f, ref, s));
    // The default solver through the batch's SIMD paths this CPU has.
    for (BatchPath p : {BatchPath::Avx2, BatchPath::Avx512})
      if (batch_path_available(p)) row(std::string("default, batch ") + batch_path_name(p), measure(f, ref, p));
    std::fflush(stdout);
  }
  return 0;
}
