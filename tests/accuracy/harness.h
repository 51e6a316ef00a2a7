// SPDX-License-Identifier: Apache-2.0
// The accuracy harness: ray families, the comparison of a solver's roots with
// the reference, and the per-family metrics. Used by accuracy_test.cpp (which
// asserts the bars for the default solver) and by the accuracy_report tool.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "accuracy/reference.h"
#include "toroid/torus/batch.h"
#include "toroid/torus/solver.h"

namespace toroid::accuracy {

struct Family {
  std::string name;
  // Bar on p99 root error (|dt| |d| / r) for the default solver.
  double p99_bar;
  // Bar on the largest root error (|dt| |d| / r) of any matched root, the
  // grazing pairs' ill-conditioned roots included: 100 times the p99 bar
  // (1e-10 r, or 1e-8 r for the far, thin and large families). The largest
  // measured (docs/torus.md) are 3.3e-11 r (grazing) and 5.2e-10 r
  // (R = 1e4), roots whose condition number is large; a root wrong by up to
  // the matching tolerance (1e-6 r), which p99 would hide in 1% of the
  // roots, is caught.
  double max_bar;
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
  int missed = 0;             // reference roots with no computed root
  int missed_subvisible = 0;  // of those, in pairs whose chord < 1e-5 r
  int spurious = 0;           // computed roots farther than 1e-7 r from the surface
  int extra = 0;              // unmatched computed roots on the surface
  int grazing_pairs = 0;      // close pairs (chord < 1e-5 r) in the reference
  int grazing_pairs_found = 0;
  std::vector<double> errors;  // |dt| |d| / r of matched roots
  double p50 = 0, p99 = 0, max = 0;
};

struct ReferenceSet {
  std::vector<std::vector<ReferenceRoot>> roots;  // per ray
};

// A solver under test: writes the roots of the ray to t, ascending, and
// returns their count (0..4). The harness's self-checks pass broken ones.
using RootFinder = std::function<int(const RayCase& c, double t[4])>;

ReferenceSet compute_references(const Family& f);
Metrics measure(const Family& f, const ReferenceSet& ref, TorusSolver solver);
Metrics measure(const Family& f, const ReferenceSet& ref, const RootFinder& solve);
// The default solver through the batch call on `path` (torus/batch.h), which
// must be available: the family's rays go in one call per run of rays on the
// same torus, and the rows it writes are measured.
Metrics measure(const Family& f, const ReferenceSet& ref, BatchPath path);

// The bars of docs/torus.md, for the default solver on family f: no missed
// root (those in grazing pairs included: every grazing pair is found, both
// roots), no spurious or extra root, p99 <= f.p99_bar and max <= f.max_bar.
// One line per bar not met; empty when all are met.
std::vector<std::string> bar_violations(const Family& f, const Metrics& m);

}  // namespace toroid::accuracy
