#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs each libFuzzer target of a -DTOROID_FUZZ=ON build for a bounded time
# on a copy of its corpus (fuzz/corpus/NAME), with its dictionary
# (fuzz/NAME.dict) when it has one. Any crash, sanitizer report, leak,
# timeout (-timeout=10 per input) or out-of-memory fails: the script prints
# the end of the fuzzer's log and exits 1; the input lands in
# BUILD/fuzz-artifacts/. The targets are TOROID_FUZZ_TARGETS of
# fuzz/CMakeLists.txt (it writes them to BUILD/fuzz/fuzz_targets.txt).
#
# Usage: tools/fuzz-bounded.sh BUILD   (TOROID_FUZZ_SECONDS, default 60 per
# target; 0 runs nothing)
set -euo pipefail
cd "$(dirname "$0")/.."
build=$(cd "${1:?usage: tools/fuzz-bounded.sh BUILD}" && pwd)
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
seconds=${TOROID_FUZZ_SECONDS:-60}
[ "$seconds" -gt 0 ] || exit 0
# The targets are TOROID_FUZZ_TARGETS of fuzz/CMakeLists.txt, which writes them here.
mapfile -t targets <"$build/fuzz/fuzz_targets.txt"
[ ${#targets[@]} -gt 0 ] || { echo "toroid: no fuzz targets in $build/fuzz/fuzz_targets.txt" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$build/fuzz-artifacts"
# libFuzzer reports a crash and saves its input itself.
export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1
for name in "${targets[@]}"; do
  mkdir -p "$work/$name"
  if [ -d "fuzz/corpus/$name" ]; then cp -r "fuzz/corpus/$name/." "$work/$name/"; fi
  args=(-max_total_time="$seconds" -timeout=10 -print_final_stats=1
    -artifact_prefix="$build/fuzz-artifacts/$name-")
  [ -f "fuzz/$name.dict" ] && args+=(-dict="fuzz/$name.dict")
  echo "toroid: fuzzing $name for ${seconds} s"
  if ! "$build/fuzz/${name}_fuzz" "${args[@]}" "$work/$name" >"$work/$name.log" 2>&1; then
    tail -n 60 "$work/$name.log" >&2
    echo "toroid: ${name}_fuzz FAILED (crash input in $build/fuzz-artifacts/)" >&2
    exit 1
  fi
  grep -E '^stat::number_of_executed_units|^Done' "$work/$name.log" || true
done
