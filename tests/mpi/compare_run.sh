#!/usr/bin/env bash
# `collide2d run` under mpirun against one process on the built-in scene, and on a small scene with
# overlap areas on: every line of the summary but the rank and thread counts, the state hash (one
# process's World), the broad-phase candidates (each rank's broad phase also pairs its ghosts) and
# the times must be the same.
#   compare_run.sh COLLIDE2D MPIEXEC RANKS FRAMES
set -euo pipefail
cli=$1 mpiexec=$2 ranks=$3 frames=$4
counts() { grep -v -E '^(ranks|threads|candidate pairs|broad phase|narrow phase|state hash)' ; }
compare() {
  one=$("$cli" run "$@" 2> /dev/null | counts)
  many=$("$mpiexec" --allow-run-as-root --oversubscribe -np "$ranks" "$cli" run "$@" 2> /dev/null)
  grep -q "^ranks  *$ranks " <<< "$many" || { echo "no 'ranks $ranks' line:"; echo "$many"; exit 1; }
  if [ "$(counts <<< "$many")" != "$one" ]; then
    diff <(echo "$one") <(counts <<< "$many")
    exit 1
  fi
}
compare --frames "$frames"
scene=$(mktemp --suffix .json)
trap 'rm -f "$scene"' EXIT
echo '{"arena": {"min": [0, 0], "max": [20, 10]}, "frames": 2, "contacts": true, "overlap_areas": true, "bodies": [
  {"shape": "circle", "center": [4.5, 5], "radius": 1, "velocity": [3, 0]},
  {"shape": "circle", "center": [5.5, 5], "radius": 1, "velocity": [3, 0.5]},
  {"shape": "ellipse", "center": [12, 5], "a": 2, "b": 1, "angle": 0.3, "velocity": [-2, 0]},
  {"shape": "rect", "center": [10, 4], "half_extents": [8, 1], "static": true, "sensor": true}]}' > "$scene"
compare "$scene" --frames "$frames"
grep -q "^overlap area per frame" <<< "$one" || { echo "no overlap area line:"; echo "$one"; exit 1; }
echo "$ranks ranks: the same summary as one process over $frames frames, with and without overlap areas"
