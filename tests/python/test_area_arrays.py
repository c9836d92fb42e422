"""The area queries on arrays against the single calls (equal means bit for bit), the detector row
formats against the rectangles they stand for, iou_matrix against every pair measured, and nms
against a greedy pass in pure Python over collide2d.iou."""
import itertools
import math

import numpy as np
import pytest

import collide2d
from test_arrays import KINDS, rows, shape


@pytest.mark.parametrize('a_kind, b_kind', list(itertools.product(KINDS, KINDS)))
def test_area_arrays_are_the_single_calls(a_kind, b_kind):
    rng = np.random.default_rng(10 + KINDS.index(a_kind) * 4 + KINDS.index(b_kind))
    a, b = rows(rng, a_kind, 200), rows(rng, b_kind, 200)
    pairs = [(shape(a_kind, x), shape(b_kind, y)) for x, y in zip(a, b)]
    got = collide2d.overlap_area_arrays(a_kind, a, b_kind, b)
    singles = [collide2d.overlap_area(x, y) for x, y in pairs]
    assert got['area'].tolist() == [r.area for r in singles]
    assert [tuple(c) for c in got['centroid']] == [r.centroid for r in singles]
    assert got['crossings'].tolist() == [r.crossings for r in singles]
    assert 0 < np.count_nonzero(got['area']) < len(pairs)
    for mode, single in (('iou', collide2d.iou), ('iof', collide2d.iof), ('distance', collide2d.iou_distance)):
        values = collide2d.iou_arrays(a_kind, a, b_kind, b, mode=mode)
        assert values.tolist() == [single(x, y) for x, y in pairs], mode


def test_float32_rows_are_their_float64_values():
    rng = np.random.default_rng(20)
    a, b = rows(rng, 'rect', 100).astype(np.float32), rows(rng, 'ellipse', 100).astype(np.float32)
    want = collide2d.iou_arrays('rect', a.astype(np.float64), 'ellipse', b.astype(np.float64))
    assert collide2d.iou_arrays('rect', a, 'ellipse', b).tolist() == want.tolist()


def test_detector_rows_are_the_boxes_they_stand_for():
    rng = np.random.default_rng(21)
    boxes = np.hstack([rng.uniform(0, 50, (100, 2)), rng.uniform(1, 20, (100, 2)), rng.uniform(-180, 180, (100, 1))])
    others = boxes + rng.normal(0, 2, boxes.shape) * [1, 1, 0.1, 0.1, 3]
    rect = lambda r, to_radians: collide2d.Rect(r[:2], r[2:4] / 2, r[4] * to_radians)
    for fmt, to_radians in (('detectron2', math.pi / 180), ('mmcv', 1.0)):
        got = collide2d.iou_arrays('rect', boxes, 'rect', others, box_format=fmt)
        assert got.tolist() == [collide2d.iou(rect(x, to_radians), rect(y, to_radians)) for x, y in zip(boxes, others)]
        assert np.count_nonzero(got) > 90


def test_iou_matrix_holds_every_overlapping_pair():
    rng = np.random.default_rng(22)
    a, b = rows(rng, 'rect', 120) * [5, 5, 1, 1, 1], rows(rng, 'ellipse', 90) * [5, 5, 1, 1, 1]
    every = [(i, j, collide2d.iou(shape('rect', x), shape('ellipse', y)))
             for (i, x), (j, y) in itertools.product(enumerate(a), enumerate(b))]
    found = []
    for min_iou in (0.0, 0.25):
        m = collide2d.iou_matrix('rect', a, 'ellipse', b, min_iou)
        want = [(i, j, v) for i, j, v in every if v > 0 and v >= min_iou]
        assert list(zip(m['i'].tolist(), m['j'].tolist(), m['iou'].tolist())) == want
        found.append(len(want))
    assert found[0] > found[1] > 5


def greedy_nms(boxes, scores, threshold, labels=None):
    """Suppression as detectron2 and torchvision define it, written out over collide2d.iou."""
    order = sorted(range(len(boxes)), key=lambda i: (-scores[i], i))
    kept = []
    for i in order:
        if all(labels is not None and labels[k] != labels[i] or collide2d.iou(boxes[k], boxes[i]) <= threshold
               for k in kept):
            kept.append(i)
    return kept


def test_nms_is_the_greedy_pass():
    rng = np.random.default_rng(23)
    rows_ = np.hstack([rng.uniform(0, 30, (300, 2)), rng.uniform(1, 6, (300, 2)), rng.uniform(-90, 90, (300, 1))])
    scores = rng.integers(0, 10, 300) / 10  # few values: many ties
    labels = rng.integers(0, 3, 300)
    boxes = [collide2d.Rect(r[:2], r[2:4] / 2, r[4] * math.pi / 180) for r in rows_]
    for threshold in (0.0, 0.3, 0.7):
        kept = collide2d.nms(rows_, scores, threshold, box_format='detectron2')
        assert kept.tolist() == greedy_nms(boxes, scores, threshold)
        assert len(kept) < len(boxes)
        by_label = collide2d.nms(rows_, scores, threshold, labels, box_format='detectron2')
        assert by_label.tolist() == greedy_nms(boxes, scores, threshold, labels)


def test_refusals_name_the_problem():
    a = rows(np.random.default_rng(24), 'rect', 5)
    with pytest.raises(ValueError, match='mode'):
        collide2d.iou_arrays('rect', a, 'rect', a, mode='giou')
    with pytest.raises(ValueError, match='box_format'):
        collide2d.iou_arrays('ellipse', a, 'rect', a, box_format='detectron2')
    with pytest.raises(ValueError, match='min_iou'):
        collide2d.iou_matrix('rect', a, 'rect', a, 2.0)
    with pytest.raises(ValueError, match='score'):
        collide2d.nms(a, np.ones(4), 0.5)
    bad = a.copy()
    bad[3, 2] = -1.0
    with pytest.raises(ValueError, match=r'a\[3\]'):
        collide2d.overlap_area_arrays('rect', bad, 'rect', a)
