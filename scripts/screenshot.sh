#!/usr/bin/env bash
# Makes the README's picture of the replay page, docs/images/replay.png (or the path given): runs
# the built-in scene for 240 frames with the built `collide2d` (BUILD_DIR, default build/), writes
# its replay page, and photographs it in Debian's chromium (tests/browser/screenshot.mjs).
#   bash scripts/screenshot.sh [OUT.png]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$root/docs/images/replay.png}")
build=${BUILD_DIR:-$root/build}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$build/tools/collide2d" run --frames 240 --html "$work/scene.html" > /dev/null 2>&1
mkdir -p "$(dirname "$out")"
(cd "$work" && node "$root/tests/browser/screenshot.mjs" scene.html "$out")
echo "picture of the replay page: $out"
