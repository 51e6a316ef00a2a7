// SPDX-License-Identifier: Apache-2.0
// Prints the accuracy table of every solver on every ray family
// (docs/torus.md shows its output). Usage: accuracy_report [rays-per-family]
#include <cstdio>
#include <cstdlib>

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
    for (TorusSolver s : {TorusSolver::Default, TorusSolver::Ferrari, TorusSolver::Tianheng}) {
      const Metrics m = measure(f, ref, s);
      std::printf("| %s | %s | %d | %d | %d | %d | %d | %d | %.1e | %.1e | %.1e | %d/%d |\n", f.name.c_str(),
                  std::string(solver_name(s)).c_str(), m.rays, m.reference_roots, m.missed - m.missed_subvisible,
                  m.missed_subvisible, m.spurious, m.extra, m.p50, m.p99, m.max, m.grazing_pairs_found,
                  m.grazing_pairs);
    }
    std::fflush(stdout);
  }
  return 0;
}
