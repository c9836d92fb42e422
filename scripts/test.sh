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

# One clang build serves the sanitizers and the fuzzers: the suite with AddressSanitizer and
# UndefinedBehaviorSanitizer (no benchmarks; the packaging tests build uninstrumented consumers
# against the instrumented library, which cannot link, and the browser tests drive a page the normal
# build wrote the same way, so they run in the normal build only), and the libFuzzer programs.
sanitize=${SANITIZE_BUILD_DIR:-$root/build-sanitize}
CXX=clang++ CC=clang cmake -S "$root" -B "$sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE2D_FUZZ=ON \
  -DCOLLIDE2D_BUILD_TESTS=ON -DCOLLIDE2D_BUILD_BENCHMARKS=OFF
cmake --build "$sanitize" -j "$(nproc)"
ctest --test-dir "$sanitize" --output-on-failure -j "$(nproc)" -LE "package|browser"

# A short fuzz run: a minute and a half in all.
FUZZ_BUILD_DIR=$sanitize FUZZ_SECONDS=${FUZZ_SECONDS:-10} bash "$root/scripts/fuzz.sh"
