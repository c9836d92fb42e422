#!/usr/bin/env bash
# `collide2d run` under mpirun against one process on the built-in scene: every line of the summary
# but the rank and thread counts, the state hash (one process's World), the broad-phase candidates (each rank's broad phase also pairs its ghosts) and
# the times must be the same.
#   compare_run.sh COLLIDE2D MPIEXEC RANKS FRAMES
set -euo pipefail
cli=$1 mpiexec=$2 ranks=$3 frames=$4
counts() { grep -v -E '^(ranks|threads|candidate pairs|broad phase|narrow phase|state hash)' ; }
one=$("$cli" run --frames "$frames" 2> /dev/null | counts)
many=$("$mpiexec" --allow-run-as-root --oversubscribe -np "$ranks" "$cli" run --frames "$frames" 2> /dev/null)
grep -q "^ranks  *$ranks " <<< "$many" || { echo "no 'ranks $ranks' line:"; echo "$many"; exit 1; }
if [ "$(counts <<< "$many")" != "$one" ]; then
  diff <(echo "$one") <(counts <<< "$many")
  exit 1
fi
echo "$ranks ranks: the same summary as one process over $frames frames"
