"""The World's queries, bodies of several shapes, filters and sensor events from Python, each against
the module's single pair queries on the same shapes (a body of one shape is that very shape in the
World), and the refusals of bad queries, which leave the World as it was."""
import math
import random

import pytest

import collide2d

from test_queries import random_shape

KINDS = ['circle', 'ellipse', 'rect', 'capsule', 'polygon']


def scene(seed, n=120):
    rng = random.Random(seed)
    world = collide2d.World()
    shapes = {}
    for k in range(n):
        shape, _ = random_shape(rng, rng.choice(KINDS), (rng.uniform(-15, 15), rng.uniform(-15, 15)))
        shapes[world.add(shape, static=k % 3 == 0)] = shape
    return rng, world, shapes


@pytest.mark.parametrize('seed', range(3))
def test_shape_box_and_distance_queries_match_the_pair_queries(seed):
    rng, world, shapes = scene(seed)
    for _ in range(40):
        probe, _ = random_shape(rng, rng.choice(KINDS), (rng.uniform(-15, 15), rng.uniform(-15, 15)))
        assert set(world.query(probe).tolist()) == {i for i, s in shapes.items() if collide2d.overlaps(probe, s)}
        reach = rng.uniform(0, 2)
        near = {i for i, s in shapes.items() if collide2d.distance(probe, s).distance <= reach}
        assert set(world.within(probe, reach).tolist()) == near
        x, y = rng.uniform(-15, 15), rng.uniform(-15, 15)
        lower, upper = (x, y), (x + rng.uniform(0, 3), y + rng.uniform(0, 3))
        box = collide2d.Rect(((lower[0] + upper[0]) / 2, (lower[1] + upper[1]) / 2),
                             ((upper[0] - lower[0]) / 2, (upper[1] - lower[1]) / 2))
        assert set(world.query_box(lower, upper).tolist()) == {i for i, s in shapes.items() if collide2d.overlaps(box, s)}


def close(x, y):
    """Equal but for rounding: the World turns the ray into each shape's frame its own way."""
    return abs(x - y) <= 1e-12 * (1 + abs(y))


@pytest.mark.parametrize('seed', range(3))
def test_ray_casts_match_the_nearest_single_ray_cast(seed):
    rng, world, shapes = scene(seed)
    hits = 0
    for _ in range(60):
        origin = (rng.uniform(-20, 20), rng.uniform(-20, 20))
        angle = rng.uniform(-math.pi, math.pi)
        direction = (math.cos(angle), math.sin(angle))
        single = {i: collide2d.ray_cast(s, origin, direction, 30.0) for i, s in shapes.items()}
        single = sorted((h.distance, i) for i, h in single.items() if h is not None and h.distance > 0)
        every = world.ray_cast_all(origin, direction, 30.0)
        assert [h.body for h in every] == [i for _, i in single]
        assert all(close(h.distance, d) for h, (d, _) in zip(every, single))
        first = world.ray_cast(origin, direction, 30.0)
        assert (first is None) == (not single)
        if first is not None:
            hits += 1
            assert first.body == single[0][1] and close(first.distance, single[0][0])
            assert all(map(close, first.point, (o + first.distance * d for o, d in zip(origin, direction))))
    assert hits > 10


def test_a_cast_stops_where_the_time_of_impact_does():
    rng, world, shapes = scene(7)
    met = 0
    for _ in range(40):
        probe, _ = random_shape(rng, rng.choice(['circle', 'ellipse', 'rect', 'capsule']),
                                (rng.uniform(-20, 20), rng.uniform(-20, 20)))
        if world.query(probe).size:
            continue
        move = (rng.uniform(-20, 20), rng.uniform(-20, 20))
        first = {i: collide2d.time_of_impact(probe, s, a_velocity=move) for i, s in shapes.items()}
        first = {i: r.t for i, r in first.items() if r.status == 'hit'}
        hit = world.cast(probe, move)
        assert (hit is None) == (not first)
        if hit is not None:
            met += 1
            assert abs(hit.fraction - min(first.values())) < 1e-6
            assert abs(first[hit.body] - min(first.values())) < 1e-6
    assert met > 5


def placed(shape_at_origin, center, angle):
    """A circle or rectangle placed in a body's frame: turned by angle and moved to center."""
    (ox, oy), c, s = shape_at_origin.center, math.cos(angle), math.sin(angle)
    at = (center[0] + c * ox - s * oy, center[1] + s * ox + c * oy)
    if isinstance(shape_at_origin, collide2d.Circle):
        return collide2d.Circle(at, shape_at_origin.radius)
    return collide2d.Rect(at, shape_at_origin.half_extents, shape_at_origin.angle + angle)


def test_a_body_of_several_shapes_pairs_when_any_of_its_shapes_does():
    """A dumbbell (two discs and a bar) at random poses against single discs: a pair of bodies
    overlaps exactly when some part of the dumbbell overlaps the disc."""
    rng = random.Random(11)
    parts = [collide2d.Circle((-2, 0), 0.6), collide2d.Circle((2, 0), 0.6), collide2d.Rect((0, 0), (2, 0.15))]
    world = collide2d.World()
    pose = ((0.3, -0.2), 0.7)
    dumbbell = world.add(parts, center=pose[0], angle=pose[1], user_id=99)
    discs = {world.add(d): d for d in (collide2d.Circle((rng.uniform(-4, 4), rng.uniform(-4, 4)), rng.uniform(0.1, 0.5))
                                       for _ in range(200))}
    world.update()
    expected = {(dumbbell, i) for i, d in discs.items()
                if any(collide2d.overlaps(placed(p, *pose), d) for p in parts)}
    expected |= {tuple(sorted((i, j))) for i in discs for j in discs if i < j and collide2d.overlaps(discs[i], discs[j])}
    assert {tuple(map(int, p)) for p in world.overlapping()} == expected
    assert 10 < len([p for p in expected if dumbbell in p]) < 200
    assert world.pose(dumbbell) == pose and world.user_id(dumbbell) == 99


def test_filters_set_later_take_effect_at_the_next_update():
    world = collide2d.World()
    a = world.add(collide2d.Circle((0, 0), 1), category=2)
    b = world.add(collide2d.Circle((1, 0), 1), mask=~2 & 0xffffffffffffffff)
    c = world.add(collide2d.Circle((-1, 0), 1))
    world.update()
    assert {tuple(map(int, p)) for p in world.overlapping()} == {(a, c), (b, c)}
    assert world.query(collide2d.Circle((0, 0), 0.1), category=2).tolist() == [a, c]
    world.set_filter(b)
    world.set_filter(c, group=-1)
    world.set_filter(a, category=2, group=-1)
    world.update()
    assert {tuple(map(int, p)) for p in world.overlapping()} == {(a, b), (b, c)}
    assert {tuple(map(int, p)) for p in world.began()} == {(a, b)} and \
        {tuple(map(int, p)) for p in world.ended()} == {(a, c)}
    assert world.query(collide2d.Circle((0, 0), 0.1), mask=2).tolist() == [a]


def test_sensor_events_and_static_bodies():
    world = collide2d.World()
    gate = world.add(collide2d.Rect((0, 0), (1, 1)), static=True, sensor=True)
    walker = world.add(collide2d.Circle((-3, 0), 0.5))
    wall = world.add(collide2d.Rect((5, 0), (0.2, 3)), static=True)
    seen = []
    for x in [-3, -1.4, 0, 1.6, 4.5]:
        world.move_to(walker, (x, 0))
        world.update()
        seen.append((world.sensor_began().tolist(), world.sensor_ended().tolist(), world.overlapping().tolist()))
    assert seen == [([], [], []), ([[gate, walker]], [], []), ([], [], []), ([], [[gate, walker]], []),
                    ([], [], [[walker, wall]])]
    world.set_static(walker)
    world.update()
    assert world.overlapping().size == 0 and world.ended().tolist() == [[walker, wall]]
    stats = world.last_frame()
    assert stats['overlapping'] == 0 and stats['candidates'] >= 0


def test_bad_queries_raise_and_leave_the_world_as_it_was():
    world = collide2d.World()
    a = world.add(collide2d.Circle((0, 0), 1))
    world.add(collide2d.Circle((1, 0), 1))
    world.update()
    refusals = {
        r'^box min x must be finite \(got nan\)$': lambda: world.query_box((math.nan, 0), (1, 1)),
        r'^box min x must not exceed box max x': lambda: world.query_box((1, 0), (0, 1)),
        r'^ray direction must not be zero$': lambda: world.ray_cast((0, 0), (0, 0)),
        r'^distance must not be negative$': lambda: world.within((0, 0), -1.0),
        r'^cast translation x must be finite \(got inf\)$': lambda: world.cast(collide2d.Circle((0, 0), 1), (math.inf, 0)),
        r'^add needs at least one shape for the body$': lambda: world.add([]),
        r'^a pose is for a list of shapes': lambda: world.add(collide2d.Circle((0, 0), 1), center=(1, 1)),
        r'must be static$': lambda: world.add([collide2d.Segment((0, 0), (1, 0))]),
    }
    for message, call in refusals.items():
        with pytest.raises(ValueError, match=message):
            call()
    with pytest.raises(IndexError, match='unknown body'):
        world.set_static(a + 5)
    assert len(world) == 2 and world.overlapping().tolist() == [[a, a + 1]]
    world.update()
    assert world.overlapping().tolist() == [[a, a + 1]]
