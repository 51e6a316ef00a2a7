#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""The torus solver's cost against issue 16's goals, every ratio from one run.

    bench/solver-goals.py [--runs N] [--core C] [--bench PATH]

Runs build/bench/torus_bench N times (default 2), each on one core (taskset
-c C, default 1, where taskset and the core exist) with its repetitions
interleaved at random, reads each run's least time per case (the `_min`
aggregate), and prints for every query the default solver's time, toroid's
Ferrari's in the same run, their ratio and the goal. With several runs each
figure is the range over the runs, and each ratio is taken within its run.
Builds the benchmark first (cmake --build build --target torus_bench) when it
is missing. Exits 1 when a case is missing from the benchmark's output.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BATCH_RAYS = 4096  # bench/torus_bench.cpp's ray sets

# (row, the default solver's case, the reference case, goal: ratio at most, or None)
ROWS = [
    ("every root, mixed", "BM_AllRoots/default_mixed", "BM_AllRoots/ferrari_mixed", 1.0),
    ("every root, hits", "BM_AllRoots/default_hits", "BM_AllRoots/ferrari_hits", 1.2),
    ("nearest root, mixed", "BM_Nearest/default_mixed", "BM_Nearest/ferrari_mixed", 0.8),
    ("blocks, mixed", "BM_Blocks/default_mixed", "BM_Blocks/ferrari_mixed", 0.8),
    ("nearest root, from a surface", "BM_Nearest/default_surface", "BM_Nearest/ferrari_surface", None),
    ("blocks, from a surface", "BM_Blocks/default_surface", "BM_Blocks/ferrari_surface", None),
    ("nearest root, from a surface, window from -0", "BM_Nearest/default_surface_from_zero", "BM_Nearest/ferrari_surface", None),
    ("blocks, from a surface, window from -0", "BM_Blocks/default_surface_from_zero", "BM_Blocks/ferrari_surface", None),
    ("nearest root, from inside", "BM_Nearest/default_inside", "BM_Nearest/ferrari_inside", None),
    ("batch avx512, mixed", "BM_Batch/avx512_mixed", "BM_AllRoots/ferrari_mixed", 0.35),
    ("batch avx2, mixed", "BM_Batch/avx2_mixed", "BM_AllRoots/ferrari_mixed", 0.35),
    ("batch scalar, mixed", "BM_Batch/scalar_mixed", "BM_AllRoots/ferrari_mixed", None),
]


def cpu_model():
    try:
        info = subprocess.run(["lscpu"], capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError):
        return "unknown CPU"
    fields = {}
    for line in info.splitlines():
        key, _, value = line.partition(":")
        fields[key.strip()] = value.strip()
    return "%s, family %s model %s" % (fields.get("Model name", "?"), fields.get("CPU family", "?"),
                                       fields.get("Model", "?"))


def run_once(bench, core):
    """One run of the benchmark: {case: least CPU ns per item}, None for a case it skipped."""
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        command = [bench, "--benchmark_enable_random_interleaving=true",
                   "--benchmark_report_aggregates_only=true",
                   "--benchmark_out=" + out.name, "--benchmark_out_format=json"]
        if shutil.which("taskset") and core < (os.cpu_count() or 1):
            command = ["taskset", "-c", str(core)] + command
        done = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if done.returncode != 0:
            sys.stderr.write(done.stderr)
            raise SystemExit("solver-goals: %s failed (exit %d)" % (" ".join(command), done.returncode))
        with open(out.name) as f:
            report = json.load(f)
    times = {}
    for b in report["benchmarks"]:
        if b.get("aggregate_name") != "min":
            continue
        case = b["run_name"].split("/repeats:")[0]
        # A batch case's iteration is one call on the whole set.
        rays = BATCH_RAYS if case.startswith("BM_Batch/") else 1
        ns = b["cpu_time"] * {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b.get("time_unit", "ns")]
        times[case] = None if b.get("error_occurred") else ns / rays
    return times


def span(values, fmt):
    lo, hi = min(values), max(values)
    return fmt % lo if fmt % lo == fmt % hi else (fmt % lo) + "–" + (fmt % hi)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--core", type=int, default=1)
    parser.add_argument("--bench", default=os.path.join(ROOT, "build", "bench", "torus_bench"))
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    if not os.access(args.bench, os.X_OK):
        subprocess.run(["cmake", "--build", os.path.join(ROOT, "build"), "--target", "torus_bench"], check=True)

    runs = [run_once(args.bench, args.core) for _ in range(args.runs)]
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"], capture_output=True,
                            text=True).stdout.strip() or "?"
    print("torus_bench, %d run(s), build %s, %s" % (args.runs, commit, cpu_model()))
    print("least CPU time of 10 repetitions, ns per ray; ratio = default / reference within each run")
    print()
    print("| query | default | reference | ratio | goal |")
    print("|---|---:|---:|---:|---|")
    missing = False
    for row, case, reference, goal in ROWS:
        pairs = []
        for times in runs:
            if case not in times or reference not in times:
                missing = True
                break
            if times[case] is not None:
                pairs.append((times[case], times[reference]))
        if missing:
            print("solver-goals: %s or %s is not in the benchmark's output" % (case, reference), file=sys.stderr)
            break
        if not pairs:
            print("| %s | (not on this CPU) | | | |" % row)
            continue
        ratios = [a / b for a, b in pairs]
        verdict = "" if goal is None else ("<= %.2f: %s" % (goal, "met" if max(ratios) <= goal else "not met"))
        print("| %s | %s | %s | %s× | %s |" % (row, span([a for a, _ in pairs], "%.1f"),
                                              span([b for _, b in pairs], "%.1f"), span(ratios, "%.2f"), verdict))
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
