#!/usr/bin/env bash
# Runs the benchmark suite once and keeps the results as data: builds the benchmarks (Release, Box2D
# 2.4.1 built from Debian's source with the same compiler and flags), runs each program with its
# repetitions interleaved at random (Google Benchmark's --benchmark_enable_random_interleaving) and
# the medians kept, runs the speed-against-error report, and writes
# bench/results/<date>-<cpu>.json: every program's Google Benchmark JSON, the report's, and the
# machine (CPU model, cores, compiler, flags); then the Python module against the same work in C++
# (bench/python/bench_python.py) into bench/results/python/<date>-<cpu>.json, the overlap areas
# (bench/bench_areas.cpp, bench/python/bench_areas.py) into bench/results/areas/, and DistributedWorld
# under mpirun into bench/results/mpi/. Then regenerates
# docs/performance.md and its plots from bench/results alone (scripts/performance.py).
# BOX2D_V3_DIR names a copy of Box2D v3's source: the suite then races v3 too (bench/box2d_v3/).
#
#   bash scripts/bench.sh                          # about 25 minutes on 2 cores
#   BOX2D_V3_DIR=path/to/box2d-v3 bash scripts/bench.sh
#   BENCH_REPETITIONS=3 BENCH_MIN_TIME=0.05 bash scripts/bench.sh   # quicker, noisier
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh" --test
build=${BENCH_BUILD_DIR:-$root/build-bench}
repetitions=${BENCH_REPETITIONS:-5}
min_time=${BENCH_MIN_TIME:-0.1}
source_dir=$(bash "$root/scripts/box2d_source.sh" "$build/box2d-source")
v3_dir=${BOX2D_V3_DIR:+$(cd "$BOX2D_V3_DIR" && pwd)}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCOLLIDE2D_BUILD_BENCHMARKS=ON -DCOLLIDE2D_BUILD_TESTS=OFF \
  -DCOLLIDE2D_BUILD_PYTHON=ON -DCOLLIDE2D_BOX2D_SOURCE="$source_dir" \
  -DCOLLIDE2D_BOX2D_V3_SOURCE="$v3_dir" > /dev/null
programs=(bench_narrowphase bench_contact bench_toi bench_broadphase bench_world bench_queries bench_movers)
cmake --build "$build" -j "$(nproc)" --target "${programs[@]}" collide2d_report collide2d_python python_rival

runs=$(mktemp -d)
trap 'rm -rf "$runs"' EXIT
for program in "${programs[@]}"; do
  echo "$program: $repetitions repetitions, interleaved" >&2
  "$build/bench/$program" --benchmark_enable_random_interleaving=true --benchmark_repetitions="$repetitions" \
    --benchmark_report_aggregates_only=true --benchmark_min_time="$min_time" \
    --benchmark_out="$runs/$program.json" --benchmark_out_format=json > /dev/null
done
echo "collide2d_report" >&2
"$build/bench/collide2d_report" --json "$runs/report.json" > /dev/null

cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
compiler=$(sed -n 's/^CMAKE_CXX_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
flags=$(sed -n 's/^CMAKE_CXX_FLAGS_RELEASE:[A-Z]*=//p' "$build/CMakeCache.txt")
python3 "$root/scripts/performance.py" collect --runs "$runs" --results "$root/bench/results" \
  --cpu "$cpu" --cores "$(nproc)" --compiler "$("$compiler" --version | head -n 1)" \
  --flags "$flags -ffp-contract=off -fno-math-errno (collide2d and Box2D); collide2d with EIGEN_DONT_VECTORIZE" \
  --repetitions "$repetitions" --min-time "$min_time"
slug=$(tr 'A-Z' 'a-z' <<< "$cpu" | sed -E 's/[^a-z0-9]+/-/g; s/^-//; s/-$//')
echo "bench_python.py" >&2
PYTHONPATH="$build/python" /usr/bin/python3 "$root/bench/python/bench_python.py" --rival "$build/bench/python_rival" \
  --json "$root/bench/results/python/$(date +%F)-$slug.json"
# Overlap areas and IoU: the C++ benchmarks and the Python side (shapely, iou_matrix), into one file.
cmake --build "$build" -j "$(nproc)" --target bench_areas
echo "bench_areas" >&2
"$build/bench/bench_areas" --benchmark_enable_random_interleaving=true --benchmark_repetitions="$repetitions" \
  --benchmark_report_aggregates_only=true --benchmark_min_time="$min_time" \
  --benchmark_out="$runs/areas.json" --benchmark_out_format=json > /dev/null
mkdir -p "$root/bench/results/areas"
PYTHONPATH="$build/python" /usr/bin/python3 "$root/bench/python/bench_areas.py" --benchmarks "$runs/areas.json" \
  --json "$root/bench/results/areas/$(date +%F)-$slug.json"
# DistributedWorld under mpirun with 1 and 2 ranks (Open MPI refuses root unless told).
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake --build "$build" -j "$(nproc)" --target bench_distributed
echo "bench_distributed" >&2
for ranks in 1 2; do mpirun --oversubscribe -np "$ranks" "$build/bench/bench_distributed"; done > "$runs/mpi.jsonl"
mkdir -p "$root/bench/results/mpi"
python3 - "$runs/mpi.jsonl" "$root/bench/results/mpi/$(date +%F)-$slug.json" "$cpu" "$(nproc)" <<'PY'
import datetime, json, sys
lines, out, cpu, cores = sys.argv[1:]
runs = [json.loads(line) for line in open(lines) if line.strip()]
data = {'date': datetime.date.today().isoformat(), 'machine': {'cpu': cpu, 'cores': int(cores)},
        'command': 'mpirun -np N build-bench/bench/bench_distributed (N = 1, 2)', 'runs': runs}
open(out, 'w').write(json.dumps(data, indent=1) + '\n')
PY
python3 "$root/scripts/performance.py" page --results "$root/bench/results" --out "$root/docs"
