# The overlap area, centroid and IoU from Python: on constructions whose answer is known exactly.
import math

import pytest

import collide2d


def test_lens_of_two_unit_circles():
    lens = collide2d.overlap_area(collide2d.Circle((0, 0), 1), collide2d.Circle((1, 0), 1))
    assert lens.area == pytest.approx(2 * math.pi / 3 - math.sqrt(3) / 2, rel=4e-16)
    assert lens.centroid == pytest.approx((0.5, 0.0), abs=4e-16)
    assert lens.crossings == 2
    assert lens.chord[0] == pytest.approx((0.5, -math.sqrt(3) / 2), abs=4e-16)
    assert lens.chord[1] == pytest.approx((0.5, math.sqrt(3) / 2), abs=4e-16)


def test_iou_of_boxes_sharing_half_their_width():
    a, b = collide2d.Rect((0, 0), (1, 1)), collide2d.Rect((1, 0), (1, 1))
    assert collide2d.iou(a, b) == pytest.approx(1 / 3, rel=4e-16)
    assert collide2d.iof(a, b) == pytest.approx(1 / 2, rel=4e-16)
    assert collide2d.overlap_area(b, a).area == collide2d.overlap_area(a, b).area


def test_iou_distance_of_boxes_apart_by_a_hair():
    # |A ^ B| = 2 * 2d and |A | B| = 2 (2 + d): the distance is 2d / (2 + d), of which 1 - IoU keeps 12 digits
    d = 2.0**-40
    a, b = collide2d.Rect((0, 0), (1, 1)), collide2d.Rect((d, 0), (1, 1))
    assert collide2d.iou_distance(a, b) == pytest.approx(2 * d / (2 + d), rel=4e-16)
    assert collide2d.iou_distance(a, a) == 0.0


def test_iou_distance_of_circles_apart_by_a_hair():
    # Unit circles with centres d apart: |A ^ B| = 2 (pi - |A & B|) = 4 asin(d/2) + d sqrt(4 - d^2), free
    # of cancellation, and |A | B| = pi + |A ^ B| / 2
    d = 2.0**-30
    a, b = collide2d.Circle((0.25, 0.5), 1), collide2d.Circle((0.25 + d, 0.5), 1)
    apart = 4 * math.asin(d / 2) + d * math.sqrt(4 - d * d)
    assert collide2d.iou_distance(a, b) == pytest.approx(apart / (math.pi + apart / 2), rel=8e-16)


def test_areas_of_the_solids():
    assert collide2d.area(collide2d.Ellipse((3, 4), 2, 0.5, 1.0)) == pytest.approx(math.pi, rel=4e-16)
    assert collide2d.area(collide2d.Capsule((0, 0), 1, 0.5)) == pytest.approx(2 + math.pi / 4, rel=4e-16)


def test_apart_and_touching_overlap_by_nothing():
    assert collide2d.overlap_area(collide2d.Circle((0, 0), 1), collide2d.Circle((2, 0), 1)).area == 0.0
    assert collide2d.iou(collide2d.Rect((0, 0), (1, 1)), collide2d.Rect((2, 0), (1, 1))) == 0.0


def test_a_segment_has_no_area():
    with pytest.raises(ValueError, match='segment'):
        collide2d.overlap_area(collide2d.Segment((0, 0), (1, 0)), collide2d.Circle((0, 0), 1))
