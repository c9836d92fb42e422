#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (AddressSanitizer and UndefinedBehaviorSanitizer on) and
# runs each of the nine on its corpus in tests/fuzz/corpus for FUZZ_SECONDS seconds (default 10). New
# inputs stay in a scratch copy of the corpus. The script fails when a fuzzer exits with an error
# (a failed property, a sanitizer finding, a crash, a timeout), writes a failing input to its build
# folder (build-fuzz/ unless FUZZ_BUILD_DIR names another), or runs no input at all. A long run: FUZZ_SECONDS=3600 bash scripts/fuzz.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh" --test
build=${FUZZ_BUILD_DIR:-$root/build-fuzz}
seconds=${FUZZ_SECONDS:-10}
# A fuzzing build made already (scripts/test.sh's, which also has the tests) is kept as it is.
if ! grep -q '^COLLIDE2D_FUZZ:BOOL=ON$' "$build/CMakeCache.txt" 2> /dev/null; then
  CXX=clang++ CC=clang cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCOLLIDE2D_FUZZ=ON \
    -DCOLLIDE2D_BUILD_TESTS=OFF -DCOLLIDE2D_BUILD_BENCHMARKS=OFF > /dev/null
fi
names="rect_ellipse ellipse_ellipse rect_rect circle polygon segment chain query_line world"
cmake --build "$build" -j "$(nproc)" --target $(printf 'fuzz_%s ' $names)
rm -f "$build"/crash-* "$build"/timeout-* "$build"/leak-* "$build"/oom-*
for name in $names; do
  scratch="$build/corpus-$name"
  log="$build/fuzz_$name.log"
  rm -rf "$scratch" && mkdir -p "$scratch" && cp "$root/tests/fuzz/corpus/$name"/* "$scratch"/
  echo "fuzz_$name: ${seconds} s"
  status=0
  (cd "$build" && "./tests/fuzz/fuzz_$name" -max_total_time="$seconds" -timeout=10 -print_final_stats=1 "$scratch" \
    > "$log" 2>&1) || status=$?
  grep -E '^stat::number_of_executed_units|^SUMMARY|property failed' "$log" || true
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  failures=$(find "$build" -maxdepth 1 \( -name 'crash-*' -o -name 'timeout-*' -o -name 'leak-*' -o -name 'oom-*' \))
  if [ "$status" -ne 0 ] || [ -n "$failures" ] || [ -z "$runs" ] || [ "$runs" -eq 0 ]; then
    echo "fuzz_$name failed (exit status $status, ${runs:-no} inputs run${failures:+, failing input: $failures}); its log: $log" >&2
    tail -n 20 "$log" >&2
    exit 1
  fi
done
