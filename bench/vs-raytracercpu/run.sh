#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# toroid against bezdomniy/RayTracerCPU (the fastest public C++ implementation
# of the book we know of) on the book's glass and metal scenes, one core each.
#
#   bench/vs-raytracercpu/run.sh PEER_BINARY [--scenes DIR] [--extra DIR] [--reps N] [--out DIR] [--toroid BINARY]
#
# PEER_BINARY: RayTracerCPU's `RayTracer`, built at 4cf8627 with its own
# Release flags (-O3 -ffast-math -flto); DEVELOPERS.md says how.
# --scenes: the shared RTC scenes (default ../shared/rtc-scenes): cover,
# reflect-refract, table and three-spheres are read from there. --extra: a
# folder holding air-bubble.yml and metal.yml (LukeGrahamLandry/RustyRayTracer's
# scenes/ has both); without it those two are left out, and said so.
#
# Every scene is widened to 1600 px (height in proportion), its brackets
# written without inner spaces and a material's `shadow:` moved up to its
# shape (the peer's parser reads neither), and the same file goes to both.
# Both render on core 0 (taskset), toroid with --threads 1 --max-depth 4 (the
# peer's compiled-in bounce limit), taking turns --reps times (default 3).
# Prints the least user CPU seconds of each and the ratio peer / toroid,
# whole runs: loading, rendering and writing the image (the peer a PPM,
# toroid a PNG). Writes the scenes and images under --out
# (default build/vs-raytracercpu). --toroid: another toroid binary (an older
# build, to compare before and after in one run; default build/toroid).
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
peer=""
scenes_dir="$root/../shared/rtc-scenes"
extra_dir=""
reps=3
out="$root/build/vs-raytracercpu"
toroid="$root/build/toroid"
while [ $# -gt 0 ]; do
  case "$1" in
    --scenes) scenes_dir=$2; shift 2 ;;
    --extra) extra_dir=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --toroid) toroid=$2; shift 2 ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    -*) echo "run.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    *) peer=$1; shift ;;
  esac
done
if [ -z "$peer" ] || [ ! -x "$peer" ]; then
  echo "run.sh: give the peer's RayTracer binary as the first argument (see --help)" >&2
  exit 2
fi
peer=$(cd "$(dirname "$peer")" && pwd)/$(basename "$peer")
"$root/tools/install-deps.sh" python3
if [ "$toroid" = "$root/build/toroid" ] && [ ! -x "$toroid" ]; then
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$root/build" toroid
fi
mkdir -p "$out"
out=$(cd "$out" && pwd)

# widen IN OUT: the scene at 1600 px wide, in the form both parsers read.
widen() {
  python3 - "$1" "$2" <<'EOF'
import re, sys
text = open(sys.argv[1]).read()
w = int(re.search(r"^\s*width:\s*(\d+)", text, re.M).group(1))
h = int(re.search(r"^\s*height:\s*(\d+)", text, re.M).group(1))
text = re.sub(r"^(\s*width:\s*)\d+", lambda m: m.group(1) + "1600", text, count=1, flags=re.M)
text = re.sub(r"^(\s*height:\s*)\d+", lambda m: m.group(1) + str(round(1600 * h / w)), text, count=1, flags=re.M)
text = re.sub(r"\[\s+", "[", text)
text = re.sub(r"\s+\]", "]", text)
text = re.sub(r"^  material:\n    shadow: (\w+)\n", r"  shadow: \1\n  material:\n", text, flags=re.M)
open(sys.argv[2], "w").write(text)
EOF
}

# user_seconds CMD...: the user CPU time of one run, on core 0, to the
# millisecond.
user_seconds() {
  "$root/bench/cpu_seconds.py" --user --stderr "$out/stderr.txt" taskset -c 0 "$@" || {
    echo "run.sh: failed: $*" >&2
    cat "$out/stderr.txt" >&2
    exit 1
  }
}
least() { if [ -z "$1" ]; then echo "$2"; else awk -v a="$1" -v b="$2" 'BEGIN { print (b < a ? b : a) }'; fi; }

list=()
for s in cover reflect-refract table three-spheres; do
  [ -f "$scenes_dir/$s.yml" ] || { echo "run.sh: $scenes_dir/$s.yml not found (--scenes)" >&2; exit 2; }
  list+=("$scenes_dir/$s.yml")
done
for s in air-bubble metal; do
  if [ -n "$extra_dir" ] && [ -f "$extra_dir/$s.yml" ]; then
    list+=("$extra_dir/$s.yml")
  else
    echo "run.sh: $s left out (no --extra folder with $s.yml)" >&2
  fi
done

cpu=$(awk -F': ' '/^model name/ { n = $2 } /^cpu family/ { f = $2 } /^model\t/ { m = $2 } END { print n " (family " f " model " m ")" }' /proc/cpuinfo)
echo "# $cpu, $(date -u +%Y-%m-%d), $toroid"

printf "%-16s %10s %10s %8s\n" scene "peer s" "toroid s" ratio
for path in "${list[@]}"; do
  name=$(basename "$path" .yml)
  widen "$path" "$out/$name.yml"
  mkdir -p "$out/peer-$name"
  p="" t=""
  for _ in $(seq "$reps"); do
    p=$(least "$p" "$(cd "$out/peer-$name" && user_seconds "$peer" -p "$out/$name.yml")")
    [ -s "$out/peer-$name/out.ppm" ] || { echo "run.sh: the peer wrote no image for $name" >&2; exit 1; }
    t=$(least "$t" "$(user_seconds "$toroid" render "$out/$name.yml" -o "$out/$name.png" --threads 1 --max-depth 4 -q)")
  done
  awk -v n="$name" -v p="$p" -v t="$t" 'BEGIN { printf "%-16s %10.3f %10.3f %7.2fx\n", n, p, t, p / t }'
done
