"""The array forms against loops of the single calls on the same rows (equal means bit for bit: both
are the library's results, the overlaps through its batched kernels), and their checks: the kind,
the columns, the lengths, and a bad row named by its index."""
import itertools

import numpy as np
import pytest

import collide2d

KINDS = ['circle', 'ellipse', 'rect', 'capsule']


def rows(rng, kind, n):
    centres = rng.uniform(-3, 3, (n, 2))
    size = lambda lo, hi: rng.uniform(lo, hi, (n, 1))
    angle = rng.uniform(-3, 3, (n, 1))
    if kind == 'circle':
        return np.hstack([centres, size(0.1, 2)])
    if kind == 'capsule':
        return np.hstack([centres, size(0.05, 2), size(0.05, 1), angle])
    return np.hstack([centres, size(0.05, 2), size(0.05, 2), angle])


def shape(kind, r):
    if kind == 'circle':
        return collide2d.Circle(r[:2], r[2])
    if kind == 'ellipse':
        return collide2d.Ellipse(r[:2], r[2], r[3], r[4])
    if kind == 'rect':
        return collide2d.Rect(r[:2], r[2:4], r[4])
    return collide2d.Capsule(r[:2], r[2], r[3], r[4])


@pytest.mark.parametrize('a_kind, b_kind', list(itertools.product(KINDS, KINDS)))
def test_arrays_are_the_single_calls(a_kind, b_kind):
    rng = np.random.default_rng(KINDS.index(a_kind) * 4 + KINDS.index(b_kind))
    a, b = rows(rng, a_kind, 400), rows(rng, b_kind, 400)
    pairs = [(shape(a_kind, x), shape(b_kind, y)) for x, y in zip(a, b)]
    hits = collide2d.overlaps_arrays(a_kind, a, b_kind, b)
    assert hits.dtype == np.bool_ and hits.tolist() == [collide2d.overlaps(x, y) for x, y in pairs]
    assert 0 < hits.sum() < len(pairs)
    d = collide2d.distance_arrays(a_kind, a, b_kind, b)
    singles = [collide2d.distance(x, y) for x, y in pairs]
    assert d['overlapping'].tolist() == [r.overlapping for r in singles]
    assert d['distance'].tolist() == [r.distance for r in singles]
    assert [tuple(p) for p in d['point_a']] == [r.point_a for r in singles]
    assert [tuple(p) for p in d['point_b']] == [r.point_b for r in singles]
    c = collide2d.contact_arrays(a_kind, a, b_kind, b)
    singles = [collide2d.contact(x, y) for x, y in pairs]
    assert c['separation'].tolist() == [r.separation for r in singles]
    assert [tuple(p) for p in c['normal']] == [r.normal for r in singles]
    assert [tuple(p) for p in c['point_a']] == [r.point_a for r in singles]
    assert [tuple(p) for p in c['point_b']] == [r.point_b for r in singles]


def test_a_bad_row_is_named_by_its_index():
    a = rows(np.random.default_rng(1), 'ellipse', 10)
    a[7, 3] = -1.0
    b = rows(np.random.default_rng(2), 'circle', 10)
    with pytest.raises(ValueError, match=r'^a\[7\]: ellipse b must be positive \(got -1\)$'):
        collide2d.overlaps_arrays('ellipse', a, 'circle', b)
    good = b.copy()
    b[4, 0] = np.nan
    with pytest.raises(ValueError, match=r'^b\[4\]: circle cx must be finite \(got nan\)$'):
        collide2d.contact_arrays('circle', good, 'circle', b)


def test_shapes_and_lengths_are_checked():
    rng = np.random.default_rng(3)
    with pytest.raises(ValueError, match=r'^a: ellipse rows need an \(n, 5\) array \(cx cy a b theta\)$'):
        collide2d.overlaps_arrays('ellipse', rows(rng, 'circle', 4), 'circle', rows(rng, 'circle', 4))
    with pytest.raises(ValueError, match=r'^a has 4 rows and b 5: pairs need as many of each$'):
        collide2d.distance_arrays('rect', rows(rng, 'rect', 4), 'circle', rows(rng, 'circle', 5))
    with pytest.raises(ValueError, match=r"^unknown shape kind 'square' \(circle, ellipse, rect or capsule\)$"):
        collide2d.overlaps_arrays('square', rows(rng, 'rect', 4), 'circle', rows(rng, 'circle', 4))
    assert collide2d.overlaps_arrays('circle', np.zeros((0, 3)), 'rect', np.zeros((0, 5))).shape == (0,)
