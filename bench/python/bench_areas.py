"""Rotated-box IoU from Python: collide2d.iou_arrays against shapely's polygon intersection (Debian's
python3-shapely), one pair at a time with the polygons built beforehand, on the same pairs of a box
and a noisy copy of it; rounds alternate the two, each figure the median of its rounds. Then the
N x N problem: collide2d.iou_matrix on N boxes against N (time, and the peak memory the call adds,
each in a process of its own) against every pair through iou_arrays at a size where that fits.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/bench_areas.py [--json FILE] [--benchmarks FILE]

With --json FILE it writes the figures and the machine as data, and with --benchmarks the medians of
a Google Benchmark JSON of bench/bench_areas.cpp beside them (scripts/bench.sh keeps both in
bench/results/areas/, and scripts/performance.py puts them on docs/performance.md).
"""
import argparse
import datetime
import json
import os
import platform
import resource
import subprocess
import sys
import time

import numpy as np

import collide2d


def boxes(rng, n, side):
    """n rotated boxes as collide2d's rect rows (cx cy hx hy theta), sides 2 to 20."""
    return np.column_stack([rng.uniform(0, side, (n, 2)), rng.uniform(1, 10, (n, 2)), rng.uniform(-np.pi, np.pi, n)])


def detections_of(rng, truths):
    """Each box moved by up to a fifth of its size, its sides changed by up to a tenth, turned by up to 0.3."""
    size = truths[:, 2:4].max(axis=1, keepdims=True)
    n = len(truths)
    return np.column_stack([truths[:, :2] + 0.2 * size * rng.uniform(-1, 1, (n, 2)),
                            truths[:, 2:4] * (1 + 0.1 * rng.uniform(-1, 1, (n, 2))),
                            truths[:, 4] + 0.3 * rng.uniform(-1, 1, n)])


def polygon(row):
    from shapely.geometry import Polygon
    cx, cy, hx, hy, t = row
    c, s = np.cos(t), np.sin(t)
    return Polygon([(cx + c * x - s * y, cy + s * x + c * y) for x, y in ((-hx, -hy), (hx, -hy), (hx, hy), (-hx, hy))])


def shapely_ious(pairs):
    out = []
    for p, q in pairs:
        shared = p.intersection(q).area
        out.append(shared / (p.area + q.area - shared))
    return out


def seconds_per_pair(run, pairs):
    start = time.perf_counter()
    run()
    return (time.perf_counter() - start) / pairs


# The N x N problem in a process of its own: its time and the peak resident memory the call adds.
CHILD = '''
import resource, sys, time
import numpy as np
import collide2d
sys.path.insert(0, {here!r})
from bench_areas import boxes
n, dense = {n}, {dense}
rng = np.random.default_rng(57)
side = np.sqrt(n * 130.0)
a, b = boxes(rng, n, side), boxes(rng, n, side)
if dense:
    a, b = np.repeat(a, n, axis=0), np.tile(b, (n, 1))
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
start = time.perf_counter()
found = (collide2d.iou_arrays('rect', a, 'rect', b) > 0).sum() if dense else len(collide2d.iou_matrix('rect', a, 'rect', b)['i'])
seconds = time.perf_counter() - start
print(seconds, (resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) * 1024, found)
'''


def n_by_n(n, dense):
    code = CHILD.format(here=os.path.dirname(os.path.abspath(__file__)), n=n, dense=dense)
    seconds, peak, found = subprocess.run([sys.executable, '-c', code], capture_output=True, text=True,
                                          check=True).stdout.split()
    return {'seconds': float(seconds), 'peak_bytes': int(peak), 'pairs': int(found)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--pairs', type=int, default=4096)
    parser.add_argument('--rounds', type=int, default=5)
    parser.add_argument('--matrix', type=int, default=100000, help='N of the sparse N x N problem')
    parser.add_argument('--dense', type=int, default=2000, help='N of the N x N problem measured both ways')
    parser.add_argument('--json', help='also write the figures as data to this file')
    parser.add_argument('--benchmarks', help="bench_areas' Google Benchmark JSON, whose medians join --json")
    args = parser.parse_args()
    rng = np.random.default_rng(56)
    a = boxes(rng, args.pairs, 1000.0)
    b = detections_of(rng, a)
    pairs = [(polygon(x), polygon(y)) for x, y in zip(a, b)]
    ours, theirs = [], []
    for _ in range(args.rounds):
        ours.append(seconds_per_pair(lambda: collide2d.iou_arrays('rect', a, 'rect', b), len(a)))
        theirs.append(seconds_per_pair(lambda: shapely_ious(pairs), len(pairs)))
    gap = np.max(np.abs(collide2d.iou_arrays('rect', a, 'rect', b) - shapely_ious(pairs)))
    results = {'iou_arrays_ns': float(np.median(ours)) * 1e9, 'shapely_ns': float(np.median(theirs)) * 1e9,
               'largest_difference': float(gap),
               'matrix': {'n': args.matrix, **n_by_n(args.matrix, False)},
               'small_matrix': {'n': args.dense, **n_by_n(args.dense, False)},
               'dense': {'n': args.dense, **n_by_n(args.dense, True)}}
    print(f'{args.pairs} box pairs: iou_arrays {results["iou_arrays_ns"]:.4g} ns, shapely {results["shapely_ns"]:.4g} ns '
          f'per pair ({results["shapely_ns"] / results["iou_arrays_ns"]:.0f}x), largest difference {gap:.2g}')
    for key in ('matrix', 'small_matrix', 'dense'):
        r = results[key]
        print(f'{key:12} {r["n"]:>7} x {r["n"]}: {r["seconds"]:.4g} s, peak +{r["peak_bytes"] / 2**20:.1f} MiB, '
              f'{r["pairs"]} pairs')
    if args.json:
        cpu = next((line.split(':', 1)[1].strip() for line in open('/proc/cpuinfo') if line.startswith('model name')),
                   platform.processor())
        import shapely
        data = {'date': datetime.date.today().isoformat(),
                'machine': {'cpu': cpu, 'cores': os.cpu_count(), 'python': platform.python_version(),
                            'numpy': np.__version__, 'shapely': shapely.__version__},
                'method': {'pairs': args.pairs, 'rounds': args.rounds, 'threads': 1,
                           'statistic': 'median over interleaved rounds'},
                'results': results}
        if args.benchmarks:
            data['benchmarks'] = benchmark_medians(args.benchmarks)
        with open(args.json, 'w') as out:
            out.write(json.dumps(data, indent=1) + '\n')


def benchmark_medians(path):
    """Each benchmark's median in ns (per pair for a batch), and its pairs counter where it has one."""
    units = {'ns': 1.0, 'us': 1e3, 'ms': 1e6, 's': 1e9}
    out = {}
    for b in json.load(open(path))['benchmarks']:
        if b.get('aggregate_name', 'median') != 'median':
            continue
        ns = b['per_pair'] * 1e9 if 'per_pair' in b else b['real_time'] * units[b.get('time_unit', 'ns')]
        out[b['run_name']] = {'ns': ns, **({'pairs': int(b['pairs'])} if 'pairs' in b else {})}
    return out


if __name__ == '__main__':
    main()
