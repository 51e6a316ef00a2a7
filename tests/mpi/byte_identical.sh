#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# `mpirun -np N toroid render` makes the single-process image, byte for byte,
# for 1, 2 and 3 ranks with 1 and 2 threads each (and with another tile
# size), and every rank renders part of it.
#   tests/mpi/byte_identical.sh MPIEXEC TOROID SOURCE_DIR WORK_DIR
set -euo pipefail
mpiexec=$1 toroid=$2 source=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
scene=$source/scenes/bitten-doughnut.yaml
size=(--width 320 --height 240 --samples 2)
"$toroid" render "$scene" -o "$work/single.png" "${size[@]}" --threads 2 --quiet
status=0
for ranks in 1 2 3; do
  for threads in 1 2; do
    out=$work/ranks$ranks-threads$threads.png
    "$mpiexec" --oversubscribe -np "$ranks" "$toroid" render "$scene" -o "$out" "${size[@]}" --threads "$threads" \
      2>"$work/log"
    summary=$(tail -n 1 "$work/log")
    if ! cmp -s "$work/single.png" "$out"; then
      echo "FAIL: $ranks ranks x $threads threads: the image differs from the single-process render" >&2
      status=1
    fi
    echo "$ranks ranks x $threads threads: same image; $summary"
  done
done
"$mpiexec" --oversubscribe -np 3 "$toroid" render "$scene" -o "$work/tiles7.png" "${size[@]}" --threads 1 \
  --tile-size 7 2>"$work/log"
if ! cmp -s "$work/single.png" "$work/tiles7.png"; then
  echo "FAIL: 3 ranks with 7-pixel tiles: the image differs from the single-process render" >&2
  status=1
fi
echo "3 ranks, --tile-size 7: same image; $(tail -n 1 "$work/log")"

# The new outputs and options go the same way: an EXR with --exposure, and a
# --linear PNG with the path integrator's summary.
"$toroid" render "$scene" -o "$work/single.exr" "${size[@]}" --exposure 1.5 --threads 2 --quiet
"$mpiexec" --oversubscribe -np 2 "$toroid" render "$scene" -o "$work/ranks2.exr" "${size[@]}" --exposure 1.5 \
  --threads 1 2>"$work/log"
if ! cmp -s "$work/single.exr" "$work/ranks2.exr"; then
  echo "FAIL: 2 ranks, .exr with --exposure 1.5: the image differs from the single-process render" >&2
  status=1
fi
echo "2 ranks, .exr, --exposure 1.5: same image; $(tail -n 1 "$work/log")"
"$toroid" render "$scene" -o "$work/single-linear.png" "${size[@]}" --linear --integrator path --threads 2 --quiet
"$mpiexec" --oversubscribe -np 2 "$toroid" render "$scene" -o "$work/ranks2-linear.png" "${size[@]}" --linear \
  --integrator path --threads 1 2>"$work/log"
summary=$(tail -n 1 "$work/log")
if ! cmp -s "$work/single-linear.png" "$work/ranks2-linear.png"; then
  echo "FAIL: 2 ranks, --linear --integrator path: the image differs from the single-process render" >&2
  status=1
fi
if [[ "$summary" != *", 2 samples, path integrator, 2 ranks, "* ]]; then
  echo "FAIL: the summary does not name the path integrator: '$summary'" >&2
  status=1
fi
echo "2 ranks, --linear --integrator path: same image; $summary"

# Every rank renders part of the image: "..., 3 ranks, 3 threads (tiles by
# rank: 171 62 67), ...". Long enough (16 samples) that a rank started late
# on a busy machine still finds work left.
"$mpiexec" --oversubscribe -np 3 "$toroid" render "$scene" -o "$work/shared.png" --width 320 --height 240 --samples 16 --threads 1 \
  2>"$work/log"
summary=$(tail -n 1 "$work/log")
read -r -a counts <<<"$(sed -n 's/.*(tiles by rank:\([0-9 ]*\)).*/\1/p' <<<"$summary")"
if [ "${#counts[@]}" -ne 3 ]; then
  echo "FAIL: no tile count for each of the 3 ranks in '$summary'" >&2
  status=1
fi
for c in "${counts[@]}"; do
  if [ "$c" -eq 0 ]; then
    echo "FAIL: a rank rendered no tile: '$summary'" >&2
    status=1
  fi
done
echo "3 ranks, 16 samples: $summary"
exit $status
