#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Thread scaling of `toroid render` on a render of a few seconds. Renders one scene at
# --threads 1 and at --threads 2, --reps times each, and prints the least
# wall time of each, the speed-up (wall 1 / wall 2) and the CPU time (user +
# sys) of each. Run it on an otherwise idle machine: the wall-clock ratio is
# only meaningful when both cores are free. The three kinds of run take
# turns within each rep, so that a machine whose speed drifts slows them
# alike. As a control it also runs two 1-thread renders at once: on a
# virtual machine whose two cores slow each other down (their host's
# hyperthreads, a busy neighbour), that pair's speed-up over one render is
# the most any program gets from the second core there.
#
#   bench/scaling.sh [--reps N] [SCENE.yaml [WIDTH HEIGHT]]
#
# Default scene: bench/vs-povray's 25 tori over a reflective checker floor,
# at 2560x1440, a few seconds on one core: long enough that loading the
# scene and writing the PNG, which are serial, weigh little.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
reps=3
if [ "${1:-}" = "--reps" ]; then reps=$2; shift 2; fi
toroid="$root/build/toroid"
if [ ! -x "$toroid" ]; then
  "$root/tools/install-deps.sh" time
  cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  ninja -C "$root/build" toroid
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene=${1:-}
size=()
if [ -z "$scene" ]; then
  scene="$work/tori25.yaml"
  awk -v scene=tori25 -v format=yaml -f "$root/bench/vs-povray/scenes.awk" >"$scene"
  size=(--width 2560 --height 1440)
fi
[ $# -ge 3 ] && size=(--width "$2" --height "$3")

# One run: "WALL CPU" (seconds; CPU = user + sys).
run_one() {
  /usr/bin/time -f "%e %U %S" -o "$work/t$2" "$toroid" render "$scene" -o "$work/out$2.png" "${size[@]}" --threads "$1" -q
  read -r wall user sys <"$work/t$2"
  echo "$wall $(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')"
}
least() { awk -v a="$1" -v b="$2" 'BEGIN { print (b == "" || a < b) ? a : b }'; }

w1="" c1="" w2="" c2="" wp=""
for ((i = 0; i < reps; i++)); do
  read -r w c < <(run_one 1 a)
  w1=$(least "$w" "$w1") c1=$(least "$c" "$c1")
  read -r w c < <(run_one 2 a)
  w2=$(least "$w" "$w2") c2=$(least "$c" "$c2")
  # The control: two 1-thread renders at once; the pair's wall time.
  start=$(date +%s.%N)
  run_one 1 b >/dev/null &
  run_one 1 c >/dev/null
  wait
  w=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }')
  wp=$(least "$w" "$wp")
done
echo "scene: ${1:-bench/vs-povray tori25} ${size[*]}"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; least of $reps runs; load average now: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-10s %8s %8s\n' threads wall_s cpu_s
printf '%-10s %8s %8s\n' 1 "$w1" "$c1"
printf '%-10s %8s %8s\n' 2 "$w2" "$c2"
echo "speed-up 1 -> 2 threads (wall): $(awk -v a="$w1" -v b="$w2" 'BEGIN { printf "%.2f", a / b }') (bar: >= 1.8)"
echo "CPU work 2 threads / 1 thread: $(awk -v a="$c2" -v b="$c1" 'BEGIN { printf "%.2f", a / b }') (1.00: no work added by threading)"
echo "control, two 1-thread renders at once: $wp s for both, a speed-up of $(awk -v a="$w1" -v b="$wp" 'BEGIN { printf "%.2f", 2 * a / b }') over one (this machine's two cores)"
