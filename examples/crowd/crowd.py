"""A crowd of elliptical agents walking along a corridor, stepped from Python with collide2d: each
frame the agents move towards the far end, the World finds every overlapping pair and its contact,
and each pair is pushed apart along its normal by its depth. No loop over agents or pairs in Python:
poses go in with set_poses, contacts come out as arrays. Writes a picture of the last frame and
prints the frames per second.

    /usr/bin/python3 examples/crowd/crowd.py [--agents 10000] [--frames 200] [--out crowd.png]
"""
import argparse
import time

import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from matplotlib.collections import EllipseCollection
import numpy as np

import collide2d

A, B = 0.25, 0.15  # the agents' semi-axes, along and across their heading
SPEED, DT = 1.3, 0.05


def corridor(agents):
    """Length and width for a crowd filling about a third of the corridor."""
    width = max(4.0, np.sqrt(agents) * 0.25)
    return agents * np.pi * A * B * 3 / width, width


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    parser.add_argument('--agents', type=int, default=10000)
    parser.add_argument('--frames', type=int, default=200)
    parser.add_argument('--out', default='crowd.png')
    args = parser.parse_args()
    rng = np.random.default_rng(1)
    length, width = corridor(args.agents)
    centres = np.column_stack([rng.uniform(0, length, args.agents), rng.uniform(-width / 2 + B, width / 2 - B, args.agents)])
    angles = rng.normal(0, 0.2, args.agents)
    world = collide2d.World(contacts=True, fat_margin=0.05)
    ids = np.array([world.add(collide2d.Ellipse(c, A, B, t)) for c, t in zip(centres, angles)], dtype=np.uint64)
    for y in (-width / 2 - 0.5, width / 2 + 0.5):  # the corridor's walls
        world.add(collide2d.Rect((length / 2, y), (length / 2 + 1, 0.5)), static=True)
    row_of = lambda body: (body & 0xffffffff).astype(np.int64)  # agents were added first: slot = row
    pushes = 0
    started = time.perf_counter()
    for _ in range(args.frames):
        heading = np.column_stack([np.cos(angles), np.sin(angles)])
        centres += SPEED * DT * heading
        centres[:, 0] %= length
        world.set_poses(ids, centres, angles)
        world.update()
        contacts = world.contacts()
        a, b = row_of(contacts['pairs'][:, 0]), row_of(contacts['pairs'][:, 1])
        push = -0.5 * contacts['separation'] * contacts['normal']  # half the depth each way
        moved = np.zeros_like(centres)
        agents_a, agents_b = a < args.agents, b < args.agents
        np.add.at(moved, a[agents_a], -push[agents_a] * np.where(agents_b[agents_a], 1.0, 2.0)[:, None])
        np.add.at(moved, b[agents_b], push[agents_b] * np.where(agents_a[agents_b], 1.0, 2.0)[:, None])
        centres += moved
        # An agent turns a little towards its sideways push, and back towards the corridor's axis.
        angles += 0.2 * (np.arctan2(moved[:, 1], 1.0) - 0.1 * angles)
        pushes += len(contacts['separation'])
    seconds = time.perf_counter() - started
    figure, axes = plt.subplots(figsize=(12, 12 * width / length + 1))
    axes.add_collection(EllipseCollection(2 * A * np.ones(args.agents), 2 * B * np.ones(args.agents),
                                          np.degrees(angles), units='xy', offsets=centres,
                                          transOffset=axes.transData, facecolors='#7aa6d8', edgecolors='#2a4f7a'))
    axes.set_xlim(0, length)
    axes.set_ylim(-width / 2 - 1, width / 2 + 1)
    axes.set_aspect('equal')
    axes.axhspan(width / 2, width / 2 + 1, color='#999')
    axes.axhspan(-width / 2 - 1, -width / 2, color='#999')
    figure.savefig(args.out, dpi=100, bbox_inches='tight')
    print(f'{args.agents} agents, {args.frames} frames, {pushes} contacts resolved')
    print(f'frames per second: {args.frames / seconds:.1f}')
    print(f'picture: {args.out}')


if __name__ == '__main__':
    main()
