import numpy as np

from taut.geometry._intersections import (
    circles_overlap,
    point_in_polygon,
    segment_circle_distance,
    segment_enters_polygon,
    segment_meets_circle,
    segments_intersect,
)


def test_segments_intersect_appendix_a1_cases():
    assert segments_intersect([0, 0], [2, 2], [0, 2], [2, 0])  # crossing
    assert not segments_intersect([0, 0], [1, 1], [0, 2], [0.9, 1.1])  # lines cross beyond the ends
    assert not segments_intersect([0, 0], [1, 0], [0, 1], [1, 1])  # parallel
    assert segments_intersect([0, 0], [2, 0], [1, 0], [3, 0])  # collinear overlap
    assert not segments_intersect([0, 0], [1, 0], [2, 0], [3, 0])  # collinear, apart
    assert segments_intersect([0, 0], [1, 0], [1, 0], [1, 1])  # touching end points
    assert not segments_intersect([0, 0], [1, 0], [1, 0], [1, 1], tol=1e-9)  # ... is not a proper crossing
    # vectorised
    out = segments_intersect(np.array([[0, 0], [0, 0]]), np.array([[2, 2], [1, 0]]), np.array([0, 2]), np.array([2, 0]))
    assert out.tolist() == [True, False]


def test_segment_circle_is_strict_at_tangency():
    assert segment_circle_distance([-1, 1], [1, 1], [0, 0]) == 1.0
    assert not segment_meets_circle([-1, 1], [1, 1], [0, 0], 1.0)  # tangent: touches, does not meet
    assert segment_meets_circle([-1, 0.9], [1, 0.9], [0, 0], 1.0)
    assert not segment_meets_circle([2, 0], [3, 0], [0, 0], 1.0)  # closest point is an end point (A.2)
    assert not segment_meets_circle([-1, 0], [1, 0], [0, 0], 0.0)  # a point object is never met


def test_polygon_and_circles():
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    assert point_in_polygon([0.5, 0.5], sq) and not point_in_polygon([1.5, 0.5], sq)
    assert segment_enters_polygon([-1, 0.5], [2, 0.5], sq)
    assert segment_enters_polygon([0.2, 0.2], [0.8, 0.8], sq)  # wholly inside: no edge crossed
    assert not segment_enters_polygon([-1, 0.5], [0, 0.5], sq)  # ending on an edge
    assert not segment_enters_polygon([1, 1], [2, 3], sq)  # from a vertex outwards
    assert not segment_enters_polygon([0, 0], [1, 0], sq) and not segment_enters_polygon(
        [0.2, 1], [0.8, 1], sq
    )  # along an edge
    assert circles_overlap([0, 0], 1, [1.5, 0], 1) and not circles_overlap([0, 0], 1, [2, 0], 1)
    assert circles_overlap([0, 0], 0, [0, 0], 0)
