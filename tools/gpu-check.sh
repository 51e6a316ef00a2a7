#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The checks of the CUDA batch that need a GPU (docs/gpu.md), in one run for
# a machine that has one. It builds toroid_cuda_tests and toroid_gpu_check
# (CUDA build in BUILD_DIR, default build-gpu), runs the test (the accuracy
# families and bad inputs against the CPU batch), then toroid_gpu_check,
# which prints the tables: the families through the kernel with the CPU's
# bars, rows that differ from the CPU's bits with --fmad=false and with
# --fmad=true (and by how many ulps), the bad inputs, and rays per second for
# 2^24 mixed rays (kernel time by CUDA events, with transfers, and the CPU
# batch on every core). Without a GPU it builds, the test skips and the
# program runs its CPU half; the script then exits 77.
#
# A GPU machine without the project's Debian packages (yaml-cpp, MPFR,
# GoogleTest...) cannot build it: --bundle builds here and copies the two
# programs and the shared libraries they need beyond the C and C++ runtimes
# into DIR; --run runs such a bundle there, building nothing.
#
#   tools/gpu-check.sh [BUILD_DIR] [-- toroid_gpu_check options]
#   tools/gpu-check.sh --bundle DIR [BUILD_DIR]
#   tools/gpu-check.sh --run DIR [-- toroid_gpu_check options]
#   e.g. tools/gpu-check.sh build-gpu -- --rays-per-family 500 --speed-rays 1048576
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-gpu"
mode=check
bundle=
case "${1:-}" in
  --bundle | --run)
    mode=${1#--}
    bundle=${2:?"$1 needs a folder"}
    shift 2
    ;;
esac
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  build=$1
  shift
fi
[ "${1:-}" = "--" ] && shift
start=$SECONDS
step() { echo "== $* ($((SECONDS - start)) s)"; }

build_programs() {
  local nvcc=${CUDACXX:-$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)}
  local jobs
  jobs=$(nproc)
  mkdir -p "$build"
  step "configure $build with $nvcc"
  # The renderer's link-time optimisation, the bench, Python, Embree and MPI
  # are left out: none is on the path checked, and they would lengthen the build.
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTOROID_CUDA=ON -DCMAKE_CUDA_COMPILER="$nvcc" \
    -DTOROID_LTO=OFF -DTOROID_BUILD_BENCH=OFF -DTOROID_PYTHON=OFF -DTOROID_EMBREE=OFF -DTOROID_MPI=OFF \
    >"$build/gpu-check-configure.log" 2>&1 || { tail -30 "$build/gpu-check-configure.log"; exit 1; }
  step "build toroid_cuda_tests toroid_gpu_check (-j$jobs)"
  ninja -C "$build" -j "$jobs" toroid_cuda_tests toroid_gpu_check >"$build/gpu-check-build.log" 2>&1 ||
    { tail -40 "$build/gpu-check-build.log"; exit 1; }
}

# Copies the programs and every shared library ldd resolves for them, except
# the C and C++ runtimes and the dynamic loader, which the GPU machine has.
make_bundle() {
  rm -rf "$bundle"
  mkdir -p "$bundle/lib"
  cp "$build/cuda/toroid_cuda_tests" "$build/cuda/toroid_gpu_check" "$bundle/"
  ldd "$bundle/toroid_cuda_tests" "$bundle/toroid_gpu_check" | awk '$2 == "=>" && $3 ~ /^\// { print $3 }' | sort -u |
    grep -Ev '/(libc|libm|libdl|libpthread|librt|libstdc\+\+|libgcc_s|ld-linux[^/]*)\.so' |
    while read -r lib; do cp -L "$lib" "$bundle/lib/"; done
  step "bundle $bundle: $(ls "$bundle/lib" | tr '\n' ' ')"
}

run_checks() {
  local dir=$1
  local status=0 rc=0
  step "toroid_cuda_tests"
  "$dir/toroid_cuda_tests" || status=1
  step "toroid_gpu_check $*"
  "$dir/toroid_gpu_check" "${@:2}" || rc=$?
  if [ "$rc" -ne 0 ] && [ "$rc" -ne 77 ]; then status=1; fi
  step "done"
  if [ "$status" -ne 0 ]; then
    echo "gpu-check: FAILED"
    exit 1
  fi
  if [ "$rc" -eq 77 ]; then
    echo "gpu-check: no CUDA device, the GPU half was skipped"
    exit 77
  fi
  echo "gpu-check: passed"
}

case $mode in
  check)
    build_programs
    run_checks "$build/cuda" "$@"
    ;;
  bundle)
    build_programs
    make_bundle
    ;;
  run)
    bundle=$(cd "$bundle" && pwd)
    export LD_LIBRARY_PATH="$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
    run_checks "$bundle" "$@"
    ;;
esac
