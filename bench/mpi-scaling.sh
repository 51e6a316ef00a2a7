#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# toroid render under mpirun, 1 rank against 2 (one thread each), and the
# inputs of the scaling model in docs/performance.md: the time of one tile,
# and what rank 0 spends per tile it receives from another rank.
#   bench/mpi-scaling.sh [--reps N] [--toroid build/toroid]
# Prints the least wall time of N runs for each, and the ratios.
set -euo pipefail
cd "$(dirname "$0")/.."
reps=3
toroid=build/toroid
while [ $# -gt 0 ]; do
  case "$1" in
    --reps) reps=$2; shift 2 ;;
    --toroid) toroid=$2; shift 2 ;;
    *) echo "usage: bench/mpi-scaling.sh [--reps N] [--toroid PATH]" >&2; exit 2 ;;
  esac
done
# Open MPI refuses root unless told; CI and containers run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

best() {  # LABEL COMMAND...: the least wall time of $reps runs, in seconds
  local label=$1 least=
  shift
  for _ in $(seq "$reps"); do
    local t0 t1 t
    t0=$(date +%s.%N)
    "$@" >/dev/null 2>"$work/log" || { cat "$work/log" >&2; exit 1; }
    t1=$(date +%s.%N)
    t=$(echo "$t1 - $t0" | bc -l)
    if [ -z "$least" ] || [ "$(echo "$t < $least" | bc -l)" = 1 ]; then least=$t; fi
  done
  printf '%-44s %8.3f s   %s\n' "$label" "$least" "$(tail -n 1 "$work/log")" >&2
  echo "$least"
}

echo "CPU: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; $(mpirun --version | head -n 1)" >&2
scene=scenes/bagels.yaml
args=(render "$scene" -o "$work/out.png" --width 800 --height 600 --samples 4 --threads 1)
one=$(best "bagels 800x600x4, 1 rank x 1 thread" mpirun -np 1 "$toroid" "${args[@]}")
two=$(best "bagels 800x600x4, 2 ranks x 1 thread" mpirun --oversubscribe -np 2 "$toroid" "${args[@]}")
single=$(best "bagels 800x600x4, no mpirun, 1 thread" "$toroid" "${args[@]}")
printf 'speed-up, 2 ranks over 1: %.2fx; 1 rank over no mpirun: %.2fx\n' \
  "$(echo "$one / $two" | bc -l)" "$(echo "$single / $one" | bc -l)"
tiles=$(( (800 + 15) / 16 * ((600 + 15) / 16) ))
printf 'one 16x16 tile of bagels at 4 samples, one thread: %.3f ms\n' "$(echo "$single / $tiles * 1000" | bc -l)"

# Rank 0's cost per remote tile: a 4K image of nothing but the sky (no shape,
# so a pixel costs next to nothing), 1 rank against 2.
printf -- '- add: camera\n  width: 3840\n  height: 2160\n  field-of-view: 1\n  from: [0, 0, -5]\n  to: [0, 0, 0]\n  up: [0, 1, 0]\n' \
  >"$work/empty.yaml"
empty=(render "$work/empty.yaml" -o "$work/empty.ppm" --threads 1)
e1=$(best "empty 3840x2160, 1 rank x 1 thread" mpirun -np 1 "$toroid" "${empty[@]}")
e2=$(best "empty 3840x2160, 2 ranks x 1 thread" mpirun --oversubscribe -np 2 "$toroid" "${empty[@]}")
etiles=$(( 3840 / 16 * (2160 / 16) ))
printf 'empty 4K: %d tiles; 1 rank %.3f s, 2 ranks %.3f s\n' "$etiles" "$e1" "$e2"
