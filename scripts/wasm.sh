#!/usr/bin/env bash
# Builds the library for WebAssembly with Debian's Emscripten, and from it two programs in WORK_DIR:
# testbed.html, the testbed page (docs/testbed.md: the kernels and the command line's query grammar
# in one HTML file that needs no server); golden.js, the golden scene (tests/regression/golden.cpp)
# for node, which ctest golden_hashes_wasm runs against the committed hashes; and digest.js, the query
# digest (tests/regression/digest.cpp), which ctest query_digest_wasm compares with the committed
# one. The build runs it (the `wasm` target, with COLLIDE2D_BUILD_TESTBED), with the library's and
# the baselines' sources:
#   bash scripts/wasm.sh WORK_DIR SOURCE.cpp...
# Highway keeps to its one static target (its WebAssembly vectors have no doubles in Debian's
# version, and the static target needs no run-time dispatch), and the World to one thread. The
# links stay at -O1, as Emscripten's -O2 JavaScript passes need npm's acorn.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(realpath -m "$1")
shift
command -v emcc > /dev/null || { echo "wasm.sh: no emcc (apt-get install emscripten)" >&2; exit 1; }
mkdir -p "$work/include" "$work/obj"
# Highway's and nlohmann-json's headers alone, not the host's C library's.
ln -sfn /usr/include/hwy "$work/include/hwy"
ln -sfn /usr/include/nlohmann "$work/include/nlohmann"
flags=(-std=c++20 -O2 -fexceptions -ffp-contract=off -fno-math-errno -DHWY_COMPILE_ONLY_STATIC=1 -DEIGEN_DONT_VECTORIZE
  -DEIGEN_MAX_ALIGN_BYTES=16 -DEIGEN_MAX_STATIC_ALIGN_BYTES=16 -I"$root/include" -I"$root" -I"$root/tests"
  -I"$root/tests/support"
  -isystem /usr/include/eigen3 -isystem "$work/include")
digest=(tests/regression/digest.cpp tests/support/hard_families.cpp tools/scene/scene.cpp tools/scene/scene_run.cpp
  tools/scene/svg_shape.cpp engine/replay/replay.cpp)
programs=(tools/query_command.cpp tools/testbed/testbed.cpp tests/regression/golden.cpp "${digest[@]}")
printf '%s\n' "$@" "${programs[@]}" | xargs -P "$(nproc)" -I{} sh -c \
  'emcc "$@" -c "'"$root"'/{}" -o "'"$work"'/obj/$(echo {} | tr / _).o"' sh "${flags[@]}"
object() { echo "$work/obj/$(echo "$1" | tr / _).o"; }
library=()
for s in "$@"; do library+=("$(object "$s")"); done  # not a stale one of a source gone
rm -f "$work/libcollide2d.a"
emar rcs "$work/libcollide2d.a" "${library[@]}"
emcc -O1 -fexceptions "$(object tools/query_command.cpp)" "$(object tools/testbed/testbed.cpp)" "$work/libcollide2d.a" \
  -o "$work/testbed.js" -sSINGLE_FILE=1 -sMODULARIZE=1 -sEXPORT_NAME=Collide2dModule \
  -sEXPORTED_FUNCTIONS=_testbed_answer -sEXPORTED_RUNTIME_METHODS=cwrap -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web
# A program for node, reading and writing the host's files: node_program NAME.js SOURCE.cpp...
node_program() {
  local out=$1 objects=()
  shift
  for s in "$@"; do objects+=("$(object "$s")"); done
  emcc -O1 -fexceptions "${objects[@]}" "$work/libcollide2d.a" -o "$work/$out" \
    -sSINGLE_FILE=1 -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=node -sNODERAWFS=1 -sEXIT_RUNTIME=1
}
node_program golden.js tests/regression/golden.cpp
node_program digest.js tools/query_command.cpp "${digest[@]}"
python3 - "$root/tools/testbed/testbed.html" "$work/testbed.js" "$work/testbed.html" <<'PY'
import sys
page, module, out = (open(p).read() if i < 2 else p for i, p in enumerate(sys.argv[1:]))
if '</script' in module:
    sys.exit('wasm.sh: the module holds </script>, which would end its script block')
open(out, 'w').write(page.replace('%%MODULE%%', module, 1))
PY
echo "testbed page: $work/testbed.html; golden scene: $work/golden.js; query digest: $work/digest.js"
