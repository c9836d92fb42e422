"""No leaks: a million calls of each kind (single queries, array forms, World updates with arrays
returned) leave the resident memory within 1 MB of where it stood after a warm-up."""
import numpy as np

import collide2d


def resident_kib():
    with open('/proc/self/status') as status:
        return next(int(line.split()[1]) for line in status if line.startswith('VmRSS:'))


def grows_by(step, warm_up, calls):
    for _ in range(warm_up):
        step()
    before = resident_kib()
    for _ in range(calls):
        step()
    return resident_kib() - before


def test_a_million_single_queries_hold_their_memory():
    a, b = collide2d.Ellipse((0, 0), 2, 1, 0.3), collide2d.Rect((1, 1), (1, 0.5), 0.2)

    def step():
        collide2d.contact(a, b).manifold
        collide2d.distance(a, b).point_a
        collide2d.Circle((0, 0), 1)

    assert grows_by(step, 10000, 1000000) < 1024


def test_array_forms_and_world_updates_hold_their_memory():
    rng = np.random.default_rng(1)
    rows = np.hstack([rng.uniform(-3, 3, (1000, 2)), rng.uniform(0.1, 1, (1000, 2)), rng.uniform(-3, 3, (1000, 1))])
    world = collide2d.World(contacts=True)
    ids = np.array([world.add(collide2d.Ellipse(r[:2], r[2], r[3], r[4])) for r in rows[:200]], dtype=np.uint64)

    def step():
        collide2d.overlaps_arrays('ellipse', rows, 'ellipse', rows[::-1])
        collide2d.contact_arrays('rect', rows, 'ellipse', rows[::-1])
        world.set_poses(ids, rows[:200, :2] + rng.uniform(-0.01, 0.01, (200, 2)), rows[:200, 4])
        world.update()
        world.overlapping(), world.contacts()

    assert grows_by(step, 50, 1000) < 1024
