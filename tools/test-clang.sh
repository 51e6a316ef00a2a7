#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The Clang job of CI, in build-ci-clang/: clang++ 14 (Debian's clang) with
# -Werror builds everything (library, command, tests, benchmarks, fuzz
# targets) with AddressSanitizer + UndefinedBehaviorSanitizer and libFuzzer's
# coverage (-DTOROID_FUZZ=ON) and the scalar code of the world index
# (TOROID_SIMD=OFF; ./test.sh checks the SSE2 code). Then it runs every test
# with ctest (any sanitizer report fails the test that made it) and each
# fuzz target for a bounded time on a copy of its corpus, with its
# dictionary when it has one: any crash, sanitizer report, leak, timeout or
# out-of-memory fails.
#
# TOROID_FUZZ_SECONDS (default 60) is the time per fuzz target; 0 skips the
# fuzz runs. Crash inputs land in build-ci-clang/fuzz-artifacts/.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh --tests clang libclang-rt-14-dev libfuzzer-14-dev
build=build-ci-clang
CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOROID_FUZZ=ON \
  -DTOROID_SIMD=OFF -DTOROID_WERROR=ON >/dev/null
cmake --build "$build" -j "$(nproc)"
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
# halt_on_error: clang's -fsanitize=undefined recovers unless told to stop.
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"

tools/fuzz-bounded.sh "$build"
