#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# What goes wrong in an MPI job ends it with a clear message, a non-zero
# status and no output file: a scene error (reported once), a scene that one
# rank cannot read, a rank whose scene differs, a rank killed mid-render
# (SIGKILL), a rank told to stop (SIGTERM, as a batch system does) and
# Ctrl-C (SIGINT) on mpirun; ranks given different
# --exposure, --linear or --integrator options.
#   tests/mpi/faults.sh CASE MPIEXEC TOROID SOURCE_DIR WORK_DIR
#   CASE: scene-error | unreadable-on-one-rank | different-scene | different-options | killed-rank | terminated-rank | interrupt
set -euo pipefail
case_name=$1 mpiexec=$2 toroid=$3 source=$4 work=$5
rm -rf "$work" && mkdir -p "$work/out"
out=$work/out/image.png
scene=$source/scenes/bitten-doughnut.yaml
small=(--width 64 --height 48)

fail() {
  echo "FAIL: $*" >&2
  echo "--- stderr:" >&2
  cat "$work/log" >&2
  exit 1
}

# The job's exit status, its stderr in $work/log, and no file in $work/out.
expect_failure() {  # PATTERN COUNT: stderr holds PATTERN (grep -F) COUNT times
  local status=$1 pattern=$2 count=$3
  [ "$status" -ne 0 ] || fail "$case_name: the job exited 0"
  local seen
  seen=$(grep -c -F -- "$pattern" "$work/log" || true)
  [ "$seen" -eq "$count" ] || fail "$case_name: expected '$pattern' $count time(s) on stderr, saw it $seen time(s)"
  [ -z "$(ls -A "$work/out")" ] || fail "$case_name: files were left in the output folder: $(ls -A "$work/out")"
  echo "$case_name: exit $status; '$pattern' on stderr; no output"
}

# The pid of rank `rank` of the job writing $out, once it has started.
rank_pid() {
  local rank=$1 p
  for _ in $(seq 100); do
    for p in /proc/[0-9]*; do
      # a process of toroid's whose command line names $out, with the rank in its environment
      [[ "$(tr '\0' ' ' <"$p/cmdline" 2>/dev/null)" == *"render "*"$out"* ]] || continue
      if tr '\0' '\n' <"$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$rank"; then
        echo "${p#/proc/}"
        return
      fi
    done
    sleep 0.1
  done
}

# Waits up to $2 s for the background job $1 and sets `waited` to its exit
# status, or to 124 (killing it) when it is still running.
wait_for() {
  local pid=$1 limit=$2
  waited=124
  for _ in $(seq $((limit * 10))); do
    if ! kill -0 "$pid" 2>/dev/null; then
      waited=0
      wait "$pid" || waited=$?
      return
    fi
    sleep 0.1
  done
  kill -9 "$pid" 2>/dev/null || true
}

long_render() {  # a render of some 15 s on 2 ranks (unloaded), in the background
  "$mpiexec" --oversubscribe -np 2 "$toroid" render "$source/scenes/bagels.yaml" -o "$out" --samples 512 --threads 1 \
    2>"$work/log" &
  job=$!
  # It has started once rank 1 runs and rank 0's first tiles are done.
  [ -n "$(rank_pid 1)" ] || fail "$case_name: rank 1 never started"
  sleep 1.5
}

# Sends SIGNAL to PID (a rank, or mpiexec) of the long render; the job must
# end within 20 s and fail as expect_failure says, with PATTERN once.
signal_job() {  # SIGNAL PID PATTERN
  kill "-$1" "$2"
  wait_for "$job" 20
  [ "$waited" -ne 124 ] || fail "$case_name: the job still ran 20 s after SIG$1"
  expect_failure "$waited" "$3" 1
}

status=0
case "$case_name" in
  scene-error)
    printf -- '- add: sphre\n' >"$work/bad.yaml"
    "$mpiexec" --oversubscribe -np 3 "$toroid" render "$work/bad.yaml" -o "$out" 2>"$work/log" || status=$?
    expect_failure "$status" "bad.yaml:1:8: unknown shape 'sphre' (did you mean 'sphere'?)" 1
    ;;
  unreadable-on-one-rank)
    # rank 1 is given a path that does not exist, as on a node without the shared folder
    "$mpiexec" --oversubscribe -np 1 "$toroid" render "$scene" -o "$out" "${small[@]}" : \
      -np 1 "$toroid" render "$work/missing/scene.yaml" -o "$out" "${small[@]}" 2>"$work/log" || status=$?
    expect_failure "$status" "toroid render: rank 1: cannot read scene '$work/missing/scene.yaml'" 1
    ;;
  different-scene)
    cp "$scene" "$work/stale.yaml"
    echo "# a stale copy" >>"$work/stale.yaml"
    "$mpiexec" --oversubscribe -np 2 "$toroid" render "$scene" -o "$out" "${small[@]}" : \
      -np 1 "$toroid" render "$work/stale.yaml" -o "$out" "${small[@]}" 2>"$work/log" || status=$?
    expect_failure "$status" "toroid render: rank 2: its scene file or options differ from rank 0's" 1
    ;;
  different-options)
    # rank 1 alone is given each option: the ranks must refuse to render
    for extra in "--exposure 1" "--exposure 1e-9" "--linear" "--integrator path"; do
      status=0
      # shellcheck disable=SC2086 # $extra is two words
      "$mpiexec" --oversubscribe -np 1 "$toroid" render "$scene" -o "$out" "${small[@]}" : \
        -np 1 "$toroid" render "$scene" -o "$out" "${small[@]}" $extra 2>"$work/log" || status=$?
      expect_failure "$status" "toroid render: rank 1: its scene file or options differ from rank 0's" 1
    done
    ;;
  killed-rank)
    long_render
    signal_job KILL "$(rank_pid 1)" "process rank 1"
    ;;
  terminated-rank)
    # rank 1 alone is told to stop: rank 0 reports it and ends the job
    long_render
    signal_job TERM "$(rank_pid 1)" "toroid render: interrupted; nothing written"
    ;;
  interrupt)
    long_render
    signal_job INT "$job" "toroid render: interrupted; nothing written"
    ;;
  *)
    echo "unknown case '$case_name'" >&2
    exit 2
    ;;
esac
