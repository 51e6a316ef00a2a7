#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds toroid with AddressSanitizer + UndefinedBehaviorSanitizer in
# build-asan/ (no benchmarks) and runs every test under it with ctest: any
# sanitizer report fails the test that triggered it. It builds the scalar
# code of the world index (TOROID_SIMD=OFF), which the Release build of
# ./test.sh replaces with SSE2 on x86-64: the suite checks both.
# CI runs the clang equivalent instead (tools/test-clang.sh: ASan + UBSan,
# TOROID_SIMD=OFF, the fuzz targets too); this one is GCC's.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh --tests
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOROID_SANITIZE=ON -DTOROID_SIMD=OFF -DTOROID_BUILD_BENCH=OFF >/dev/null
cmake --build build-asan
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
