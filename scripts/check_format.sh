#!/usr/bin/env bash
# Fails, listing the places, when a C++ file of the tree differs from what clang-format makes of it
# (.clang-format). Fix them all: bash scripts/check_format.sh --fix
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mapfile -t files < <(cd "$root" && find include shapes broadphase narrowphase engine tools examples tests bench \
  \( -name '*.h' -o -name '*.cpp' \) -not -path 'tests/fuzz/corpus/*' | sort)
cd "$root"
if [[ ${1:-} == --fix ]]; then
  clang-format -i "${files[@]}"
else
  clang-format --dry-run --Werror "${files[@]}"
fi
