#!/usr/bin/env bash
# The main job: installs what is missing, builds, and runs the built-in scene (4000 moving circles,
# ellipses and rectangles, and 8 continuous bullets) with `collide2d run`, writing a picture of the
# last frame.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh"
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build" -j "$(nproc)" --target collide2d_cli
"$build/tools/collide2d" run --svg "$build/scene.svg"
