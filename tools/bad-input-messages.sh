#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs every case of the bad-input corpus (tests/bad-input/) the way
# tests/bad_input_test.cpp does and prints, per case, the exit status and the
# message: tab-separated, or with --markdown one table per kind (the examples
# in docs/errors.md come from here).
# Usage: tools/bad-input-messages.sh [BUILD_DIR] [--all | --markdown]
#   BUILD_DIR defaults to build; --all also runs cases without an .expected.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
toroid="$(cd "${1:-$root/build}" && pwd)/toroid"
corpus="$root/tests/bad-input"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

run_case() {  # kind file
  local kind=$1 file=$2 name
  name=$(basename "$file")
  rm -rf "$work"/* && mkdir -p "$work"
  case $kind in
    scene) (cd "$corpus/scene" && "$toroid" render "$name" -o "$work/out.png" </dev/null 2>&1 >/dev/null) ;;
    obj)
      cp "$file" "$work/"
      printf -- '- add: camera\n  width: 8\n  height: 6\n  field-of-view: 0.8\n  from: [0, 2, -5]\n  to: [0, 0, 0]\n  up: [0, 1, 0]\n- add: obj\n  file: %s\n' "$name" >"$work/scene.yml"
      (cd "$work" && "$toroid" render scene.yml -o out.png </dev/null 2>&1 >/dev/null) ;;
    intersect) (cd "$work" && "$toroid" intersect <"$file" 2>&1 >/dev/null) ;;
    cli)
      local args
      args=$(sed "s|{scene}|$corpus/cli/good-scene.yml|g" "$file")
      (cd "$work" && eval "\"$toroid\" $args" </dev/null 2>&1 >/dev/null) ;;
  esac
}

mode=${2:-}
for kind in scene obj intersect cli; do
  case $kind in scene) ext=yml ;; obj) ext=obj ;; intersect) ext=txt ;; cli) ext=args ;; esac
  if [ "$mode" = --markdown ]; then
    printf '\n| case (`tests/bad-input/%s/`) | exit | message |\n|---|---|---|\n' "$kind"
  fi
  for f in "$corpus/$kind"/*.$ext; do
    [ -e "$f.expected" ] || [ "$mode" = --all ] || continue
    set +e
    msg=$(run_case "$kind" "$f")
    status=$?
    set -e
    msg=$(printf '%s' "$msg" | head -n 1)
    if [ "$mode" = --markdown ]; then
      printf '| `%s` | %s | `%s` |\n' "$(basename "$f")" "$status" "${msg//|/\\|}"
    else
      printf '%s\t%s\t%s\n' "$kind/$(basename "$f")" "$status" "$msg"
    fi
  done
done
