import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.geometry._tangents import circle_circle_tangents, directed_tangent, point_circle_tangents, wrap_direction

coord = st.floats(-5, 5)
rad = st.floats(0, 1)


def _cross(p, q):
    return p[..., 0] * q[..., 1] - p[..., 1] * q[..., 0]


@settings(max_examples=200, deadline=None)
@given(coord, coord, rad, coord, coord, rad, st.sampled_from([1, -1]), st.sampled_from([1, -1]))
def test_directed_tangent_touches_both_circles_with_its_wrap_directions(x1, y1, r1, x2, y2, r2, d1, d2):
    c1, c2 = np.array([x1, y1]), np.array([x2, y2])
    a, b, u, L, ok = directed_tangent(c1, r1, d1, c2, r2, d2)
    dist = np.linalg.norm(c2 - c1)
    if dist < abs(d2 * r2 - d1 * r1) - 1e-9 or dist == 0:
        assert not ok
        return
    if not ok:  # tangency within round-off only
        assert dist == pytest.approx(abs(d2 * r2 - d1 * r1), abs=1e-9)
        return
    assert np.linalg.norm(a - c1) == pytest.approx(r1, abs=1e-9)
    assert np.linalg.norm(b - c2) == pytest.approx(r2, abs=1e-9)
    assert np.dot(a - c1, u) == pytest.approx(0, abs=1e-9)  # perpendicular radius: tangent
    assert np.dot(b - c2, u) == pytest.approx(0, abs=1e-9)
    assert np.allclose(b - a, L * u, atol=1e-9)
    # the centre lies on the left of the travel direction for ccw (+1), right for cw (-1)
    if r1 > 1e-6:
        assert np.sign(_cross(u, c1 - a)) == d1
    if r2 > 1e-6:
        assert np.sign(_cross(u, c2 - b)) == d2


def test_point_circle_tangents_match_appendix_a3():
    a, c, r = np.array([0.3, -0.2]), np.array([2.0, 1.0]), 0.5
    b, dirs = point_circle_tangents(a, c, r)
    alpha = np.arctan2(*(c - a)[::-1])
    beta = np.arcsin(r / np.linalg.norm(c - a)) + np.pi / 2
    expected = {
        tuple(np.round(c + r * np.array([np.cos(alpha + s * beta), np.sin(alpha + s * beta)]), 12)) for s in (1, -1)
    }
    assert {tuple(np.round(p, 12)) for p in b} == expected
    for p, d in zip(b, dirs):  # A.3: dir = sign((b - c) x (b - a))
        assert np.sign(_cross(p - c, p - a)) == d


def test_circle_circle_tangents_match_appendix_a4_directions():
    c1, r1, c2, r2 = np.array([0.0, 0.0]), 0.3, np.array([2.0, 0.5]), 0.2
    a, b, d1, d2 = circle_circle_tangents(c1, r1, c2, r2)
    assert np.isfinite(a).all() and np.isfinite(b).all()
    assert np.array_equal(wrap_direction(c1, a, b), d1)  # dir1 of A.4
    assert np.array_equal(d2[:2], d1[:2]) and np.array_equal(d2[2:], -d1[2:])  # external / internal
    # overlapping circles have no internal tangents
    a, _, _, _ = circle_circle_tangents(c1, 1.0, c2, 1.5)
    assert np.isfinite(a[:2]).all() and np.isnan(a[2:]).all()


def test_zero_radius_tangency_and_coincidence():
    # two points: the tangent is the segment itself, whatever the wrap directions
    for d1 in (1, -1):
        for d2 in (1, -1):
            a, b, u, L, ok = directed_tangent([0, 0], 0.0, d1, [3, 4], 0.0, d2)
            assert ok and L == pytest.approx(5) and np.allclose(a, [0, 0]) and np.allclose(b, [3, 4])
    # a point on a circle: a single contact point, zero length, tangent direction
    a, b, u, L, ok = directed_tangent([0, 0], 0.0, 1, [1, 0], 1.0, 1)
    assert ok and L == pytest.approx(0, abs=1e-7) and np.allclose(b, [0, 0], atol=1e-7)
    assert abs(u[0]) < 1e-7
    # coincident circles / a point inside a circle: none
    assert not directed_tangent([1, 1], 0.2, 1, [1, 1], 0.2, 1)[4]
    assert not directed_tangent([0, 0], 0.0, 1, [0.1, 0], 1.0, 1)[4]
