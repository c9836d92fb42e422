#!/usr/bin/env bash
# The test command: installs what is missing, configures, builds, and runs the whole suite with ctest;
# then builds it again with clang, AddressSanitizer and UndefinedBehaviorSanitizer, runs the suite
# there too, and runs each of the nine libFuzzer targets that build made for 10 seconds on its corpus
# (scripts/fuzz.sh).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh" --test
# The packaging and Python install tests build the library again from its source, as a user does;
# through the compiler cache they reuse this build's objects.
export CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache
build=${BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE2D_BUILD_TESTS=ON -DCOLLIDE2D_BUILD_BENCHMARKS=ON \
  -DCOLLIDE2D_BUILD_PYTHON=ON -DCOLLIDE2D_BUILD_TESTBED=ON \
  -DCOLLIDE2D_BOX2D_SOURCE="$(bash "$root/scripts/box2d_source.sh" "$build/box2d-source")"
cmake --build "$build" -j "$(nproc)"
ctest --test-dir "$build" --output-on-failure -j "$(nproc)"

# One clang build serves the sanitizers, the fuzzers and clang itself: it builds the library, the
# tests, the tools and the fuzz targets, and runs the suite with AddressSanitizer and
# UndefinedBehaviorSanitizer. It leaves out what its tests cannot use: the WebAssembly programs
# (scripts/wasm.sh), the benchmark programs (an instrumented build's times mean nothing) and the
# Python module (Debian's python3 cannot load an instrumented one). The packaging tests build
# uninstrumented consumers against the instrumented library, which cannot link, and the browser
# tests drive a page the first build wrote: these run in the first build only.
sanitize=${SANITIZE_BUILD_DIR:-$root/build-sanitize}
CXX=clang++ CC=clang cmake -S "$root" -B "$sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE2D_FUZZ=ON \
  -DCOLLIDE2D_BUILD_TESTS=ON -DCOLLIDE2D_BUILD_BENCHMARKS=ON \
  -DCOLLIDE2D_BOX2D_SOURCE="$build/box2d-source"
cmake --build "$sanitize" -j "$(nproc)"
ctest --test-dir "$sanitize" --output-on-failure -j "$(nproc)" -LE "package|browser|python"

# A short fuzz run: a minute and a half in all.
FUZZ_BUILD_DIR=$sanitize FUZZ_SECONDS=${FUZZ_SECONDS:-10} bash "$root/scripts/fuzz.sh"
