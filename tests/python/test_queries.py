"""The Python module's shapes and pair queries against the C++ library through another path: the
`collide2d query` command (COLLIDE2D_CLI) on the same numbers, whose %.17g output reads back to the
same doubles, so that equal means bit for bit. Also its refusals, which must say what the command's
error lines say, and ray casts on constructions whose answers are exact."""
import math
import os
import random
import subprocess

import pytest

import collide2d

CLI = os.environ.get('COLLIDE2D_CLI', 'collide2d')


def words(x):
    return repr(float(x))


def random_shape(rng, kind, center):
    """A shape of `kind` about `center`, as the module's value and as the command's words."""
    cx, cy = center
    angle = rng.uniform(-3, 3)
    if kind == 'circle':
        r = rng.uniform(0.1, 2)
        return collide2d.Circle((cx, cy), r), f'circle {words(cx)} {words(cy)} {words(r)}'
    if kind == 'ellipse':
        a, b = rng.uniform(0.1, 2), rng.uniform(0.05, 2)
        return (collide2d.Ellipse((cx, cy), a, b, angle),
                f'ellipse {words(cx)} {words(cy)} {words(a)} {words(b)} {words(angle)}')
    if kind == 'rect':
        hx, hy = rng.uniform(0.05, 2), rng.uniform(0.05, 2)
        return (collide2d.Rect((cx, cy), (hx, hy), angle),
                f'rect {words(cx)} {words(cy)} {words(hx)} {words(hy)} {words(angle)}')
    if kind == 'capsule':
        h, r = rng.uniform(0.05, 2), rng.uniform(0.05, 1)
        return (collide2d.Capsule((cx, cy), h, r, angle),
                f'capsule {words(cx)} {words(cy)} {words(h)} {words(r)} {words(angle)}')
    if kind == 'polygon':
        n = rng.randint(3, 8)
        size, radius = rng.uniform(0.2, 2), rng.choice([0.0, rng.uniform(0.01, 0.3)])
        vertices = [(size * math.cos(2 * math.pi * (k + rng.uniform(-0.2, 0.2)) / n),
                     size * math.sin(2 * math.pi * (k + rng.uniform(-0.2, 0.2)) / n)) for k in range(n)]
        line = f'polygon {words(cx)} {words(cy)} {words(angle)} {words(radius)} ' + \
            ' '.join(f'{words(x)} {words(y)}' for x, y in vertices)
        return collide2d.ConvexPolygon(vertices, radius, (cx, cy), angle), line
    half = rng.uniform(0.1, 2)
    p = (cx - half * math.cos(angle), cy - half * math.sin(angle))
    q = (cx + half * math.cos(angle), cy + half * math.sin(angle))
    return collide2d.Segment(p, q), f'segment {words(p[0])} {words(p[1])} {words(q[0])} {words(q[1])}'


def command(lines, *mode):
    out = subprocess.run([CLI, 'query', *mode], input='\n'.join(lines) + '\n', capture_output=True, text=True)
    return [line.split() for line in out.stdout.splitlines()]


KINDS = ['circle', 'ellipse', 'rect', 'capsule', 'polygon', 'segment']
FLAT = ['circle', 'ellipse', 'rect', 'capsule', 'polygon']  # a segment is not a moving shape's B here


def pairs(seed, count=300):
    """Random pairs of every kind, near enough that a third overlap."""
    rng = random.Random(seed)
    out = []
    for _ in range(count):
        ka, kb = rng.choice(KINDS), rng.choice(FLAT)
        a, la = random_shape(rng, ka, (rng.uniform(-1, 1), rng.uniform(-1, 1)))
        b, lb = random_shape(rng, kb, (rng.uniform(-3, 3), rng.uniform(-3, 3)))
        out.append((a, b, f'{la} ; {lb}'))
    return out


def test_overlap_and_distance_are_the_commands():
    cases = pairs(1)
    for (a, b, line), row in zip(cases, command([c[2] for c in cases])):
        d = collide2d.distance(a, b)
        expected = [float(x) for x in row]
        assert (collide2d.overlaps(a, b), d.overlapping) == (expected[0] == 1, expected[0] == 1), line
        assert [d.distance, *d.point_a, *d.point_b] == expected[1:], line
    assert sum(collide2d.overlaps(a, b) for a, b, _ in cases) > 50


def test_contact_is_the_commands():
    cases = pairs(2)
    for (a, b, line), row in zip(cases, command([c[2] for c in cases], '--contact')):
        c = collide2d.contact(a, b)
        assert [c.separation, *c.normal, *c.point_a, *c.point_b] == [float(x) for x in row], line
        assert c.manifold[0].point_a == c.point_a and c.manifold[0].separation == c.separation, line


def test_time_of_impact_is_the_commands():
    rng = random.Random(3)
    cases = []
    for a, b, line in pairs(4, 200):
        v, w = (rng.uniform(-4, 4), rng.uniform(-4, 4)), rng.uniform(-1, 1)
        cases.append((a, b, v, w, f'{line} @ {words(v[0])} {words(v[1])} {words(w)}'))
    rows = command([c[4] for c in cases], '--toi')
    for (a, b, v, w, line), row in zip(cases, rows):
        r = collide2d.time_of_impact(a, b, b_velocity=v, b_turn=w)
        expected = [float(x) for x in row]
        assert (r.status != 'miss') == (expected[0] == 1), line
        assert [r.t, *r.normal, *r.point] == expected[1:], line
    assert {'hit', 'miss', 'overlapping'} <= {collide2d.time_of_impact(a, b, b_velocity=v, b_turn=w).status
                                              for a, b, v, w, _ in cases}


@pytest.mark.parametrize('make, line', [
    (lambda: collide2d.Circle((0, 0), -1), 'circle 0 0 -1'),
    (lambda: collide2d.Circle((math.nan, 0), 1), 'circle nan 0 1'),
    (lambda: collide2d.Ellipse((0, 0), 1, 0), 'ellipse 0 0 1 0 0'),
    (lambda: collide2d.Rect((0, 0), (1, math.inf)), 'rect 0 0 1 inf 0'),
    (lambda: collide2d.Capsule((0, 0), 0, 1), 'capsule 0 0 0 1 0'),
    (lambda: collide2d.ConvexPolygon([(0, 0), (1, 0), (2, 0)]), 'polygon 0 0 0 0 0 0 1 0 2 0'),
    (lambda: collide2d.ConvexPolygon([(0, 0), (0, 1), (1, 0)]), 'polygon 0 0 0 0 0 0 0 1 1 0'),
    (lambda: collide2d.Segment((1, 1), (1, 1)), 'segment 1 1 1 1'),
])
def test_a_bad_shape_raises_what_the_command_says(make, line):
    said = command([f'{line} ; circle 0 0 1'])[0]
    assert said[0] == 'error:'
    with pytest.raises(ValueError) as refused:
        make()
    assert str(refused.value) == ' '.join(said[1:])


def test_boundary_distance_of_a_rectangle_is_refused():
    with pytest.raises(collide2d.UnsupportedPair):
        collide2d.boundary_distance(collide2d.Rect((0, 0), (1, 1)), collide2d.Circle((3, 0), 1))
    assert issubclass(collide2d.UnsupportedPair, ValueError)


def test_boundary_distance_of_nested_circles_is_their_gap():
    gap = collide2d.boundary_distance(collide2d.Circle((0, 0), 4), collide2d.Circle((1, 0), 1))
    assert gap.distance == 2.0 and gap.point_a == (4.0, 0.0) and gap.point_b == (2.0, 0.0)


def test_ray_casts_on_exact_constructions():
    hit = collide2d.ray_cast(collide2d.Circle((0, 0), 1), (-5, 0), (1, 0))
    assert (hit.distance, hit.point, hit.normal) == (4.0, (-1.0, 0.0), (-1.0, 0.0))
    hit = collide2d.ray_cast(collide2d.Rect((0, 0), (2, 1)), (0, 5), (0, -2))
    assert (hit.distance, hit.point, hit.normal) == (2.0, (0.0, 1.0), (0.0, 1.0))
    assert collide2d.ray_cast(collide2d.Circle((0, 0), 1), (-5, 2), (1, 0)) is None
    assert collide2d.ray_cast(collide2d.Circle((0, 0), 1), (-5, 0), (1, 0), max_distance=3.5) is None
    inside = collide2d.ray_cast(collide2d.Ellipse((0, 0), 2, 1), (0.5, 0), (1, 0))
    assert (inside.distance, inside.normal) == (0.0, (0.0, 0.0))


def test_contact_beyond_the_limit_is_empty():
    c = collide2d.contact(collide2d.Circle((0, 0), 1), collide2d.Circle((5, 0), 1), max_separation=1.0)
    assert c.empty and c.manifold == [] and c.separation > 1.0
    c = collide2d.contact(collide2d.Circle((0, 0), 1), collide2d.Circle((3, 0), 1), max_separation=1.0)
    assert not c.empty and c.separation == 1.0 and c.normal == (1.0, 0.0)


def test_contact_to_a_tolerance():
    a, b = collide2d.Ellipse((0, 0), 2, 0.5, 0.3), collide2d.Ellipse((2.5, 1), 1.5, 0.4, -0.7)
    exact = collide2d.contact(a, b)
    loose = collide2d.contact(a, b, tolerance=1e-3)
    assert abs(loose.separation - exact.separation) <= 1e-3
    assert all(abs(p - q) <= 1e-3 for p, q in zip(loose.point_a, exact.point_a))
    assert (loose.separation <= 0) == collide2d.overlaps(a, b)
    with pytest.raises(ValueError, match="contact tolerance must be finite and not negative"):
        collide2d.contact(a, b, tolerance=-1.0)


def test_shapes_read_back_their_fields():
    e = collide2d.Ellipse((1, 2), 3, 0.5, 0.25)
    assert (e.center, e.a, e.b, e.angle) == ((1.0, 2.0), 3.0, 0.5, 0.25)
    poly = collide2d.ConvexPolygon([(-1, -1), (1, -1), (0, 1)], 0.1, (2, 3), 0.5)
    assert (poly.center, poly.angle, poly.radius, poly.vertices) == ((2.0, 3.0), 0.5, 0.1,
                                                                       [(-1.0, -1.0), (1.0, -1.0), (0.0, 1.0)])
    s = collide2d.Segment((0, 0), (3, 4))
    assert (s.point1, s.point2) == ((0.0, 0.0), (3.0, 4.0))
    assert repr(collide2d.Circle((0, 0.5), 2)) == 'Circle((0.0, 0.5), 2.0)'


def test_the_stubs_name_what_the_module_has():
    """Every public name of the module is in collide2d.pyi beside it, and every stub names something."""
    import ast
    stub = os.path.join(os.path.dirname(collide2d.__file__), 'collide2d.pyi')
    tree = ast.parse(open(stub).read())
    declared = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    public = {n for n in dir(collide2d) if not n.startswith('_')}
    assert public == declared


def test_every_function_and_world_method_says_what_it_does():
    """help() reads like the C++ docs: each public function and World method has a docstring
    beyond its signature."""
    def described(f):
        return any(line.strip() for line in (f.__doc__ or '').splitlines()[1:])
    functions = [getattr(collide2d, n) for n in dir(collide2d) if not n.startswith('_')]
    functions = [f for f in functions if callable(f) and not isinstance(f, type)]
    methods = [getattr(collide2d.World, n) for n in dir(collide2d.World) if not n.startswith('_')]
    assert len(functions) >= 9 and len(methods) >= 27
    assert [f.__name__ for f in functions + methods if not described(f)] == []
