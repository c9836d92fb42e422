"""Movers from Python: a capsule walking a floor and a chain at the commanded speed, standing on a
slope, riding a platform, the World's mover queries against the pair queries, the planes' solver
on exact constructions, and the refusals."""
import math

import pytest

import collide2d

DT = 1 / 60
SKIN = 0.01


def player(x, y):
    return collide2d.Capsule(center=(x, y), half_length=0.25, radius=0.25, angle=math.pi / 2)


def walk(world, shape, frames, speed, **options):
    velocity, ground = (0.0, 0.0), collide2d.Ground()
    for _ in range(frames):
        velocity = (speed, velocity[1] - 20 * DT)
        r = world.move(shape, velocity, DT, ground, **options)
        shape = player(*r.position)
        velocity, ground = r.velocity, r.ground
        yield shape, r


def test_walks_a_floor_and_a_chain_at_the_commanded_speed():
    world = collide2d.World()
    floor = world.add(collide2d.Rect(center=(0, -0.5), half_extents=(50, 0.5)), static=True, user_id=7)
    world.add_chain([(60, 5), (40, 5), (20, 5), (0, 5)])
    for y, body in ((0.5 + SKIN, floor), (5.5 + SKIN, None)):
        x = -10.0 if body else 25.0
        for k, (shape, r) in enumerate(walk(world, player(x, y), 120, 3.0)):
            assert r.position[0] == pytest.approx(x + 3.0 * DT * (k + 1), abs=1e-12)
            assert r.position[1] == pytest.approx(y, abs=1e-12)
            assert r.ground.on_ground and not r.blocked
            if body:
                assert r.ground.body == body and r.ground.user_id == 7


def test_stands_on_a_slope_and_rides_a_platform():
    world = collide2d.World()
    world.add(collide2d.ConvexPolygon(vertices=[(-10, -6), (10, -6), (10, 5.77350269189626), (-10, -5.77350269189626)]),
              static=True)
    shapes = list(walk(world, player(0, 2), 200, 0.0))
    rest = shapes[-1][1].position
    for shape, r in walk(world, player(*rest), 100, 0.0):
        assert r.position == pytest.approx(rest, abs=1e-12)
    platform = world.add(collide2d.Rect(center=(30, 0), half_extents=(2, 0.25)))
    world.update()
    shape, ground = player(30, 0.25 + 0.5 + SKIN), collide2d.Ground()
    for k in range(60):
        world.move_to(platform, (30 + 0.05 * (k + 1), 0))
        world.update()
        r = world.move(shape, (0, 0), DT, ground)
        shape, ground = player(*r.position), r.ground
        assert world.displacement(platform, r.position) == pytest.approx((0.05, 0), abs=1e-12)
        # It stands on the platform from the first move on, and moves with it from the second.
        assert r.position[0] == pytest.approx(30 + 0.05 * k, abs=1e-12)


def test_mover_queries_match_the_pair_queries():
    world = collide2d.World()
    rock = collide2d.Ellipse(center=(0, 0), a=2, b=1, angle=0.3)
    body = world.add(rock, static=True)
    mover = collide2d.Circle(center=(0, 3), radius=0.5)
    f = world.cast_mover(mover, (0, -4), skin=SKIN)
    assert 0 < f < 1
    moved = collide2d.Circle(center=(0, 3 - 4 * f), radius=0.5)
    assert collide2d.contact(rock, moved).separation == pytest.approx(SKIN, abs=1e-9)
    planes = world.collide_mover(moved, skin=2 * SKIN)
    assert [p.body for p in planes] == [body]
    c = collide2d.contact(rock, moved)
    assert planes[0].separation == c.separation and planes[0].normal == tuple(c.normal)
    assert world.collide_mover(moved, skin=2 * SKIN, own_body=body) == []


def test_planes_on_a_floor_and_a_wall():
    floor = collide2d.CollisionPlane((0, 1))
    wall = collide2d.CollisionPlane((-1, 0))
    assert collide2d.solve_planes((0.375, -0.25), [floor, wall]) == (0, 0)
    assert floor.push == 0.25 and wall.push == 0.375
    assert collide2d.clip_vector((2.0, -1.0), [floor, wall]) == (0, 0)
    assert collide2d.solve_planes((-0.5, 0.5), [floor, wall]) == (-0.5, 0.5)


def test_refusals_leave_the_world_as_it_was():
    world = collide2d.World()
    world.add(collide2d.Rect(center=(0, -0.5), half_extents=(5, 0.5)), static=True)
    with pytest.raises(ValueError, match='mover skin'):
        world.cast_mover(player(0, 1), (1, 0), skin=-1)
    with pytest.raises(ValueError, match='move dt'):
        world.move(player(0, 1), (1, 0), -1.0)
    with pytest.raises(ValueError, match='max slope'):
        world.move(player(0, 1), (1, 0), DT, max_slope=2.0)
    with pytest.raises(ValueError, match='normal must be of unit length'):
        collide2d.solve_planes((0, 0), [collide2d.CollisionPlane((0, 2))])
    with pytest.raises(ValueError, match='at least 4 points'):
        world.add_chain([(0, 0), (1, 0)])
    assert len(world) == 1
