#!/usr/bin/env bash
# Installs the Debian packages collide2d needs to build, test and benchmark, and the npm package
# its browser tests drive chromium with, when any is missing.
set -euo pipefail
packages=(build-essential ccache cmake pkg-config python3 clang-format libeigen3-dev libhwy-dev libbox2d-dev googletest libgtest-dev libbenchmark-dev libboost-dev nlohmann-json3-dev zlib1g-dev clang libclang-rt-14-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-setuptools python3-venv python3-matplotlib
  libopenmpi-dev openmpi-bin)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# The browser tests (tests/browser): Debian's chromium, and Node.js for puppeteer-core.
command -v chromium > /dev/null || missing+=(chromium)
command -v node > /dev/null || missing+=(nodejs)
# The testbed page (tools/testbed): Emscripten.
command -v emcc > /dev/null || missing+=(emscripten)
if ((${#missing[@]})); then
  echo "installing: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y "${missing[@]}"
fi
# puppeteer-core, from the npm registry, at the version package-lock.json names.
browser_tests=$(cd "$(dirname "$0")/.." && pwd)/tests/browser
if [ ! -d "$browser_tests/node_modules/puppeteer-core" ]; then
  (cd "$browser_tests" && npm ci --no-audit --no-fund --loglevel=error)
fi
