#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Renders the pictures of docs/gallery.md into docs/images, one core each,
# and prints one line per picture: the command, toroid's own final line
# (size, samples, threads, wall time, rays) and the CPU time (user + sys).
# Usage: tools/render-gallery.sh [chapters|rtc|stress|tori|path|all]   (from the checkout root,
# after building; the rtc pictures need ../shared/rtc-scenes or
# TOROID_SHARED_DIR)
set -euo pipefail
cd "$(dirname "$0")/.."
shared="${TOROID_SHARED_DIR:-../shared}/rtc-scenes"
which="${1:-all}"

render() {  # OUTPUT SCENE [OPTIONS...]
  local out="$1" scene="$2"
  shift 2
  local cmd="build/toroid render $scene -o docs/images/$out --threads 1 $*"
  local log
  log=$( { /usr/bin/time -f "cpu %U+%S s" $cmd; } 2>&1 | tail -2 | tr '\n' ' ')
  echo "$cmd | $log"
}

if [[ "$which" == chapters || "$which" == all ]]; then
  for s in ch05-silhouette ch06-shaded-sphere ch07-world ch09-planes ch10-patterns ch11-reflect-refract \
           ch12-table ch13-cylinders-cones ch14-hexagon ch15-teapot ch16-csg torus-seed; do
    render "$s.png" "scenes/rtc-chapters/$s.yaml" --samples 16
  done
fi

if [[ "$which" == rtc || "$which" == all ]]; then
  # The three in the README's table, as the README says: 400 x 300, cover 400 x 400.
  render rtc-cover.png "$shared/cover.yml" --width 400 --height 400
  render rtc-reflect-refract.png "$shared/reflect-refract.yml" --width 400 --height 300
  render rtc-csg_difference.kjeldahl.png "$shared/csg_difference.kjeldahl.yml" --width 400 --height 300
  # The other six that need no texture: 400 wide, each scene's own aspect.
  render rtc-chap7-putting-it-together.png "$shared/chap7-putting-it-together.yml" --width 400 --height 200 --samples 4
  render rtc-cylinders.png "$shared/cylinders.yml" --width 400 --height 200 --samples 4
  render rtc-group.png "$shared/group.yml" --width 400 --height 133 --samples 4
  render rtc-shadow-glamour-shot.png "$shared/shadow-glamour-shot.yml" --width 400 --height 225 --samples 4
  render rtc-table.png "$shared/table.yml" --width 400 --height 200 --samples 4
  render rtc-three-spheres.png "$shared/three-spheres.yml" --width 400 --height 200 --samples 4
fi

if [[ "$which" == stress || "$which" == all ]]; then
  # One sample per pixel: anti-aliasing would blur speckles away.
  for s in far-camera thin thin-tiny huge tiny offset-1e12 glass-tiny glass-thin-tiny; do
    render "stress-$s.png" "scenes/stress/$s.yaml"
  done
fi

if [[ "$which" == tori || "$which" == all ]]; then
  # The README's scenes of tori. bitten-doughnut: the half-eaten doughnut
  # closed into a solid (its camera and size).
  render three-doughnuts.png scenes/three-doughnuts.yaml --samples 16
  for s in half-eaten-doughnut spindle-torus soft-shadow-doughnut textured-bagel; do
    render "$s.png" "scenes/$s.yaml" --samples 4
  done
  render bitten-doughnut.png scenes/bitten-doughnut.yaml --samples 16
fi

if [[ "$which" == path || "$which" == all ]]; then
  # The path tracer's hero scene (its `- add: integrator` picks the path
  # integrator); several minutes on one core.
  render bagels-path.png scenes/bagels-path.yaml --samples 256
fi
