#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The checks of the CUDA batch that need a GPU (docs/gpu.md), in one run for
# a machine that has one: configures a CUDA build in BUILD_DIR (default
# build-gpu), builds only the CUDA test and toroid_gpu_check, runs the test
# (the accuracy families and bad inputs against the CPU batch), then
# toroid_gpu_check, which prints the tables: the families through the kernel
# with the CPU's bars, rows that differ from the CPU's bits with --fmad=false
# and with --fmad=true (and by how many ulps), the bad inputs, and rays per
# second for 2^24 mixed rays (kernel time by CUDA events, with transfers, and
# the CPU batch on every core). About 3 to 5 minutes on 16 cores, most of it
# the build. Without a GPU it builds, the test skips and the program runs
# its CPU half; the script then exits 77.
#
#   tools/gpu-check.sh [BUILD_DIR] [-- toroid_gpu_check options]
#   e.g. tools/gpu-check.sh build-gpu -- --rays-per-family 500 --speed-rays 1048576
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build-gpu"
if [ $# -gt 0 ] && [ "$1" != "--" ]; then
  build=$1
  shift
fi
[ "${1:-}" = "--" ] && shift
nvcc=${CUDACXX:-$(command -v nvcc || echo /usr/local/cuda/bin/nvcc)}
jobs=$(nproc)
start=$SECONDS
step() { echo "== $* ($((SECONDS - start)) s)"; }

mkdir -p "$build"
step "configure $build with $nvcc"
# The renderer's link-time optimisation, the bench, Python, Embree and MPI
# are left out: none is on the path checked, and they would lengthen the build.
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DTOROID_CUDA=ON -DCMAKE_CUDA_COMPILER="$nvcc" \
  -DTOROID_LTO=OFF -DTOROID_BUILD_BENCH=OFF -DTOROID_PYTHON=OFF -DTOROID_EMBREE=OFF -DTOROID_MPI=OFF >"$build/gpu-check-configure.log" 2>&1 ||
  { tail -30 "$build/gpu-check-configure.log"; exit 1; }
step "build toroid_cuda_tests toroid_gpu_check (-j$jobs)"
ninja -C "$build" -j "$jobs" toroid_cuda_tests toroid_gpu_check >"$build/gpu-check-build.log" 2>&1 ||
  { tail -40 "$build/gpu-check-build.log"; exit 1; }

status=0
step "toroid_cuda_tests"
"$build/cuda/toroid_cuda_tests" || status=1

step "toroid_gpu_check $*"
rc=0
"$build/cuda/toroid_gpu_check" "$@" || rc=$?
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
