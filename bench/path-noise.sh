#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Time to a noise level for the path integrator: renders a scene (default
# the hero scene, scenes/bagels-path.yaml) at a reference sample count, then
# at fewer samples, and prints each render's time and its RMS difference
# from the reference, in the linear values a PPM holds (0..1). The noise of
# an unbiased estimate falls as 1/sqrt(samples); the last column checks it.
#
#   bench/path-noise.sh [--scene F] [--size WxH] [--reference N] [--samples "4 16 64"]
#                       [--threads N] [--target RMSE] [--build DIR]
#
# The reference's own noise is sqrt(N / reference) of the noise at N samples:
# keep the reference at least 16 times the largest count measured.
set -euo pipefail
cd "$(dirname "$0")/.."
scene=scenes/bagels-path.yaml
size=320x200
reference=1024
counts="4 16 64"
threads=
target=0.01
build=build
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) scene=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --reference) reference=$2; shift 2 ;;
    --samples) counts=$2; shift 2 ;;
    --threads) threads=$2; shift 2 ;;
    --target) target=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    *) echo "path-noise.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
toroid=$build/toroid
[ -x "$toroid" ] || { echo "path-noise.sh: no $toroid (build it first: ninja -C $build toroid)" >&2; exit 2; }
width=${size%x*}
height=${size#*x}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
thread_args=()
[ -n "$threads" ] && thread_args=(--threads "$threads")

render() {  # render SAMPLES OUT: prints the render's wall seconds
  local start end
  start=$(date +%s.%N)
  "$toroid" render "$scene" -o "$2" --width "$width" --height "$height" --samples "$1" \
    --integrator path -q "${thread_args[@]}"
  end=$(date +%s.%N)
  python3 -c "print(f'{$end - $start:.2f}')"
}

echo "path-noise.sh: $scene at ${width}x${height}, reference $reference samples" \
  "($(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores, threads: ${threads:-all}, $(date -u +%F))"
ref_time=$(render "$reference" "$work/reference.ppm")
echo "reference: $reference samples in $ref_time s"
rows=()
for n in $counts; do
  t=$(render "$n" "$work/$n.ppm")
  rows+=("$n $t $work/$n.ppm")
done
python3 - "$work/reference.ppm" "$target" "${rows[@]}" <<'EOF'
import math
import sys

def read_ppm(path):
    words = open(path).read().split()
    assert words[0] == "P3", path
    w, h, top = int(words[1]), int(words[2]), int(words[3])
    return [int(v) / top for v in words[4:4 + 3 * w * h]]

ref = read_ppm(sys.argv[1])
target = float(sys.argv[2])
print(f"{'samples':>8} {'seconds':>8} {'RMSE':>9} {'RMSE*sqrt(N)':>13}")
last = None
for row in sys.argv[3:]:
    n, t, path = row.split()
    img = read_ppm(path)
    rmse = math.sqrt(sum((a - b) ** 2 for a, b in zip(img, ref)) / len(ref))
    print(f"{int(n):>8} {float(t):>8.2f} {rmse:>9.5f} {rmse * math.sqrt(int(n)):>13.4f}")
    last = (int(n), float(t), rmse)
n, t, rmse = last
if rmse > 0:
    need = n * (rmse / target) ** 2
    print(f"RMSE {target} needs about {need:.0f} samples, {t * need / n:.1f} s at this size "
          f"(from {n} samples, noise falling as 1/sqrt(samples))")
EOF
