#!/usr/bin/env python3
"""Benchmark results as data, and the performance page made from them.

  performance.py collect --runs DIR --results bench/results --cpu ... --cores ... --compiler ... --flags ...
      merges one run of the suite (DIR: each program's Google Benchmark JSON and report.json) into
      bench/results/<date>-<cpu>.json, with the machine;
  performance.py page --results bench/results --out docs [--check]
      writes docs/performance.md and docs/performance/*.svg from bench/results/*.json alone (the
      newest file's figures; every file listed); --check compares instead of writing, for ctest.
"""
import argparse
import datetime
import html
import json
import math
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent  # the repository, which the page's paths start from

UNITS = {'ns': 1.0, 'us': 1e3, 'ms': 1e6, 's': 1e9}
WORKLOADS = [('random', 0), ('candidate', 1), ('scene', 2)]
# The contact benchmarks add the overlapping pairs among the candidate and the scene pairs.
CONTACT_WORKLOADS = WORKLOADS + [('overlapping candidate', 3), ('overlapping scene', 4)]

# (label, ours, rival): `{w}` stands for the workload's number. Batches are timed over the whole list
# per iteration (per_pair), against Box2D's loop over the same list.
OVERLAP = [
    ('rect–ellipse, one pair', 'posed_overlap/rect_ellipse/candidates:{w}', 'box2d_overlap/rect_ellipse_8gon/candidates:{w}'),
    ('rect–ellipse, batch', 'batch_overlap/rect_ellipse/candidates:{w}', 'box2d_batch_overlap/rect_ellipse_8gon/candidates:{w}'),
    ('rect–rect, one pair', 'posed_overlap/rect_rect/candidates:{w}', 'box2d_overlap/rect_rect_4gons/candidates:{w}'),
    ('rect–rect, batch', 'batch_overlap/rect_rect/candidates:{w}', 'box2d_batch_overlap/rect_rect_4gons/candidates:{w}'),
    ('ellipse–ellipse, one pair', 'posed_overlap/ellipse_ellipse/candidates:{w}', 'box2d_overlap/ellipse_ellipse_8gons/candidates:{w}'),
    ('ellipse–ellipse, batch', 'batch_overlap/ellipse_ellipse/candidates:{w}', 'box2d_batch_overlap/ellipse_ellipse_8gons/candidates:{w}'),
    ('circle–ellipse, one pair', 'posed_overlap/circle_ellipse/candidates:{w}', 'box2d_overlap/circle_ellipse_8gon/candidates:{w}'),
    ('circle–ellipse, batch', 'batch_overlap/circle_ellipse/candidates:{w}', 'box2d_batch_overlap/circle_ellipse_8gon/candidates:{w}'),
    ('polygon–polygon (8-gons), one pair', 'posed_overlap/polygon_polygon/candidates:{w}', 'box2d_overlap/polygon_polygon_8gons/candidates:{w}'),
    ('polygon–circle, one pair', 'posed_overlap/polygon_circle/candidates:{w}', 'box2d_overlap/polygon_circle/candidates:{w}'),
    ('polygon–polygon (8-gons), batch', 'batch_overlap/polygon_polygon/candidates:{w}', 'box2d_batch_overlap/polygon_polygon_8gons/candidates:{w}'),
    ('polygon–circle, batch', 'batch_overlap/polygon_circle/candidates:{w}', 'box2d_batch_overlap/polygon_circle/candidates:{w}'),
    ('polygon–ellipse vs 8-gon, one pair', 'posed_overlap/polygon_ellipse/candidates:{w}', 'box2d_overlap/polygon_ellipse_8gon/candidates:{w}'),
    ('polygon–ellipse vs 8-gon, batch', 'batch_overlap/polygon_ellipse/candidates:{w}', 'box2d_batch_overlap/polygon_ellipse_8gon/candidates:{w}'),
    ('capsule–circle, one pair', 'posed_overlap/capsule_circle/candidates:{w}', 'box2d_overlap/capsule_circle/candidates:{w}'),
    ('capsule–circle, batch', 'batch_overlap/capsule_circle/candidates:{w}', 'box2d_batch_overlap/capsule_circle/candidates:{w}'),
    ('capsule–ellipse vs 8-gon, one pair', 'posed_overlap/capsule_ellipse/candidates:{w}', 'box2d_overlap/capsule_ellipse_8gon/candidates:{w}'),
    ('capsule–ellipse vs 8-gon, batch', 'batch_overlap/capsule_ellipse/candidates:{w}', 'box2d_batch_overlap/capsule_ellipse_8gon/candidates:{w}'),
    ('segment–polygon (8-gon), one pair', 'posed_overlap/segment_polygon/candidates:{w}', 'box2d_overlap/segment_polygon/candidates:{w}'),
    ('segment–ellipse vs 8-gon, one pair', 'posed_overlap/segment_ellipse/candidates:{w}', 'box2d_overlap/segment_ellipse_8gon/candidates:{w}'),
]
DISTANCE = [
    ('ellipse–ellipse vs 8-gons', 'posed_distance_ellipse_ellipse/candidates:{w}', 'box2d_distance_ellipse_ellipse/candidates:{w}/sides:8'),
    ('ellipse–ellipse vs 16-gons', 'posed_distance_ellipse_ellipse/candidates:{w}', 'box2d_distance_ellipse_ellipse/candidates:{w}/sides:16'),
    ('ellipse–ellipse vs 32-gons', 'posed_distance_ellipse_ellipse/candidates:{w}', 'box2d_distance_ellipse_ellipse/candidates:{w}/sides:32'),
]
# Contacts against Box2D v3 (bench/box2d_v3/contact.cpp): collide2d's contact() asked for no
# contact beyond v3's speculative distance, against v3's manifold function with its transforms, an
# ellipse v3's inscribed 8-gon. Absent from a run made without a v3 source.
V3_PAIRS = [
    ('capsule–capsule', 'capsule_capsule'), ('segment–capsule', 'segment_capsule'), ('chain segment–capsule', 'chain_capsule'),
    ('segment–circle', 'segment_circle'), ('chain segment–circle', 'chain_circle'),
    ('segment–rect', 'segment_rect'), ('chain segment–rect', 'chain_rect'),
    ('segment–polygon (8-gon)', 'segment_polygon'), ('chain segment–polygon (8-gon)', 'chain_polygon'),
    ('circle–circle', 'circle_circle'), ('capsule–circle', 'capsule_circle'), ('rect–circle', 'rect_circle'),
    ('polygon–circle', 'polygon_circle'), ('rect–capsule', 'rect_capsule'), ('polygon–capsule', 'polygon_capsule'),
    ('rect–rect', 'rect_rect'), ('rect–polygon', 'rect_polygon'), ('polygon–polygon (8-gons)', 'polygon_polygon'),
    ('rounded polygon–circle', 'rounded_circle'), ('rounded polygon–capsule', 'rounded_capsule'),
    ('rect–rounded polygon', 'rect_rounded'), ('polygon–rounded polygon', 'polygon_rounded'),
    ('rounded polygon–rounded polygon', 'rounded_rounded'), ('segment–rounded polygon', 'segment_rounded'),
    ('chain segment–rounded polygon', 'chain_rounded'),
    ('circle–ellipse vs 8-gon', 'circle_ellipse'), ('capsule–ellipse vs 8-gon', 'capsule_ellipse'),
    ('rect–ellipse vs 8-gon', 'rect_ellipse'), ('polygon–ellipse vs 8-gon', 'polygon_ellipse'),
    ('rounded polygon–ellipse vs 8-gon', 'rounded_ellipse'),
    ('ellipse–ellipse vs 8-gons', 'ellipse_ellipse'), ('segment–ellipse vs 8-gon', 'segment_ellipse'),
    ('chain segment–ellipse vs 8-gon', 'chain_ellipse'),
]
CONTACT_V3 = [(label, f'ours/{name}_speculative/candidates:{{w}}',
               f'box2d_v3/{name}{["", "_8gon", "_8gons"][name.count("ellipse")]}/candidates:{{w}}')
              for label, name in V3_PAIRS]
# The pairs with an ellipse to ContactOptions::tolerance 1e-2 of the size, against v3 on the
# ellipses' inscribed 5- to 8-gons (bench/box2d_v3/contact.cpp's race_tolerances).
V3_TOLERANCE_PAIRS = [(label.split(' vs ')[0], name) for label, name in V3_PAIRS if 'ellipse' in name]
CONTACT_V3_TOLERANCE = [
    (f'{label} vs {n}-gon{"s" if name == "ellipse_ellipse" else ""}', f'ours/{name}_speculative_tolerance_1e-2/candidates:{{w}}',
     f'box2d_v3/{name}_{n}gon{"s" if name == "ellipse_ellipse" else ""}/candidates:{{w}}')
    for label, name in V3_TOLERANCE_PAIRS for n in (5, 6, 7, 8)]
CONTACT = [
    ('rect–rect, one pair', 'ours/rect_rect_oriented/candidates:{w}', 'box2d_collide_polygons/rect_rect_4gons/candidates:{w}'),
    ('rect–rect, one pair, max_separation 0', 'ours/rect_rect_limited/candidates:{w}', 'box2d_collide_polygons/rect_rect_4gons/candidates:{w}'),
    ('rect–circle, one pair', 'ours/rect_circle_oriented/candidates:{w}', 'box2d_collide_polygon_and_circle/rect_circle/candidates:{w}'),
    ('rect–circle, one pair, max_separation 0', 'ours/rect_circle_limited/candidates:{w}', 'box2d_collide_polygon_and_circle/rect_circle/candidates:{w}'),
    ('rect–circle, batch', 'batch_contact/rect_circle/candidates:{w}', 'box2d_batch_contact/rect_circle/candidates:{w}'),
    ('circle–circle, one pair', 'ours/circle_circle/candidates:{w}', 'box2d_collide_circles/circle_circle/candidates:{w}'),
    ('rect–ellipse vs 8-gon, one pair', 'ours/rect_ellipse_oriented/candidates:{w}', 'box2d_collide_polygons/rect_ellipse_8gon/candidates:{w}'),
    ('rect–ellipse vs 8-gon, one pair, max_separation 0', 'ours/rect_ellipse_limited/candidates:{w}', 'box2d_collide_polygons/rect_ellipse_8gon/candidates:{w}'),
    ('rect–ellipse vs 16-gon, one pair', 'ours/rect_ellipse_oriented/candidates:{w}', 'box2d_collide_polygons/rect_ellipse_16gon/candidates:{w}'),
    ('circle–ellipse vs 8-gon, one pair', 'ours/circle_ellipse_oriented/candidates:{w}', 'box2d_collide_polygon_and_circle/circle_ellipse_8gon/candidates:{w}'),
    ('circle–ellipse vs 8-gon, one pair, max_separation 0', 'ours/circle_ellipse_limited/candidates:{w}', 'box2d_collide_polygon_and_circle/circle_ellipse_8gon/candidates:{w}'),
    ('circle–ellipse vs 16-gon, one pair', 'ours/circle_ellipse_oriented/candidates:{w}', 'box2d_collide_polygon_and_circle/circle_ellipse_16gon/candidates:{w}'),
    ('circle–ellipse vs 8-gon, batch', 'batch_contact/circle_ellipse/candidates:{w}', 'box2d_batch_contact/circle_ellipse_8gon/candidates:{w}'),
    ('circle–ellipse vs 16-gon, batch', 'batch_contact/circle_ellipse/candidates:{w}', 'box2d_batch_contact/circle_ellipse_16gon/candidates:{w}'),
    ('ellipse–ellipse vs 8-gons, one pair', 'ours/ellipse_ellipse_oriented/candidates:{w}', 'box2d_collide_polygons/ellipse_ellipse_8gons/candidates:{w}'),
    ('ellipse–ellipse vs 8-gons, one pair, max_separation 0', 'ours/ellipse_ellipse_limited/candidates:{w}', 'box2d_collide_polygons/ellipse_ellipse_8gons/candidates:{w}'),
    ('ellipse–ellipse vs 16-gons, one pair', 'ours/ellipse_ellipse_oriented/candidates:{w}', 'box2d_collide_polygons/ellipse_ellipse_16gons/candidates:{w}'),
    ('polygon–polygon (8-gons), one pair', 'ours/polygon_polygon/candidates:{w}', 'box2d_collide_polygons/polygon_polygon_8gons/candidates:{w}'),
    ('polygon–polygon (8-gons), one pair, max_separation 0', 'ours/polygon_polygon_limited/candidates:{w}', 'box2d_collide_polygons/polygon_polygon_8gons/candidates:{w}'),
    ('polygon–circle, one pair', 'ours/polygon_circle/candidates:{w}', 'box2d_collide_polygon_and_circle/polygon_circle/candidates:{w}'),
    ('polygon–circle, one pair, max_separation 0', 'ours/polygon_circle_limited/candidates:{w}', 'box2d_collide_polygon_and_circle/polygon_circle/candidates:{w}'),
    ('polygon–ellipse vs 8-gon, one pair', 'ours/polygon_ellipse/candidates:{w}', 'box2d_collide_polygons/polygon_ellipse_8gon/candidates:{w}'),
    ('polygon–ellipse vs 8-gon, one pair, max_separation 0', 'ours/polygon_ellipse_limited/candidates:{w}', 'box2d_collide_polygons/polygon_ellipse_8gon/candidates:{w}'),
    ('capsule–circle, one pair', 'ours/capsule_circle/candidates:{w}', 'box2d_collide_polygon_and_circle/capsule_circle/candidates:{w}'),
    ('capsule–circle, one pair, max_separation 0', 'ours/capsule_circle_limited/candidates:{w}', 'box2d_collide_polygon_and_circle/capsule_circle/candidates:{w}'),
    ('capsule–ellipse vs 8-gon, one pair', 'ours/capsule_ellipse/candidates:{w}', 'box2d_collide_polygons/capsule_ellipse_8gon/candidates:{w}'),
    ('capsule–ellipse vs 8-gon, one pair, max_separation 0', 'ours/capsule_ellipse_limited/candidates:{w}', 'box2d_collide_polygons/capsule_ellipse_8gon/candidates:{w}'),
    ('segment–polygon (8-gon), one pair', 'ours/segment_polygon/candidates:{w}', 'box2d_collide_edge_and_polygon/segment_polygon/candidates:{w}'),
    ('segment–polygon (8-gon), one pair, max_separation 0', 'ours/segment_polygon_limited/candidates:{w}', 'box2d_collide_edge_and_polygon/segment_polygon/candidates:{w}'),
    ('segment–circle, one pair', 'ours/segment_circle/candidates:{w}', 'box2d_collide_edge_and_circle/segment_circle/candidates:{w}'),
    ('segment–circle, one pair, max_separation 0', 'ours/segment_circle_limited/candidates:{w}', 'box2d_collide_edge_and_circle/segment_circle/candidates:{w}'),
    ('segment–ellipse vs 8-gon, one pair', 'ours/segment_ellipse/candidates:{w}', 'box2d_collide_edge_and_polygon/segment_ellipse_8gon/candidates:{w}'),
    ('segment–ellipse vs 8-gon, one pair, max_separation 0', 'ours/segment_ellipse_limited/candidates:{w}', 'box2d_collide_edge_and_polygon/segment_ellipse_8gon/candidates:{w}'),
    ('chain segment–polygon (8-gon), one pair, max_separation 0', 'ours/chain_polygon_limited/candidates:{w}', 'box2d_collide_edge_and_polygon/chain_polygon/candidates:{w}'),
    ('chain segment–circle, one pair, max_separation 0', 'ours/chain_circle_limited/candidates:{w}', 'box2d_collide_edge_and_circle/chain_circle/candidates:{w}'),
    ('chain segment–ellipse vs 8-gon, one pair, max_separation 0', 'ours/chain_ellipse_limited/candidates:{w}', 'box2d_collide_edge_and_polygon/chain_ellipse_8gon/candidates:{w}'),
]
TOI = [
    ('ellipse–ellipse translating vs 8-gons', 'ours/ellipse_ellipse_translating', 'box2d_toi/ellipse_ellipse_translating_8gons'),
    ('ellipse–ellipse translating vs 16-gons', 'ours/ellipse_ellipse_translating', 'box2d_toi/ellipse_ellipse_translating_16gons'),
    ('ellipse–ellipse turning vs 8-gons', 'ours/ellipse_ellipse_turning', 'box2d_toi/ellipse_ellipse_turning_8gons'),
    ('ellipse–ellipse turning vs 16-gons', 'ours/ellipse_ellipse_turning', 'box2d_toi/ellipse_ellipse_turning_16gons'),
    ('rect–ellipse translating vs 8-gon', 'ours/rect_ellipse_translating', 'box2d_toi/rect_ellipse_translating_8gon'),
    ('rect–ellipse translating vs 16-gon', 'ours/rect_ellipse_translating', 'box2d_toi/rect_ellipse_translating_16gon'),
    ('rect–ellipse turning vs 8-gon', 'ours/rect_ellipse_turning', 'box2d_toi/rect_ellipse_turning_8gon'),
    ('rect–ellipse turning vs 16-gon', 'ours/rect_ellipse_turning', 'box2d_toi/rect_ellipse_turning_16gon'),
    ('circle–ellipse translating vs 8-gon', 'ours/circle_ellipse_translating', 'box2d_toi/circle_ellipse_translating_8gon'),
    ('circle–ellipse translating vs 16-gon', 'ours/circle_ellipse_translating', 'box2d_toi/circle_ellipse_translating_16gon'),
    ('circle–ellipse turning vs 8-gon', 'ours/circle_ellipse_turning', 'box2d_toi/circle_ellipse_turning_8gon'),
    ('circle–ellipse turning vs 16-gon', 'ours/circle_ellipse_turning', 'box2d_toi/circle_ellipse_turning_16gon'),
    ('rect–rect turning', 'ours/rect_rect_turning', 'box2d_toi/rect_rect_turning'),
]
TOI_V3 = [(f'{pair.replace("_", "–")} {motion} vs {gons}', f'ours/{pair}_{motion}',
           f'box2d_v3_toi/{pair}_{motion}_{gons.replace("-", "")}')
          for pair, gons in (('ellipse_ellipse', '8-gons'), ('rect_ellipse', '8-gon'), ('circle_ellipse', '8-gon'))
          for motion in ('translating', 'turning')] + [
    ('rect–rect turning', 'ours/rect_rect_turning', 'box2d_v3_toi/rect_rect_turning')]
SIZES = (1000, 10000, 100000, 1000000)
# Each tree as insertion leaves it, and rebuilt (collide2d's rebuild(), v3's b2DynamicTree_Rebuild).
TREES = (('tree', 'box2d_v3', 'trees built by insertion'), ('tree_rebuilt', 'box2d_v3_rebuilt', 'trees rebuilt'))
BROAD = [(f'{n:,} boxes', f'moving_boxes<SweepAndPrune>/{n}{it}', f'moving_boxes<Box2dBroadPhase>/{n}{it}')
         for n, it in ((1000, ''), (10000, ''), (100000, ''), (1000000, '/iterations:3'))]


def tree_rows(trees):
    """Box and ray query rows, each (collide2d's tree, the rival's, how both were built) at every size."""
    return [(f'{query}, {n:,} boxes, {how}', f'{query}/{ours}/{n}', f'{query}/{rival}/{n}')
            for query in ('box', 'ray') for ours, rival, how in trees for n in SIZES]


QUERIES_V3 = tree_rows(TREES)
QUERIES = tree_rows((('tree', 'box2d', 'trees built by insertion'),))
WORLD = [
    ('1,000 moving bodies', 'frame/alone/1000/1', 'box2d_frame/alone/1000'),
    ('100,000 moving bodies', 'frame/crowd/100000/1', 'box2d_frame/crowd/100000'),
    ('the built-in scene (4,036 bodies)', 'frame/scene/4000/1', 'box2d_frame/scene/4000'),
]
WORLD_V3 = [(f'{n:,} moving bodies, contacts', f'frame/alone_contacts/{n}/1',
             f'box2d_v3_frame/alone_contacts/{n}/manual_time') for n in (1000, 10000)] + [
    ('the built-in scene (4,036 bodies), contacts', 'frame/scene_contacts/4000/1',
     'box2d_v3_frame/scene_contacts/4000/manual_time')]
MOVERS = [('1,000 capsule movers, one move() each', 'movers/capsule/collide2d', 'movers/capsule/box2d_v3')]
# The mover suite's checks (tests/support/mover_course.h): a label, and the figure from a run's counters.
COURSE_CHECKS = [
    ('deepest overlap of a level shape after a move', lambda c: max(0.0, -c['depth'])),
    ('a stopped move\'s separation less the skin (0.01), least', lambda c: c['blocked_low']),
    ('the same, greatest', lambda c: c['blocked_high']),
    ('seam: distance from the path over one box and one segment, relative', lambda c: c['seam']),
    ('tiles jittered by 1e-9: spread of the standing height', lambda c: c['bump_high'] - c['bump_low']),
    ('clear flat floor: progress off the commanded, relative', lambda c: c['progress']),
    ('standing on a slope: slide a frame, relative', lambda c: c['slide']),
    ('riding the platform or the lift: drift a frame, relative', lambda c: c['drift']),
    ('soft movers: deepest overlap of two (the platform sweeps to 1.5 m of a wall)', lambda c: max(0.0, -c['soft'])),
    ('crushed frames (reported, excluded)', lambda c: c['crushed']),
]


def collect(args):
    runs = pathlib.Path(args.runs)
    programs = {}
    for path in sorted(runs.glob('bench_*.json')):
        programs[path.stem] = json.loads(path.read_text())
        # The program by its name: the folder it was built in is the measuring machine's.
        context = programs[path.stem]['context']
        context['executable'] = pathlib.PurePath(context['executable']).name
    today = datetime.date.today().isoformat()
    cpu_slug = re.sub(r'[^a-z0-9]+', '-', args.cpu.lower()).strip('-')
    result = {
        'date': today,
        'machine': {'cpu': args.cpu, 'cores': int(args.cores), 'compiler': args.compiler, 'flags': args.flags},
        'method': {'repetitions': int(args.repetitions), 'min_time_s': float(args.min_time),
                   'interleaved': True, 'statistic': 'median of the repetitions'},
        'benchmarks': programs,
        'report': json.loads((runs / 'report.json').read_text()),
    }
    out = pathlib.Path(args.results) / f'{today}-{cpu_slug}.json'
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(json.dumps(result, indent=1) + '\n')
    print(out)


def medians(result):
    """Each benchmark's median, in ns (per pair for the batches); a run of one repetition has no
    aggregates, and its one measurement stands for the median."""
    out = {}
    for program in result['benchmarks'].values():
        aggregated = any(b.get('aggregate_name') for b in program['benchmarks'])
        for b in program['benchmarks']:
            if b.get('aggregate_name', 'median' if not aggregated else None) != 'median':
                continue
            if 'per_pair' in b:
                out[b['run_name']] = b['per_pair'] * 1e9
            else:
                out[b['run_name']] = b['real_time'] * UNITS[b.get('time_unit', 'ns')]
    return out


def fmt_time(ns):
    if ns is None:
        return '—'
    for unit, scale in (('s', 1e9), ('ms', 1e6), ('µs', 1e3)):
        if ns >= 0.9995 * scale:  # what rounds to 1.00 of the unit is written in it
            return f'{ns / scale:.3g} {unit}'
    return f'{ns:.3g} ns'


def fmt_ratio(ours, rival):
    if ours is None or rival is None:
        return '—'
    return f'{ours / rival:.2f}x'


def table(rows, med, workloads):
    """One row per comparison: a column per workload (a list of WORKLOADS' kind), or one figure."""
    lines = []
    if workloads:
        head = '| pair | ' + ' | '.join(f'{w} pairs: collide2d / Box2D' for w, _ in workloads) + ' |'
        lines += [head, '| --- |' + ' --- |' * len(workloads)]
        for label, ours, rival in rows:
            cells = []
            for _, n in workloads:
                o, r = med.get(ours.format(w=n)), med.get(rival.format(w=n))
                cells.append('—' if o is None and r is None else f'{fmt_time(o)} / {fmt_time(r)} = **{fmt_ratio(o, r)}**')
            lines.append(f'| {label} | ' + ' | '.join(cells) + ' |')
    else:
        lines += ['| what | collide2d | Box2D | ratio |', '| --- | --- | --- | --- |']
        for label, ours, rival in rows:
            o, r = med.get(ours), med.get(rival)
            lines.append(f'| {label} | {fmt_time(o)} | {fmt_time(r)} | **{fmt_ratio(o, r)}** |')
    return '\n'.join(lines)


def ratio_svg(groups, med):
    """Horizontal bars of collide2d's time over Box2D's (log scale), one per row, candidate pairs
    where the row has workloads."""
    bars = []
    for title, rows, workloads in groups:
        for label, ours, rival in rows:
            o = med.get(ours.format(w=1) if workloads else ours)
            r = med.get(rival.format(w=1) if workloads else rival)
            if o and r:
                bars.append((f'{title}: {label}', o / r))
    width, left, right, top, row = 900, 380, 40, 50, 20
    height = top + row * len(bars) + 50
    lo, hi = -2.0, 1.0  # 0.01x to 10x
    x = lambda v: left + (math.log10(min(max(v, 10 ** lo), 10 ** hi)) - lo) / (hi - lo) * (width - left - right)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="20" y="24" font-size="15">collide2d time / Box2D time (candidate pairs; below 1: collide2d faster)</text>']
    for k in range(int(lo), int(hi) + 1):
        xx = x(10 ** k)
        out.append(f'<line x1="{xx:.1f}" y1="{top - 8}" x2="{xx:.1f}" y2="{height - 40}" stroke="{"#333" if k == 0 else "#ddd"}"/>')
        out.append(f'<text x="{xx:.1f}" y="{height - 22}" text-anchor="middle">{10.0 ** k:g}x</text>')
    for i, (label, v) in enumerate(bars):
        y = top + i * row
        x0, x1 = sorted((x(1.0), x(v)))
        colour = '#17a589' if v < 1 else '#c0392b'
        out.append(f'<rect x="{x0:.1f}" y="{y:.1f}" width="{max(x1 - x0, 1):.1f}" height="{row - 6}" fill="{colour}"/>')
        out.append(f'<text x="{left - 8}" y="{y + row - 9:.1f}" text-anchor="end">{html.escape(label)}</text>')
        out.append(f'<text x="{x1 + 4 if v >= 1 else x0 - 4:.1f}" y="{y + row - 9:.1f}" font-size="10" '
                   f'text-anchor="{"start" if v >= 1 else "end"}">{v:.2f}x</text>')
    out.append('</svg>')
    return '\n'.join(out) + '\n'


def error_of(value):
    """An error from the report; null (a method that failed on some pair) as infinite."""
    return math.inf if value is None else value


def error_svg(results, title):
    """Time per query against error, log-log: a point per method, a curve per Box2D fit over N; an
    infinite error's bar reaches the top."""
    results = [dict(r, median_error=error_of(r['median_error']), max_error=error_of(r['max_error'])) for r in results]
    width, height, left, right, top, bottom, floor = 820, 520, 90, 230, 40, 60, 1e-17
    times = [r['nanoseconds'] for r in results]
    x0, x1 = math.floor(math.log10(min(times))), math.ceil(math.log10(max(times)))
    y0 = math.log10(floor)
    y1 = max(0, math.ceil(math.log10(max(max(r['max_error'] for r in results if math.isfinite(r['max_error'])), floor))))
    px = lambda t: left + (math.log10(t) - x0) / (x1 - x0) * (width - left - right)
    py = lambda e: height - bottom - (math.log10(min(max(e, floor), 10.0 ** y1)) - y0) / (y1 - y0) * (height - top - bottom)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" font-family="sans-serif" font-size="12">',
           '<rect width="100%" height="100%" fill="white"/>', f'<text x="{left}" y="24" font-size="15">{html.escape(title)}</text>']
    for k in range(x0, x1 + 1):
        xx = px(10 ** k)
        out.append(f'<line x1="{xx:.1f}" y1="{top}" x2="{xx:.1f}" y2="{height - bottom}" stroke="#ddd"/>')
        out.append(f'<text x="{xx:.1f}" y="{height - bottom + 18}" text-anchor="middle">1e{k}</text>')
    for k in range(int(y0), y1 + 1, 2):
        yy = py(10.0 ** k)
        out.append(f'<line x1="{left}" y1="{yy:.1f}" x2="{width - right}" y2="{yy:.1f}" stroke="#ddd"/>')
        out.append(f'<text x="{left - 8}" y="{yy + 4:.1f}" text-anchor="end">1e{k}</text>')
    out.append(f'<text x="{(left + width - right) / 2}" y="{height - 18}" text-anchor="middle">time per query (ns, log)</text>')
    out.append(f'<text transform="rotate(-90)" x="{-(top + height - bottom) / 2}" y="24" text-anchor="middle">'
               'median error / scale (log; the bar reaches the largest; 1e-17 and below at the floor)</text>')
    colours = ['#c0392b', '#8e44ad', '#d68910', '#2471a3', '#17a589']
    names = []
    for r in results:
        if r['method'] not in names:
            names.append(r['method'])
    for m, name in enumerate(names):
        colour = colours[m % len(colours)]
        points = []
        for r in results:
            if r['method'] != name:
                continue
            xx, yy, top_y = px(r['nanoseconds']), py(r['median_error']), py(r['max_error'])
            points.append(f'{xx:.1f},{yy:.1f}')
            out.append(f'<line x1="{xx:.1f}" y1="{yy:.1f}" x2="{xx:.1f}" y2="{top_y:.1f}" stroke="{colour}" stroke-opacity="0.5"/>')
            out.append(f'<circle cx="{xx:.1f}" cy="{yy:.1f}" r="4" fill="{colour}"/>')
            tag = r['sides'] or (f'{r["tolerance"]:.0e}' if r.get('tolerance') else '')
            if tag:
                out.append(f'<text x="{xx + 5:.1f}" y="{yy - 5:.1f}" font-size="10">{tag}</text>')
        out.append(f'<polyline points="{" ".join(points)}" fill="none" stroke="{colour}"/>')
        ly = top + 20 + 22 * m
        out.append(f'<circle cx="{width - right + 20}" cy="{ly - 4}" r="4" fill="{colour}"/>')
        out.append(f'<text x="{width - right + 30}" y="{ly}">{html.escape(name)}</text>')
    out.append('</svg>')
    return '\n'.join(out) + '\n'


def report_table(results):
    """The report's rows; a contact's normal and point errors where the results have them."""
    contacts = any('median_normal_error' in r for r in results)
    lines = ['| method | N | time per query | median error | max error |' + (' normal (median / max, rad) | point (median / max) |' if contacts else ''),
             '| --- | --- | --- | --- | --- |' + (' --- | --- |' if contacts else '')]
    pair_of = lambda r, what: ' / '.join(f'{r[k]:.1e}' if k in r else '—' for k in (f'median_{what}_error', f'max_{what}_error'))
    for r in results:
        errors = [f'{e:.1e}' if math.isfinite(e) else 'failed' for e in (error_of(r['median_error']), error_of(r['max_error']))]
        n = r['sides'] or (f'{r["tolerance"]:.0e}' if r.get('tolerance') else '—')
        extra = f' {pair_of(r, "normal")} | {pair_of(r, "point")} |' if contacts else ''
        lines.append(f'| {r["method"]} | {n} | {fmt_time(r["nanoseconds"])} | {errors[0]} | {errors[1]} |' + extra)
    return '\n'.join(lines)


METRICS = (('', 'separation'), ('normal_', 'normal'), ('point_', 'point'))


def errors_within(ours, rival):
    """Whether each of collide2d's largest errors is within the rival's median error on that metric
    (a metric either leaves unmeasured is not compared)."""
    for key, _ in METRICS:
        mine, theirs = ours.get(f'max_{key}error'), rival.get(f'median_{key}error')
        if mine is not None and theirs is not None and not error_of(mine) <= theirs:
            return False
    return True


def front_table(results):
    """For each pair and each of Box2D's inscribed polygons (v3's where the report has them, else
    2.4.1's), the loosest tolerance of collide2d's whose largest errors are within the polygon's
    median errors (exact where none is), and its time over the polygon's."""
    lines = ['| pair | Box2D | its median errors (separation / normal / point) | collide2d within them | '
             'its largest errors | time: collide2d / Box2D |', '| --- | --- | --- | --- | --- | --- |']
    triple = lambda r, which: ' / '.join(f'{error_of(r[k]):.1e}' if k in r else '—'
                                         for k in (f'{which}_{key}error' for key, _ in METRICS))
    for pair, rows in contact_pairs(results):
        ours = [r for r in rows if r['method'].startswith('collide2d contact')]
        rival = 'box2d v3 manifold inscribed' if any(r['method'].startswith('box2d v3') for r in rows) else 'box2d manifold inscribed'
        for polygon in (r for r in rows if r['method'] == rival and 5 <= r['sides'] <= 8):
            within = [r for r in ours if errors_within(r, polygon)]
            name = f'{"v3" if "v3" in rival else "2.4.1"} {polygon["sides"]}-gon'
            if not within:
                lines.append(f'| {pair} | {name} | {triple(polygon, "median")} | none | — | — |')
                continue
            best = max(within, key=lambda r: r.get('tolerance', 0.0))
            tolerance = f'to {best["tolerance"]:.0e} of the size' if best.get('tolerance') else 'exact'
            lines.append(f'| {pair} | {name} | {triple(polygon, "median")} | {tolerance} | {triple(best, "max")} | '
                         f'{fmt_time(best["nanoseconds"])} / {fmt_time(polygon["nanoseconds"])} = '
                         f'**{fmt_ratio(best["nanoseconds"], polygon["nanoseconds"])}** |')
    return '\n'.join(lines)


def contact_pairs(results):
    """The report's contact results by pair kind, in their order; a result without one is of two
    ellipses."""
    pairs = {}
    for r in results:
        pairs.setdefault(r.get('pair', 'ellipse-ellipse'), []).append(r)
    return list(pairs.items())


PYTHON_ROWS = [('one `overlaps()` call against one C++ call', 'overlaps_one_call'),
               ('`overlaps_arrays` against the C++ batch', 'overlaps_batch'),
               ('a World step from arrays (`set_poses`, `update`)', 'world_step')]


def newest(folder):
    """The newest results file of a folder and its data, or (None, None)."""
    files = sorted(folder.glob('*.json'))
    return (files[-1], json.loads(files[-1].read_text())) if files else (None, None)


def python_section(folder):
    """The Python module against the same work in C++, from the newest bench/results/python file."""
    path, data = newest(folder)
    if not path:
        return ''
    method, machine, results = data['method'], data['machine'], data['results']
    rows = ['| work | Python | C++ | ratio |', '| --- | --- | --- | --- |']
    for label, key in PYTHON_ROWS:
        r = results[key]
        rows.append(f"| {label} | {r['python']:.4g} {r['unit']} | {r['c++']:.4g} {r['unit']} | "
                    f"{r['python'] / r['c++']:.2f} |")
    table_text = '\n'.join(rows)
    return f'''## Python

`bench/python/bench_python.py` (run by `bash scripts/bench.sh`) times the Python module against
`bench/python/python_rival.cpp`, the same work in C++ on the same rows read from the same files:
{method['pairs']:,} ellipse pairs and a World of {method['bodies']:,} ellipses, {method['threads']} thread,
{method['rounds']} rounds alternating the two sides, each the median of {method['repeats']} repeats, and
the median of the rounds kept. The ratio is Python's time over C++'s. From
`bench/results/python/{path.name}` (Python {machine['python']}, NumPy {machine['numpy']},
{data['date']}).

{table_text}

'''


AREA_ROWS = [
    ('rotated-box IoU, batch of 4,096 pairs', 'ours/iou_rotated_boxes_batch', 'detectron2_method/iou_rotated_boxes_batch'),
    ('rotated-box IoU, one pair', 'ours/iou_rotated_boxes', 'detectron2_method/iou_rotated_boxes'),
    ('ellipse–ellipse overlap area, one pair', 'ours/overlap_area/ellipse_ellipse/candidates:3',
     'hughes_chraibi/overlap_area/ellipse_ellipse/candidates:3'),
]
AREA_KINDS = ['circle_circle', 'rect_rect', 'capsule_capsule', 'rect_ellipse', 'circle_ellipse', 'ellipse_ellipse']
NEAR_IDENTICAL_KINDS = ['rect_rect', 'circle_circle', 'capsule_capsule', 'ellipse_ellipse']


def areas_section(folder):
    """Overlap areas and IoU, from the newest bench/results/areas file."""
    path, data = newest(folder)
    if not path:
        return ''
    bench, py, machine = data['benchmarks'], data['results'], data['machine']
    ns = lambda key: bench[key]['ns'] if key in bench else None
    rival = ['| what | collide2d | rival | ratio |', '| --- | --- | --- | --- |']
    for label, ours, theirs in AREA_ROWS:
        rival.append(f'| {label} | {fmt_time(ns(ours))} | {fmt_time(ns(theirs))} | **{fmt_ratio(ns(ours), ns(theirs))}** |')
    kinds = ['| pair | time |', '| --- | --- |']
    for name in AREA_KINDS:
        kinds.append(f"| {name.replace('_', '–')} | {fmt_time(ns(f'ours/overlap_area/{name}/candidates:3'))} |")
    near = ['| pair | `iou()` | `iou_distance()` |', '| --- | --- | --- |']
    for name in NEAR_IDENTICAL_KINDS:
        times = [fmt_time(ns(f'ours/{q}/{name}/near_identical')) for q in ('iou', 'iou_distance')]
        near.append(f"| {name.replace('_', '–')} | {times[0]} | {times[1]} |")
    small, large, dense = (bench.get(k, {}) for k in ('ours/iou_pairs/2000', 'ours/iou_pairs/100000', 'ours/iou_dense/2000'))
    m, sm, d = py['matrix'], py['small_matrix'], py['dense']
    mib = lambda b: f'{b / 2**20:.1f} MiB'
    return f'''## Overlap areas and IoU

`bench/bench_areas.cpp` and `bench/python/bench_areas.py` (run by `bash scripts/bench.sh`), from
`bench/results/areas/{path.name}` ({data['date']}, one thread). Rotated boxes as a detector scores
them: a box and a noisy copy of it (centre moved by up to a fifth of its size, sides changed by up to
a tenth, angle by up to 0.3 rad). The rival is double-precision code written from detectron2's
published method for rotated-box IoU (`narrowphase/baselines/rotated_box_iou.h`: crossings with
fixed epsilons, a Graham hull, a fan), and for two ellipses double-precision code following Hughes
and Chraibi, "Calculating ellipse overlap areas" (`narrowphase/baselines/ellipse_overlap_area.h`: a
quartic solved in closed form, sectors less triangles), on the overlapping candidate pairs
(bench/shape_pairs.h); both compiled alike, their accuracy beside collide2d's on the
[overlap area page](overlap-area.md#accuracy). The batch is `ious()` over spans against a loop of the
rival over the same pairs.

{chr(10).join(rival)}

`overlap_area()`, one pair at a time, on the overlapping candidate pairs of each kind
(bench/shape_pairs.h):

{chr(10).join(kinds)}

`iou()` beside `iou_distance()` on near-identical pairs, each overlapping candidate's first shape
beside itself moved by 10⁻⁶ of its size and turned by 10⁻⁶ rad, where `iou_distance()` takes the
overlap and both areas again in double-double to keep its own digits
([method](overlap-area.md#method)):

{chr(10).join(near)}

The N × N problem, `iou_pairs()`: {large.get('pairs', 0):,} pairs with IoU above 0 among 100,000 boxes
against 100,000 in {fmt_time(ns('ours/iou_pairs/100000'))}; at 2,000 against 2,000,
{fmt_time(ns('ours/iou_pairs/2000'))} against {fmt_time(ns('ours/iou_dense/2000'))} for `iou()` of every
pair ({small.get('pairs', 0):,} and {dense.get('pairs', 0):,} pairs found).

From Python ({machine['python']}, NumPy {machine['numpy']}, shapely {machine['shapely']}), on
{data['method']['pairs']:,} pairs, the median of {data['method']['rounds']} alternating rounds:
`iou_arrays` takes {fmt_time(py['iou_arrays_ns'])} per pair, shapely's polygon intersection (polygons
built beforehand) {fmt_time(py['shapely_ns'])}: **{py['shapely_ns'] / py['iou_arrays_ns']:.0f}x**; the
largest difference of their IoUs is {py['largest_difference']:.1e}. `iou_matrix` of
{m['n']:,} boxes against {m['n']:,} takes {m['seconds']:.3g} s and adds {mib(m['peak_bytes'])} to the
process's peak memory ({m['pairs']:,} pairs); at {d['n']:,} against {d['n']:,}, {sm['seconds'] * 1e3:.3g} ms
and {mib(sm['peak_bytes'])}, where `iou_arrays` over every pair (the rows repeated) takes
{d['seconds']:.3g} s and {mib(d['peak_bytes'])}.

'''


# The network a model of many ranks assumes: one message's latency and a link's bandwidth, those of
# a common InfiniBand cluster, not measured here.
LATENCY_S = 2e-6
BANDWIDTH_BYTES_S = 10e9


def mpi_model(runs):
    """Weak scaling of DistributedWorld to many ranks from the measured per-body costs: 10^6 bodies
    per rank, the field square (so that slabs thin as ranks grow) or a corridor (slabs of a fixed
    height), three all-to-all exchanges a frame."""
    one = next(r for r in runs if r['ranks'] == 1 and r['height'] == min(x['height'] for x in runs if x['ranks'] == 1))
    two = [r for r in runs if r['ranks'] == 2]
    per_body = one['world_alone_ms'] * 1e-3 / one['bodies_per_rank']
    layer = max(0.0, one['frame_ms'] * 1e-3 / one['bodies_per_rank'] - per_body)
    ghosts_per_length = sum(r['ghosts_per_rank'] / r['height'] for r in two) / len(two)
    bytes_per_ghost = sum(r['bytes_per_rank'] / max(r['ghosts_per_rank'], 1) for r in two) / len(two)
    area = one['width'] * one['height'] / one['bodies_per_rank']  # per body
    n = 1e6
    rows = []
    for p in (1, 64, 1024):
        for shape in ('square field', 'corridor'):
            height = math.sqrt(p * n * area) if shape == 'square field' else math.sqrt(n * area)
            sides = 0 if p == 1 else 2
            ghosts = sides * height * ghosts_per_length
            sent = ghosts * bytes_per_ghost
            compute = (n + ghosts) * (per_body + layer)
            network = (0 if p == 1 else 3 * LATENCY_S * (p - 1)) + sent / BANDWIDTH_BYTES_S
            rows.append((p, shape, ghosts, sent, compute, network))
    base = rows[0][4] + rows[0][5]
    lines = ['| ranks | field | ghosts per rank | bytes sent per rank | compute | network | frame | weak-scaling efficiency |',
             '| --- | --- | --- | --- | --- | --- | --- | --- |']
    for p, shape, ghosts, sent, compute, network in rows:
        if p == 1 and shape == 'corridor':
            continue
        frame = compute + network
        lines.append(f'| {p:,} | {shape} | {ghosts:,.0f} | {sent / 1e6:.2f} MB | {compute * 1e3:.0f} ms | '
                     f'{network * 1e3:.2f} ms | {frame * 1e3:.0f} ms | {base / frame:.3f} |')
    return '\n'.join(lines), per_body, layer, ghosts_per_length, bytes_per_ghost


def mpi_section(folder):
    """DistributedWorld measured with 1 and 2 ranks, from the newest bench/results/mpi file, and the model."""
    path, data = newest(folder)
    if not path:
        return ''
    runs = data['runs']
    rows = ['| ranks | field height (boundary length) | frame | one World alone | ghosts per rank | bytes sent per rank | bodies handed on per rank |',
            '| --- | --- | --- | --- | --- | --- | --- |']
    for r in runs:
        rows.append(f"| {r['ranks']} | {r['height']:.0f} | {r['frame_ms']:.2f} ms | {r['world_alone_ms']:.2f} ms | "
                    f"{r['ghosts_per_rank']:,.0f} | {r['bytes_per_rank'] / 1e3:,.1f} kB | {r['migrated_per_rank']:.1f} |")
    model, per_body, layer, ghosts_per_length, bytes_per_ghost = mpi_model(runs)
    measured = '\n'.join(rows)
    return f'''## Over MPI ranks

`bench/mpi/bench_distributed.cpp` under `mpirun -np 1` and `-np 2` (run by `bash scripts/bench.sh`):
{runs[0]['bodies_per_rank']:,} moving ellipses and circles per rank at 8% coverage, each rank's slab
of the same area, the field's height (the length of the boundary between slabs) doubled twice at a
fixed area; each figure the median over the frames, per rank (the ranks' mean), a frame's time the
slowest rank's; beside it one plain World of the same bodies on one rank. Both ranks share this
machine's {data['machine']['cores']} cores. From `bench/results/mpi/{path.name}`.

{measured}

**A model, not a measurement**: weak scaling to 64 and 1,024 ranks with 10^6 bodies per rank, from
the figures above: {per_body * 1e9:.0f} ns per body for the World, {layer * 1e9:.0f} ns per body for
the exchange layer around it, {ghosts_per_length:.2f} ghosts per unit of boundary, {bytes_per_ghost:.0f}
bytes per ghost sent; and an assumed network of {LATENCY_S * 1e6:.0f} µs per message and
{BANDWIDTH_BYTES_S / 1e9:.0f} GB/s per link. A rank inside the field has two boundaries; a frame
makes three all-to-all exchanges, each costing a latency per rank. In a square field the slabs
thin as the ranks grow (height √p times one rank's), so ghosts grow as √p; in a corridor they stay
as they are ([distributed.md](distributed.md#scale)).

{model}

'''


def has_runs(med, prefix):
    """Whether the run measured any benchmark whose name starts with `prefix`."""
    return any(name.startswith(prefix) for name in med)


def v3_contact_section(med):
    """The contacts raced against Box2D v3, or how to add them where the run has none."""
    if not has_runs(med, 'box2d_v3/'):
        return ('These results have no Box2D v3 figures: `BOX2D_V3_DIR=<a Box2D v3 source folder> bash '
                'scripts/bench.sh` adds them.')
    return f"""Box2D v3: its manifold function of the pair (`b2CollideCapsules`, `b2CollidePolygons`,
`b2CollideSegmentAndPolygon`, `b2CollideChainSegmentAndPolygon`, ...) on the shapes in their own
frames with float transforms, as v3's bodies hold them, the shapes in the order it takes them. Its
timed call forms B's transform relative to A's and maps the manifold's normal and points to world
coordinates, as collide2d returns them; a chain segment's simplex cache starts empty on every call.
collide2d: `contact()` on the shapes with their orientations kept (the World's call), asked for no
contact beyond v3's speculative distance (`max_separation` 0.02, `B2_SPECULATIVE_DISTANCE` at one
length unit per metre), beyond which v3 returns no manifold. Each benchmark counts the share of its
pairs whose manifold has points (the counter `manifolds` in the results file): the two libraries'
are equal for the exact pairs, and differ by up to 10 pairs in 100 where v3 meets an ellipse as its
inscribed 8-gon or a chain segment as its one-sided edge. v3 computes in float, collide2d in double.
A rounded polygon is one of the 8-gons rounded by 5% to 30% of its smaller half axis (v3's
`b2MakePolygon` with that radius). The scene has no polygons, capsules, segments or chains: their rows
have no scene columns.

{table(CONTACT_V3, med, CONTACT_WORKLOADS)}

{v3_tolerance_part(med)}"""


def v3_tolerance_part(med):
    """The pairs with an ellipse to a tolerance against v3's smaller polygons, where the run has them."""
    if not has_runs(med, 'ours/circle_ellipse_speculative_tolerance'):
        return ''
    return f"""The pairs with an ellipse to a tolerance (`ContactOptions::tolerance` 1e-2 of the pair's size, the
larger `reach_of`; [contacts](contacts.md#contacts-to-a-tolerance)) against v3 on the ellipse's
inscribed 5- to 8-gons. The errors each side carries are weighed under
[speed against error](#speed-against-error).

{table(CONTACT_V3_TOLERANCE, med, CONTACT_WORKLOADS)}"""


def v3_toi_section(med):
    """Time of impact raced against Box2D v3's, where the run has it, before 2.4.1's table."""
    if not has_runs(med, 'box2d_v3_toi/'):
        return ''
    return f"""Box2D v3's `b2TimeOfImpact` on the same pairs (bench/box2d_v3/toi.cpp), its sweeps turning
by interpolated rotations where collide2d's turn at a constant rate:

{table(TOI_V3, med, False)}

Box2D 2.4.1's:

"""


def v3_world_section(med):
    """The frame with contacts raced against Box2D v3's World, where the run has it."""
    if not has_runs(med, 'box2d_v3_frame/'):
        return ''
    return f"""With contacts (`WorldOptions::contacts`), against Box2D v3's World on the same
bodies (bench/box2d_v3/world.cpp): dynamic bodies with no gravity, sleep or continuous collision, one
worker, each frame every body's `b2Body_SetTransform` with its velocities zeroed, then
`b2World_Step`. v3's time is its pose loop's plus the step's `b2Profile` `pairs` and `collide`
(what makes its contacts; its solver is not counted). The scene's level is static in both, its cave
a `b2ChainShape` loop in v3, its sensors sensor shapes, its layers `b2Filter`s.

{table(WORLD_V3, med, False)}

"""


def course_runs(result):
    """The mover suite's counters by (shape, library): one run each, never repeated."""
    program = result['benchmarks'].get('bench_movers', {'benchmarks': []})
    return {tuple(b['name'].split('/')[1:3]): b for b in program['benchmarks'] if b['name'].startswith('mover_course/')}


def fmt_figure(x):
    return f'{x:.0f}' if x == int(x) and abs(x) >= 1 else f'{x:.2g}'


def movers_section(result, med):
    """The character movers' crowd against Box2D v3's mover loop, and the mover suite's worst values."""
    if not has_runs(med, 'movers/'):
        return ''
    runs = course_runs(result)
    ours = [c for (shape, library), c in runs.items() if library == 'collide2d']
    rows = []
    for label, figure in COURSE_CHECKS:
        capsule, v3 = runs.get(('capsule', 'collide2d')), runs.get(('capsule', 'box2d_v3'))
        worst = max((figure(c) for c in ours), key=abs, default=None)
        cells = [fmt_figure(figure(c)) if c else '—' for c in (capsule,)] + [
            fmt_figure(worst) if worst is not None else '—', fmt_figure(figure(v3)) if v3 else '—']
        rows.append(f'| {label} | ' + ' | '.join(cells) + ' |')
    crowd = table(MOVERS, med, False)
    return f"""## Character movers

1,000 movers walking and jumping at random in a level of 10,000 static shapes, one `move()` each a
frame on one thread, the movers not seeing each other (bench/bench_movers.cpp); Box2D v3: its
mover sample's loop on capsules (`b2World_CollideMover`, `b2SolvePlanes`, `b2World_CastMover`, at
most 5 times, then `b2ClipVector`). The ellipse crowd has no Box2D counterpart:
{fmt_time(med.get('movers/ellipse/collide2d'))} a frame.

{crowd}

The mover suite ([moving characters](movers.md#tests)), 10,000 frames of six movers at once on a
scripted level, every move judged with collide2d's exact `contact()`: collide2d's capsule, the
worst of its six mover shapes, and Box2D v3's capsule moved as its geometric mover sample moves it
(a spring on a ray down holds the capsule 0.1 above the ground). Relative figures are over
max(|position|, size).

| check | collide2d capsule | collide2d, worst shape | Box2D v3 capsule |
| --- | --- | --- | --- |
{chr(10).join(rows)}

"""


def tree_rival(med):
    """The box tree against Box2D v3's b2DynamicTree where the run has it, else 2.4.1's."""
    if has_runs(med, 'box/box2d_v3/'):
        return f"""Box2D v3's `b2DynamicTree_QueryAll` and `b2DynamicTree_RayCast` on the
same boxes, each tree as insertion leaves it and fully rebuilt (`rebuild()`, `b2DynamicTree_Rebuild`).

{table(QUERIES_V3, med, False)}"""
    return f"""Box2D 2.4.1's `b2DynamicTree::Query` and `RayCast` on the same
boxes.

{table(QUERIES, med, False)}"""


def page(args):
    files = sorted(pathlib.Path(args.results).glob('*.json'))
    if not files:
        sys.exit('no results in ' + args.results)
    side_files = [f for folder in ('python', 'mpi', 'areas') for f in sorted((pathlib.Path(args.results) / folder).glob('*.json'))]
    newest = json.loads(files[-1].read_text())
    med = medians(newest)
    machine, method = newest['machine'], newest['method']
    groups = [('contact vs v3', CONTACT_V3, True), ('overlap', OVERLAP, True), ('distance', DISTANCE, True), ('contact', CONTACT, True),
              ('time of impact', TOI, False), ('time of impact vs v3', TOI_V3, False),
              ('broad phase', BROAD, False), ('World', WORLD, False),
              ('World vs v3', WORLD_V3, False)]
    report = newest['report']
    svgs = {
        'ratios.svg': ratio_svg(groups, med),
        'distance_error.svg': error_svg(report['distance'], 'ellipse–ellipse distance: time per query against error'),
    }
    contact_sections = []
    for pair, rows in contact_pairs(report['contact']):
        name = 'contact_error.svg' if pair == 'ellipse-ellipse' else f'contact_error_{pair.replace("-", "_")}.svg'
        label = pair.replace('-', '–')
        svgs[name] = error_svg(rows, f'{label} contact depth: time per query against error')
        contact_sections.append(f'### {label[0].upper() + label[1:]}\n\n'
                                f'![{label} contact depth: time against error](performance/{name})\n\n'
                                f'{report_table(rows)}')
    text = f'''# Performance

This page is generated: `bash scripts/bench.sh` runs the benchmark suite and writes its results to
`bench/results/<date>-<cpu>.json`, and `python3 scripts/performance.py page --results bench/results
--out docs` makes this page and its plots from those files alone. The figures below are from
`{files[-1].name}`.

## How the comparisons are made

- **The rivals** are Box2D v3, the Box2D games use today, built from a copy of its source that
  `scripts/bench.sh` is given (`BOX2D_V3_DIR`), and Box2D 2.4.1, built from Debian's source, where
  v3 has no counterpart in the suite. Both are compiled by the same compiler with the same flags as
  collide2d and linked statically into the same benchmark programs. An ellipse is Box2D's polygon
  inscribed in it, with the vertex count given (v3 and 2.4.1 cap it at 8; the 2.4.1 contact
  benchmark builds 2.4.1 with 16), so Box2D's answers carry the polygon's error, which collide2d's
  do not ([accuracy](accuracy.md)); the speed-against-error tables below weigh both.
- **One pair at a time against one pair at a time**: collide2d's kernel with each shape's
  orientation kept, against Box2D's function with its transforms prepared, one call per pair,
  cycling through 4,096 pre-generated pairs so that no input is cached.
- **A batch against the rival's fastest loop**, labelled *batch*: collide2d's batched call over the
  4,096 pairs against a loop of Box2D's function over the same list, both as time per pair.
- **The same thread count**: every World figure compared with Box2D's pipeline runs the World on one
  thread, as Box2D runs.
- **Statistics**: each benchmark repeated {method['repetitions']} times, repetitions of all
  benchmarks of a program interleaved at random, and the median kept; ratios compare medians of one
  run. The ratio is collide2d's time over Box2D's: below 1, collide2d is faster.
- **Workloads** for pairs (bench/shape_pairs.h): *random* pairs (centres in a 4 × 4 square, sizes 0.05
  to 1, ellipse aspect up to 10; most far apart), *candidate* pairs (the same generator, only pairs
  whose boxes overlap, as a broad phase hands them over), and *scene* pairs (those the built-in
  scene's broad phase hands over, frame after frame). Both libraries' shapes are made in pair
  order: Box2D's into one array, collide2d's polygon outlines one after another in memory.

## The machine

| | |
| --- | --- |
| CPU | {machine['cpu']} |
| cores | {machine['cores']} |
| compiler | {machine['compiler']} |
| flags | `{machine['flags']}` |
| date | {newest['date']} |

![collide2d's time over Box2D's](performance/ratios.svg)

## Contacts against Box2D v3

{v3_contact_section(med)}

## Overlap tests

Box2D: `b2TestOverlap` on a rectangle's 4-gon and an ellipse's inscribed 8-gon (a circle is a
`b2CircleShape`). The polygons are convex 8-gons, the same in both libraries (bench/shape_pairs.h).
Box2D 2.4.1 has no capsule: its nearest equivalent is a box rounded by a radius
(`b2PolygonShape::m_radius`), of half extents (h + 0.003, 0.003) and radius r - 0.003, within
0.0013 of the capsule (bench/box2d_baseline.h). A segment is a two-sided `b2EdgeShape`. The scene
has no polygons, capsules or segments, so their rows are the random and candidate pairs.

{table(OVERLAP, med, WORKLOADS)}

## Distance

Box2D: `b2Distance` on the ellipses' inscribed N-gons.

{table(DISTANCE, med, WORKLOADS)}

## Contacts against Box2D 2.4.1

Box2D: `b2CollidePolygons`, `b2CollidePolygonAndCircle` and `b2CollideCircles` on the polygons (a
capsule its rounded box, as above), `b2CollideEdgeAndPolygon` and `b2CollideEdgeAndCircle` on a
segment's two-sided edge, and on a chain segment's one-sided child edge of `b2ChainShape` with its
ghost vertices (each end's neighbour turned 0.3 rad, convex or concave by the pair's index); its
manifold is empty for pairs apart, where collide2d's contact carries the exact distance and normal.
The scene has no polygons, capsules, segments or chains: their rows have no scene columns.

{table(CONTACT, med, CONTACT_WORKLOADS)}

## Time of impact

Pairs apart at t = 0 coming together over one step, translating or both turning up to 2 radians a
step (bench/bench_toi.cpp); Box2D: `b2TimeOfImpact` on the inscribed polygons with the same sweeps.

{v3_toi_section(med)}{table(TOI, med, False)}

## Broad phase

Every box moved, then one update (bench/bench_broadphase.cpp); Box2D's `b2BroadPhase` driven as
`b2World` drives it (`MoveProxy` per box, `UpdatePairs`, a `TestOverlap` on every known pair).

{table(BROAD, med, False)}

## Queries through the box tree

Every box a query box (half side 4) or a ray (30 long) meets, in a uniform scene 8% covered
(bench/query_scene.h). {tree_rival(med)}

## The World

One frame: every moving body posed, then `update()`, on one thread (bench/bench_world.cpp); Box2D's
pipeline on the same bodies (`b2BroadPhase`, then `b2TestOverlap` on its pairs, the filters applied
as `b2ContactManager` applies them).

{table(WORLD, med, False)}

{v3_world_section(med)}{movers_section(newest, med)}{python_section(pathlib.Path(args.results) / 'python')}{areas_section(pathlib.Path(args.results) / 'areas')}{mpi_section(pathlib.Path(args.results) / 'mpi')}## Speed against error

`collide2d_report`: {report['pairs']} ellipse pairs of the random generator, time the median of
{report['repetitions']} passes, error against the 50-digit reference as a fraction of max(size,
centre distance), median and largest over the pairs. The reference methods `gradient` and
`polynomial` are in [two ellipses](algorithms/ellipse-ellipse.md). `collide2d_report --html FILE`
writes the same measurements as a page: the plot with each method's figures on hover, and the pair
kinds to show or hide, beside the tables.

![distance: time against error](performance/distance_error.svg)

{report_table(report['distance'])}

The contact depth of overlapping pairs deeper than 2% of the size, for each curved pair (rectangles
of aspect up to 10, circles of the same sizes); collide2d one pair at a time, exact and to
tolerances of 1e-1 to 1e-12 of the pair's size, and, where it has one, its batch (the whole list
timed, per pair); Box2D 2.4.1's manifold on N-gons inscribed in and circumscribed about each
ellipse, N = 5 to 8 and 16, and where the run has v3, v3's on the inscribed 5- to 8-gons. A Box2D
manifold without points counts as separation 0. Each metric is measured against the 50-digit
reference: the separation, the normal's angle (rad) and the deepest points' midpoint (over the
scale), the last two on the pairs whose deepest direction is unique.

### The fronts

For each pair and each of Box2D's inscribed polygons, the loosest tolerance at which collide2d's
largest error on every metric is within that polygon's median error on it, and its time there. A rectangle's face is exact in
Box2D too, so against a rectangle the normal's median error is float rounding, and only a tight
tolerance meets it.

{front_table(report['contact'])}

{(chr(10) * 2).join(contact_sections)}

## Results on file

{chr(10).join(f"- `{f.resolve().relative_to(ROOT)}`" for f in files + side_files)}
'''
    out = pathlib.Path(args.out)
    wanted = {out / 'performance.md': text}
    wanted.update({out / 'performance' / name: svg for name, svg in svgs.items()})
    if args.check:
        # Results name programs, never the folders of the machine that measured them.
        placed = [str(f) for f in files + side_files if re.search(r'"(/work|/home|/root|/tmp)/', f.read_text())]
        if placed:
            print('results with a path of the machine that made them: ' + ', '.join(placed))
            sys.exit(1)
        stale = [str(p) for p, content in wanted.items() if not p.exists() or p.read_text() != content]
        if stale:
            print('out of date with bench/results (python3 scripts/performance.py page --results bench/results '
                  '--out docs): ' + ', '.join(stale))
            sys.exit(1)
        return
    for path, content in wanted.items():
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(content)


def main():
    parser = argparse.ArgumentParser()
    sub = parser.add_subparsers(dest='command', required=True)
    c = sub.add_parser('collect')
    for name in ('runs', 'results', 'cpu', 'cores', 'compiler', 'flags', 'repetitions', 'min-time'):
        c.add_argument('--' + name, required=True)
    p = sub.add_parser('page')
    p.add_argument('--results', required=True)
    p.add_argument('--out', required=True)
    p.add_argument('--check', action='store_true')
    args = parser.parse_args()
    collect(args) if args.command == 'collect' else page(args)


if __name__ == '__main__':
    main()
