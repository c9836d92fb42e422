"""The World from Python: bodies driven from arrays over frames against an all-pairs check made of the
array forms, began and ended against the sets' differences, a Python pair predicate on several
threads, what it raises coming out of update(), and the checks of set_poses."""
import numpy as np
import pytest

import collide2d


def scene(rng, n):
    rows = np.hstack([rng.uniform(-10, 10, (n, 2)), rng.uniform(0.2, 1.0, (n, 2)), rng.uniform(-3, 3, (n, 1))])
    return rows


def all_pairs(ids, rows, accept=lambda a, b: True):
    """Every overlapping pair of ellipses by the array form, as sorted (a, b) id pairs."""
    i, j = np.triu_indices(len(rows), 1)
    hits = collide2d.overlaps_arrays('ellipse', rows[i], 'ellipse', rows[j])
    pairs = {tuple(sorted((int(ids[a]), int(ids[b])), key=lambda x: x & 0xffffffff)) for a, b in zip(i[hits], j[hits])}
    return {p for p in pairs if accept(*p)}


def as_set(array):
    return {(int(a), int(b)) for a, b in array}


@pytest.mark.parametrize('threads', [1, 2])
def test_a_world_driven_from_arrays_matches_all_pairs(threads):
    rng = np.random.default_rng(threads)
    rows = scene(rng, 300)
    world = collide2d.World(fat_margin=0.1, threads=threads)
    ids = np.array([world.add(collide2d.Ellipse(r[:2], r[2], r[3], r[4])) for r in rows], dtype=np.uint64)
    velocity = rng.uniform(-0.3, 0.3, (len(rows), 2))
    before = set()
    for frame in range(20):
        rows[:, :2] += velocity
        rows[:, 4] += 0.05
        world.set_poses(ids, rows[:, :2], rows[:, 4])
        world.update()
        now = as_set(world.overlapping())
        assert now == all_pairs(ids, rows), f'frame {frame}'
        assert as_set(world.began()) == now - before and as_set(world.ended()) == before - now
        before = now
    assert len(before) > 10


def test_a_python_pair_predicate_filters_on_several_threads():
    rng = np.random.default_rng(5)
    rows = scene(rng, 300)
    world = collide2d.World(threads=2)
    ids = [world.add(collide2d.Ellipse(r[:2], r[2], r[3], r[4]), user_id=k) for k, r in enumerate(rows)]
    even = lambda a, b: (a & 0xffffffff) % 2 == 0 and (b & 0xffffffff) % 2 == 0
    world.set_pair_predicate(even)
    world.update()
    expected = all_pairs(np.array(ids, dtype=np.uint64), rows, even)
    assert as_set(world.overlapping()) == expected and len(expected) > 0
    world.set_pair_predicate(None)
    world.update()
    assert as_set(world.overlapping()) == all_pairs(np.array(ids, dtype=np.uint64), rows)


def test_what_the_predicate_raises_comes_out_of_update():
    world = collide2d.World(threads=2)
    a = world.add(collide2d.Circle((0, 0), 1))
    world.add(collide2d.Circle((1, 0), 1))
    world.set_pair_predicate(lambda x, y: 1 / 0)
    with pytest.raises(ZeroDivisionError):
        world.update()
    world.set_pair_predicate(lambda x, y: True)
    world.update()
    assert world.overlapping().shape == (1, 2) and int(world.overlapping()[0, 0]) == a


def test_contacts_proximity_and_sensors_come_as_arrays():
    world = collide2d.World(proximity_margin=1.0, contacts=True)
    a = world.add(collide2d.Rect((0, 0), (1, 1)))
    b = world.add(collide2d.Ellipse((0, 1.75), 2, 1))
    c = world.add(collide2d.Circle((2.5, 0), 1))
    s = world.add(collide2d.Circle((0, 0), 0.5), static=True, sensor=True)
    world.update()
    contacts = world.contacts()
    assert as_set(contacts['pairs']) == {(a, b)}
    assert contacts['separation'].tolist() == [[-0.25]] and contacts['normal'][0].tolist() == [0.0, 1.0]
    near = world.proximity()
    shapes = {a: collide2d.Rect((0, 0), (1, 1)), b: collide2d.Ellipse((0, 1.75), 2, 1), c: collide2d.Circle((2.5, 0), 1)}
    apart = {(x, y): collide2d.distance(shapes[x], shapes[y]).distance for x, y in [(a, b), (a, c), (b, c)]}
    assert as_set(near['pairs']) == {p for p, d in apart.items() if 0 < d < 1.0}
    assert near['distance'][:, 0].tolist() == [apart[p] for p in map(tuple, near['pairs'].tolist())]
    assert apart[(a, c)] == 0.5
    assert as_set(world.sensing()) == {(s, a)}
    assert set(world.query(collide2d.Circle((3.2, 0), 0.1)).tolist()) == {c}
    assert world.pose(b) == ((0.0, 1.75), 0.0) and len(world) == 4


def test_contacts_to_a_tolerance_are_the_kernel_s():
    shapes = [collide2d.Ellipse((0, 0), 2, 0.5, 0.3), collide2d.Ellipse((1.5, 0.8), 1.5, 0.4, -0.7)]
    world = collide2d.World(contacts=True, contact_tolerance=1e-3)
    for shape in shapes:
        world.add(shape)
    world.update()
    expected = collide2d.contact(shapes[0], shapes[1], tolerance=1e-3)
    assert world.contacts()['separation'].tolist() == [[expected.separation]]
    assert world.contacts()['normal'][0].tolist() == list(expected.normal)
    with pytest.raises(ValueError, match="contact tolerance must not be negative"):
        collide2d.World(contacts=True, contact_tolerance=-1.0)


def test_contacts_of_a_body_against_a_scan():
    """contacts_of(body) gives the rows of contacts() that name the body, the other bodies, and the
    normals turned away from the body: each the normal of the contact query with its shape first."""
    rng = np.random.default_rng(5)
    world = collide2d.World(contacts=True)
    shapes = {}
    for x, y, r in zip(rng.uniform(0, 8, 60), rng.uniform(0, 8, 60), rng.uniform(0.3, 1.0, 60)):
        shape = collide2d.Circle((float(x), float(y)), float(r))
        shapes[world.add(shape)] = shape
    world.update()
    pairs = world.contacts()['pairs']
    assert len(pairs) > 20
    for body, shape in shapes.items():
        mine = world.contacts_of(body)
        rows = [k for k, (a, b) in enumerate(pairs.tolist()) if body in (a, b)]
        assert mine['index'].tolist() == rows
        others = [b if a == body else a for a, b in pairs[rows].tolist()]
        assert mine['other'].tolist() == others
        for other, normal in zip(others, mine['normal'].tolist()):
            assert normal == list(collide2d.contact(shape, shapes[other]).normal)


def test_overlap_areas_come_with_contacts_and_sensor_visits():
    """A 2 x 2 box centred on the line y = 0, the top of a water sensor, has half of it, 2, under the
    line, centred 0.5 below its centre; where it overlaps a circle, its contact's area is
    overlap_area's."""
    world = collide2d.World(contacts=True, overlap_areas=True)
    water = world.add(collide2d.Rect((0, -5), (50, 5)), static=True, sensor=True)
    box = world.add(collide2d.Rect((3, 0), (1, 1)))
    ball = world.add(collide2d.Circle((4.5, 0.5), 1))
    world.update()
    areas = world.sensing_areas()
    rows = {tuple(p): (a, c) for p, a, c in zip(areas['pairs'].tolist(), areas['area'][:, 0], areas['centroid'])}
    assert rows[(water, box)][0] == 2.0 and rows[(water, box)][1].tolist() == [3.0, -0.5]
    assert rows[(water, ball)][0] == pytest.approx(np.pi / 3 - np.sqrt(3) / 4, rel=1e-14)
    contacts = world.contacts()
    assert as_set(contacts['pairs']) == {(box, ball)}
    expected = collide2d.overlap_area(collide2d.Rect((3, 0), (1, 1)), collide2d.Circle((4.5, 0.5), 1))
    assert contacts['area'].tolist() == [[expected.area]]
    assert contacts['centroid'][0].tolist() == list(expected.centroid)
    assert collide2d.World(contacts=True).contacts()['area'].shape == (0, 1)


def test_a_body_of_three_shapes_enters_and_leaves_a_sensor_once():
    """Its shapes cross the sensor's edge on different frames; the body enters with its first and
    leaves with its last."""
    world = collide2d.World()
    sensor = world.add(collide2d.Rect((0, 0), (1, 5)), static=True, sensor=True)
    train = world.add([collide2d.Circle((-2, 0), 0.4), collide2d.Circle((0, 0), 0.4), collide2d.Circle((2, 0), 0.4)],
                      center=(-4.05, 0))
    entered, left, inside = [], [], []
    for frame in range(40):
        world.move_to(train, (-4.05 + 0.25 * frame, 0), 0)
        world.update()
        entered += [frame for _ in world.sensor_began()]
        left += [frame for _ in world.sensor_ended()]
        inside.append(as_set(world.sensing()))
    # The sensor spans x in [-1, 1]. The body at x = -4.05 + 0.25 f: its front circle (offset 2,
    # radius 0.4) reaches x = -1 when -1.65 + 0.25 f >= -1, first at f = 3 (the middle one at 11,
    # the rear at 19); its rear circle's left edge, -6.45 + 0.25 f, passes x = 1 first at f = 30.
    assert entered == [3] and left == [30]
    assert inside[2] == set() and inside[3:30] == [{(sensor, train)}] * 27 and inside[30] == set()


def test_set_poses_checks_its_arrays():
    """Each array's expected and given shapes are named; a bad row is named and nothing moves."""
    world = collide2d.World()
    ids = np.array([world.add(collide2d.Circle((k, 0), 0.4)) for k in range(3)], dtype=np.uint64)
    with pytest.raises(ValueError, match=r'^set_poses: centres must be an \(n, 2\) array for the n = 3 ids, '
                                         r'got shape \(3, 3\)$'):
        world.set_poses(ids, np.zeros((3, 3)), np.zeros(3))
    with pytest.raises(ValueError, match=r'^set_poses: angles must be an \(n,\) array for the n = 3 ids, '
                                         r'got shape \(2,\)$'):
        world.set_poses(ids, np.zeros((3, 2)), np.zeros(2))
    with pytest.raises(ValueError, match=r'^set_poses: ids must be an \(n,\) array, got shape \(3, 1\)$'):
        world.set_poses(ids.reshape(3, 1), np.zeros((3, 2)), np.zeros(3))
    world.remove(int(ids[1]))
    with pytest.raises(ValueError, match=r'^set_poses row 1: stale body 1'):
        world.set_poses(ids, np.full((3, 2), 7.0), np.zeros(3))
    with pytest.raises(ValueError, match=r'^set_poses row 1: .*must be finite'):
        world.set_poses(ids[[0, 2]], np.array([[5.0, 5.0], [np.nan, 0.0]]), np.zeros(2))
    assert world.pose(int(ids[0])) == ((0.0, 0.0), 0.0) and world.pose(int(ids[2])) == ((2.0, 0.0), 0.0)


def test_a_bullet_stops_at_its_first_contact_in_the_step():
    """A circle of radius 0.1 moving 10 along x from (-5, 5) meets the wall's face x = -0.5 at
    t = (-0.6 - -5) / 10, at (-0.5, 5)."""
    world = collide2d.World()
    bullet = world.add(collide2d.Circle((-5, 5), 0.1), continuous=True)
    wall = world.add(collide2d.Rect((0, 5), (0.5, 2)), static=True)
    world.update()
    world.move_to(bullet, (5, 5))
    world.update()
    hits = world.impacts()
    assert as_set(hits['pairs']) == {(bullet, wall)}
    assert abs(hits['t'][0, 0] - 0.44) < 1e-9
    assert np.abs(hits['point'][0] - [-0.5, 5]).max() < 1e-9 and np.abs(hits['normal'][0] - [1, 0]).max() < 1e-9
