#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Memory per torus: peak RSS of `toroid render` (8x8 pixels) on
# scenes of 1 and 10,001 tori, and the heap a loaded scene keeps per torus
# (build/bench/scene_memory_bench). Peak RSS includes the scene file's text
# and yaml-cpp's nodes of one top-level item at a time (the loader never
# holds the whole document's), both freed once the scene is built; the heap
# figure does not.
# For scale, the same tori in POV-Ray 3.7 (peak RSS, 8x8, one thread).
#   bench/memory.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/tools/install-deps.sh" time povray
if [ ! -x "$root/build/toroid" ] || [ ! -x "$root/build/bench/scene_memory_bench" ]; then
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$root/build" toroid scene_memory_bench
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The same tori as scene_memory_bench: own transform and material each (equal
# materials, which the loader shares).
tori() {
  awk -v n="$1" 'BEGIN {
    print "- add: camera\n  width: 8\n  height: 8\n  field-of-view: 1\n  from: [0, 0, -50]\n  to: [0, 0, 0]\n  up: [0, 1, 0]"
    print "- add: light\n  at: [0, 50, -50]\n  intensity: [1, 1, 1]"
    for (i = 0; i < n; i++)
      printf "- add: torus\n  major: 0.4\n  minor: 0.1\n  material:\n    color: [0.8, 0.3, 0.2]\n    specular: 0.4\n  transform:\n    - [rotate-x, %g]\n    - [translate, %d, %d, %d]\n", 0.01 * i, i % 100 - 50, int(i / 100) % 100 - 50, int(i / 10000)
  }'
}

rss() { /usr/bin/time -f "%M" -o "$work/t" "$root/build/toroid" render "$1" -o "$work/out.png" --threads 1 -q; cat "$work/t"; }
tori 1 >"$work/1.yaml"
tori 10001 >"$work/10001.yaml"
r1=$(rss "$work/1.yaml")
r2=$(rss "$work/10001.yaml")
echo "peak RSS, toroid render 8x8: 1 torus ${r1} KiB, 10,001 tori ${r2} KiB: $(( (r2 - r1) * 1024 / 10000 )) bytes per torus (scene text included)"
"$root/build/bench/scene_memory_bench" 2>/dev/null | grep '^BM_'

# POV-Ray: the same tori (its torus lies in the xz-plane; the orientation
# does not matter for memory), one pigment and finish each.
pov_tori() {
  awk -v n="$1" 'BEGIN {
    print "camera { location <0, 0, -50> look_at <0, 0, 0> angle 57 }"
    print "light_source { <0, 50, -50> rgb 1 }"
    for (i = 0; i < n; i++)
      printf "torus { 0.4, 0.1 pigment { rgb <0.8, 0.3, 0.2> } finish { specular 0.4 } rotate x * %g translate <%d, %d, %d> }\n", 0.573 * i, i % 100 - 50, int(i / 100) % 100 - 50, int(i / 10000)
  }'
}
pov_rss() {
  (cd "$work" && /usr/bin/time -f "%M" -o "$work/t" povray "+I$1" +O"$work/pov.png" +W8 +H8 -D -V +WT1 -GA >/dev/null 2>&1)
  cat "$work/t"
}
pov_tori 1 >"$work/1.pov"
pov_tori 10001 >"$work/10001.pov"
p1=$(pov_rss "$work/1.pov")
p2=$(pov_rss "$work/10001.pov")
echo "POV-Ray 3.7 peak RSS, 8x8: 1 torus ${p1} KiB, 10,001 tori ${p2} KiB: $(( (p2 - p1) * 1024 / 10000 )) bytes per torus"
