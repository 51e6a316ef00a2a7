#!/usr/bin/env bash
# Thread scaling of `toroid render` (issue 6: CPU work scales >= 1.8x from
# 1 to 2 threads on a render of a few seconds). Renders one scene at
# --threads 1 and at --threads 2, --reps times each, and prints the least
# wall time of each, the speed-up (wall 1 / wall 2) and the CPU time (user +
# sys) of each. Run it on an otherwise idle machine: the wall-clock ratio is
# only meaningful when both cores are free.
#
#   bench/scaling.sh [--reps N] [SCENE.yaml [WIDTH HEIGHT]]
#
# Default scene: bench/vs-povray's 25 tori over a reflective checker floor,
# at 1920x1080 (a few seconds on one core of an AMD EPYC).
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
  size=(--width 1920 --height 1080)
fi
[ $# -ge 3 ] && size=(--width "$2" --height "$3")

# least wall and CPU seconds over the reps: "WALL CPU"
measure() {
  local best_wall="" best_cpu=""
  for ((i = 0; i < reps; i++)); do
    /usr/bin/time -f "%e %U %S" -o "$work/t" "$toroid" render "$scene" -o "$work/out.png" "${size[@]}" --threads "$1" -q
    read -r wall user sys <"$work/t"
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.2f", u + s }')
    if [ -z "$best_wall" ] || awk -v a="$wall" -v b="$best_wall" 'BEGIN { exit !(a < b) }'; then best_wall=$wall; fi
    if [ -z "$best_cpu" ] || awk -v a="$cpu" -v b="$best_cpu" 'BEGIN { exit !(a < b) }'; then best_cpu=$cpu; fi
  done
  echo "$best_wall $best_cpu"
}

read -r w1 c1 < <(measure 1)
read -r w2 c2 < <(measure 2)
echo "scene: ${1:-bench/vs-povray tori25} ${size[*]}"
echo "machine: $(lscpu | sed -n 's/^Model name: *//p'), $(nproc) cores; least of $reps runs; load average now: $(cut -d' ' -f1-3 /proc/loadavg)"
printf '%-10s %8s %8s\n' threads wall_s cpu_s
printf '%-10s %8s %8s\n' 1 "$w1" "$c1"
printf '%-10s %8s %8s\n' 2 "$w2" "$c2"
echo "speed-up 1 -> 2 threads (wall): $(awk -v a="$w1" -v b="$w2" 'BEGIN { printf "%.2f", a / b }') (bar: >= 1.8)"
echo "CPU work 2 threads / 1 thread: $(awk -v a="$c2" -v b="$c1" 'BEGIN { printf "%.2f", a / b }') (1.00: no work added by threading)"
