#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The ThreadSanitizer job of CI, in build-ci-tsan/: clang++ 14 with -Werror
# builds toroid and its tests with -fsanitize=thread against a libtbb built
# with ThreadSanitizer too (tools/build-tbb-tsan.sh: Debian's oneTBB source,
# same version as libtbb-dev), and runs the whole suite with ctest. Any data
# race report fails the test that made it (TSan exits non-zero); there is no
# suppression file.
#
# Debian's libtbb is not instrumented: against it TSan reports every
# hand-over of work between the main thread and TBB's workers (the
# synchronisation inside libtbb is invisible to it), so this build insists
# on the instrumented one.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh --tests clang libclang-rt-14-dev dpkg-dev xz-utils  # dpkg-dev: apt-get source unpacks with dpkg-source
export CXX=clang++ CC=clang
prefix=$PWD/build-ci-tbb-tsan/prefix
tools/build-tbb-tsan.sh "$prefix"
build=build-ci-tsan
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DTOROID_SANITIZE_THREAD=ON \
  -DTOROID_BUILD_BENCH=OFF -DTOROID_WERROR=ON -DCMAKE_PREFIX_PATH="$prefix" -DTBB_DIR="$prefix/lib/cmake/TBB" >/dev/null
cmake --build "$build" -j "$(nproc)"
# The tests must load the instrumented libtbb, not Debian's. ldd's listing is
# held in a variable first: under pipefail, `ldd | grep -q` fails whenever grep
# stops reading early and ldd dies of SIGPIPE.
libraries=$(ldd "$build/tests/toroid_tests")
if [[ "$libraries" != *"$prefix/lib/libtbb"* ]]; then
  echo "toroid: $build/tests/toroid_tests does not load $prefix/lib/libtbb:" >&2
  grep tbb <<<"$libraries" >&2
  exit 1
fi
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:history_size=4
# setarch -R: without address randomisation, so that clang 14's TSan also runs
# on kernels with vm.mmap_rnd_bits above 28 (it cannot map its shadow there).
setarch "$(uname -m)" -R ctest --test-dir "$build" --output-on-failure -j "$(nproc)"
