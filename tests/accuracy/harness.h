// The accuracy harness: ray families, the comparison of a solver's roots with
// the reference, and the per-family metrics. Used by accuracy_test.cpp (which
// asserts the bars for the default solver) and by the accuracy_report tool.
#pragma once

#include <string>
#include <vector>

#include "accuracy/reference.h"
#include "toroid/torus/solver.h"

namespace toroid::accuracy {

struct Family {
  std::string name;
  // Bar on p99 root error (|dt| |d| / r) for the default solver.
  double p99_bar;
  // Far family: the error is measured beyond the rounding of t itself, since
  // no double can be closer to the exact root than half an ulp of t.
  bool beyond_rounding;
  std::vector<RayCase> rays;
};

// Every family of the harness; `per_family` rays each, deterministic.
std::vector<Family> make_families(int per_family);

struct Metrics {
  int rays = 0;
  int reference_roots = 0;
  int missed = 0;              // reference roots with no computed root
  int missed_subvisible = 0;   // of those, in pairs whose chord < 1e-5 r
  int spurious = 0;            // computed roots farther than 1e-7 r from the surface
  int extra = 0;               // unmatched computed roots on the surface
  int grazing_pairs = 0;       // close pairs (chord < 1e-5 r) in the reference
  int grazing_pairs_found = 0;
  std::vector<double> errors;  // |dt| |d| / r of matched roots
  double p50 = 0, p99 = 0, max = 0;
};

struct ReferenceSet {
  std::vector<std::vector<ReferenceRoot>> roots;  // per ray
};

ReferenceSet compute_references(const Family& f);
Metrics measure(const Family& f, const ReferenceSet& ref, TorusSolver solver);

}  // namespace toroid::accuracy
