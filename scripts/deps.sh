#!/usr/bin/env bash
# Installs the Debian packages that are missing: with no argument, what building the library and the
# `collide2d` command needs (the main job); with --test, also what the tests, the benchmarks, the
# fuzzers, the Python module, the browser tests and the testbed need, and the npm package the
# browser tests drive chromium with.
set -euo pipefail
packages=(build-essential cmake pkg-config libeigen3-dev libhwy-dev nlohmann-json3-dev zlib1g-dev)
test_tools=0
case "${1:-}" in
  "") ;;
  --test) test_tools=1 ;;
  *) echo "deps.sh: unknown argument '$1' (none, or --test)" >&2; exit 2 ;;
esac
if ((test_tools)); then
  packages+=(ccache python3 clang-format libbox2d-dev googletest libgtest-dev libbenchmark-dev libboost-dev clang
    libclang-rt-14-dev pybind11-dev python3-dev python3-numpy python3-pytest python3-setuptools python3-venv
    python3-matplotlib python3-shapely libopenmpi-dev openmpi-bin)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((test_tools)); then
  # The browser tests (tests/browser): Debian's chromium, and Node.js for puppeteer-core; the
  # WebAssembly testbed page and golden scene (scripts/wasm.sh): Emscripten.
  command -v chromium > /dev/null || missing+=(chromium)
  command -v node > /dev/null || missing+=(nodejs)
  command -v emcc > /dev/null || missing+=(emscripten)
fi
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y "${missing[@]}"
fi
# puppeteer-core, from the npm registry, at the version package-lock.json names.
browser_tests=$(cd "$(dirname "$0")/.." && pwd)/tests/browser
if ((test_tools)) && [ ! -d "$browser_tests/node_modules/puppeteer-core" ]; then
  (cd "$browser_tests" && npm ci --no-audit --no-fund --loglevel=error)
fi
