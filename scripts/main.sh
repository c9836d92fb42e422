#!/usr/bin/env bash
# The main job: installs what is missing, builds, and answers the example queries with `collide2d query`.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh"
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)" --target collide2d_cli
"$build/tools/collide2d" query < "$root/examples/queries.txt"
