#!/usr/bin/env bash
# Builds the testbed page (docs/testbed.md): the library's kernels and the command line's query
# grammar compiled to WebAssembly by Debian's Emscripten, in one HTML file that needs no server.
# The build runs it (the `testbed` target, where emcc is installed), with the library's sources:
#   bash scripts/testbed.sh OUT.html WORK_DIR SOURCE.cpp...
# Highway keeps to its one static target (its WebAssembly vectors have no doubles in Debian's
# version, and the static target needs no run-time dispatch); the link stays at -O1, as
# Emscripten's -O2 JavaScript passes need npm's acorn.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "$1")
work=$(realpath -m "$2")
shift 2
command -v emcc > /dev/null || { echo "testbed.sh: no emcc (apt-get install emscripten)" >&2; exit 1; }
mkdir -p "$work/include" "$work/obj" "$(dirname "$out")"
ln -sfn /usr/include/hwy "$work/include/hwy"  # Highway's headers alone, not the host's C library's
flags=(-std=c++20 -O2 -fexceptions -ffp-contract=off -DHWY_COMPILE_ONLY_STATIC=1 -DEIGEN_DONT_VECTORIZE
  -DEIGEN_MAX_ALIGN_BYTES=16 -DEIGEN_MAX_STATIC_ALIGN_BYTES=16 -I"$root/include" -I"$root"
  -isystem /usr/include/eigen3 -isystem "$work/include")
sources=("$@" tools/query_command.cpp tools/testbed/testbed.cpp)
printf '%s\n' "${sources[@]}" | xargs -P "$(nproc)" -I{} sh -c \
  'emcc "$@" -c "'"$root"'/{}" -o "'"$work"'/obj/$(echo {} | tr / _).o"' sh "${flags[@]}"
objects=()
for s in "${sources[@]}"; do objects+=("$work/obj/$(echo "$s" | tr / _).o"); done  # not a stale one of a source gone
emcc -O1 -fexceptions "${objects[@]}" -o "$work/testbed.js" -sSINGLE_FILE=1 -sMODULARIZE=1 \
  -sEXPORT_NAME=Collide2dModule -sEXPORTED_FUNCTIONS=_testbed_answer -sEXPORTED_RUNTIME_METHODS=cwrap \
  -sALLOW_MEMORY_GROWTH=1 -sENVIRONMENT=web
python3 - "$root/tools/testbed/testbed.html" "$work/testbed.js" "$out" <<'PY'
import sys
page, module, out = (open(p).read() if i < 2 else p for i, p in enumerate(sys.argv[1:]))
if '</script' in module:
    sys.exit('testbed.sh: the module holds </script>, which would end its script block')
open(out, 'w').write(page.replace('%%MODULE%%', module, 1))
PY
echo "testbed page: $out"
