"""The Python module's speed against the same work in C++ (python_rival.cpp, built with the
benchmarks) on the same rows: one call to overlaps() per pair, the overlap array form against the
C++ batch at 100,000 pairs, and a World step driven from arrays against the same step in C++ at
100,000 bodies, both on one thread. Rounds alternate the two sides; each side's figure is the
median of its rounds, each round the median of its repeats.

    PYTHONPATH=build/python /usr/bin/python3 bench/python/bench_python.py --rival build/bench/python_rival

With --json FILE it also writes the figures and the machine as data (scripts/bench.sh keeps them in
bench/results/python/, and scripts/performance.py puts them on docs/performance.md).
"""
import argparse
import datetime
import json
import os
import platform
import subprocess
import tempfile
import time

import numpy as np

import collide2d


def ellipse_rows(rng, n, half_side):
    a = rng.uniform(0.05, 1.0, n)
    return np.column_stack([rng.uniform(-half_side, half_side, (n, 2)), a, a / rng.uniform(1, 10, n),
                            rng.uniform(0, 6.3, n)])


def median_seconds(repeats, items, run):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        run()
        times.append((time.perf_counter() - start) / items)
    return float(np.median(times))


def python_side(a, b, bodies, poses, repeats):
    sa = [collide2d.Ellipse(r[:2], r[2], r[3], r[4]) for r in a]
    sb = [collide2d.Ellipse(r[:2], r[2], r[3], r[4]) for r in b]
    overlaps = collide2d.overlaps
    out = {'overlaps_one_call': median_seconds(repeats, len(sa), lambda: [overlaps(x, y) for x, y in zip(sa, sb)]),
           'overlaps_batch': median_seconds(repeats, len(a), lambda: collide2d.overlaps_arrays('ellipse', a, 'ellipse', b))}
    world = collide2d.World(fat_margin=0.05, threads=1)
    ids = np.array([world.add(collide2d.Ellipse(r[:2], r[2], r[3], r[4])) for r in bodies], dtype=np.uint64)
    world.update()
    frame = [0]

    def step():
        frame[0] += 1
        centres = poses[:, :2] + [(frame[0] % 2) * 1e-3, 0.0]
        world.set_poses(ids, centres, poses[:, 2])
        world.update()

    out['world_step'] = median_seconds(repeats, 1, step)
    return out


def rival_side(rival, files, repeats):
    out = subprocess.run([rival, *files, str(repeats)], capture_output=True, text=True, check=True).stdout
    return {name: float(value) for name, value in (line.split() for line in out.splitlines())}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--rival', required=True)
    parser.add_argument('--pairs', type=int, default=100000)
    parser.add_argument('--bodies', type=int, default=100000)
    parser.add_argument('--rounds', type=int, default=5)
    parser.add_argument('--repeats', type=int, default=5)
    parser.add_argument('--json', help='also write the figures as data to this file')
    args = parser.parse_args()
    rng = np.random.default_rng(2024)
    a, b = ellipse_rows(rng, args.pairs, 2.0), ellipse_rows(rng, args.pairs, 2.0)
    # Bodies at about 8% coverage, and a frame's poses a little away from where they were added.
    bodies = ellipse_rows(rng, args.bodies, np.sqrt(args.bodies * 0.35 / 0.08) / 2)
    poses = np.column_stack([bodies[:, :2] + rng.uniform(-0.02, 0.02, (args.bodies, 2)), bodies[:, 4] + 0.01])
    with tempfile.TemporaryDirectory() as folder:
        files = [f'{folder}/a', f'{folder}/b', f'{folder}/bodies']
        a.tofile(files[0])
        b.tofile(files[1])
        np.concatenate([bodies.ravel(), poses.ravel()]).tofile(files[2])
        rounds = {'python': [], 'c++': []}
        for _ in range(args.rounds):
            rounds['python'].append(python_side(a, b, bodies, poses, args.repeats))
            rounds['c++'].append(rival_side(args.rival, files, args.repeats))
    median = {side: {k: float(np.median([r[k] for r in runs])) for k in runs[0]} for side, runs in rounds.items()}
    units = {'overlaps_one_call': ('ns per pair', 1e9), 'overlaps_batch': ('ns per pair', 1e9),
             'world_step': ('ms per step', 1e3)}
    print(f'{args.pairs} ellipse pairs, {args.bodies} bodies, {args.rounds} interleaved rounds of {args.repeats}')
    print(f'{"":20} {"python":>12} {"c++":>12} {"ratio":>7}')
    for key, (unit, scale) in units.items():
        p, c = median['python'][key] * scale, median['c++'][key] * scale
        print(f'{key:20} {p:12.4g} {c:12.4g} {p / c:7.2f}   {unit}')
    if args.json:
        write_json(args, {key: {'python': median['python'][key] * scale, 'c++': median['c++'][key] * scale,
                                'unit': unit} for key, (unit, scale) in units.items()})


def write_json(args, results):
    cpu = next((line.split(':', 1)[1].strip() for line in open('/proc/cpuinfo') if line.startswith('model name')),
               platform.processor())
    data = {'date': datetime.date.today().isoformat(),
            'machine': {'cpu': cpu, 'cores': os.cpu_count(), 'python': platform.python_version(),
                        'numpy': np.__version__},
            'method': {'pairs': args.pairs, 'bodies': args.bodies, 'rounds': args.rounds, 'repeats': args.repeats,
                       'threads': 1, 'statistic': 'median over interleaved rounds of the median of each round'},
            'results': results}
    with open(args.json, 'w') as out:
        out.write(json.dumps(data, indent=1) + '\n')

if __name__ == '__main__':
    main()
