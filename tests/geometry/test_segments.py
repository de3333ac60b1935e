"""Segment–segment distance (Lieskovský 2020, §3.5) against exact and brute-force references, in the
parallel, collinear, skew and degenerate (zero-length) configurations."""

from fractions import Fraction

import numpy as np
import pytest
from hypothesis import assume, example, given, settings
from hypothesis import strategies as st
from scipy.optimize import lsq_linear

from taut.geometry._segments import segment_distance


def exact(a1, b1, a2, b2):
    """Reference: the bounded least-squares problem min ‖a1 + s v1 − a2 − t v2‖, s, t ∈ [0, 1]."""
    M = np.column_stack([b1 - a1, -(b2 - a2)])
    res = lsq_linear(M, a2 - a1, bounds=(0, 1), method="bvls", tol=1e-14)
    return float(np.linalg.norm(M @ res.x - (a2 - a1)))


def brute(a1, b1, a2, b2, k=801):
    s = np.linspace(0, 1, k)
    P = a1 + s[:, None] * (b1 - a1)
    Q = a2 + s[:, None] * (b2 - a2)
    return float(np.sqrt(((P[:, None] - Q[None]) ** 2).sum(-1)).min())


CASES = {
    "skew crossing": ([0, 0, 0], [2, 0, 0], [1, -1, 1], [1, 1, 1], 1.0),
    "parallel offset": ([0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], 1.0),
    "parallel disjoint": ([0, 0, 0], [1, 0, 0], [3, 4, 0], [5, 4, 0], np.hypot(2, 4)),
    "antiparallel overlap": ([0, 0, 0], [2, 0, 0], [3, 0.5, 0], [1, 0.5, 0], 0.5),
    "collinear overlap": ([0, 0, 0], [2, 0, 0], [1, 0, 0], [3, 0, 0], 0.0),
    "collinear gap": ([0, 0, 0], [1, 0, 0], [3, 0, 0], [2, 0, 0], 1.0),
    "touching ends": ([0, 0, 0], [1, 0, 0], [1, 0, 0], [1, 5, 0], 0.0),
    "point and segment": ([0, 1, 0], [0, 1, 0], [-1, 0, 0], [1, 0, 0], 1.0),
    "point beyond end": ([3, 4, 0], [3, 4, 0], [-1, 0, 0], [0, 0, 0], 5.0),
    "two points": ([1, 2, 3], [1, 2, 3], [4, 6, 3], [4, 6, 3], 5.0),
    "planar": ([0, 0], [1, 1], [1, 0], [2, -1], np.sqrt(0.5)),
}


@pytest.mark.parametrize("case", CASES.values(), ids=CASES.keys())
def test_named_configurations(case):
    *pts, expected = case
    d, s, t = segment_distance(*pts, parameters=True)
    assert d == pytest.approx(expected, abs=1e-12)
    p = np.asarray(pts, float)
    gap = (p[0] + s * (p[1] - p[0])) - (p[2] + t * (p[3] - p[2]))
    assert 0 <= s <= 1 and 0 <= t <= 1 and np.linalg.norm(gap) == pytest.approx(d, abs=1e-12)
    assert segment_distance(pts[2], pts[3], pts[0], pts[1]) == pytest.approx(expected, abs=1e-12)  # symmetric


def test_random_batch_matches_references():
    rng = np.random.default_rng(0)
    P = rng.normal(size=(400, 4, 3))
    # make a quarter (nearly) parallel, some degenerate
    P[:100, 3] = (
        P[:100, 2] + (P[:100, 1] - P[:100, 0]) * rng.uniform(-2, 2, (100, 1)) + rng.normal(scale=1e-9, size=(100, 3))
    )
    P[100:130, 1] = P[100:130, 0]
    d = segment_distance(P[:, 0], P[:, 1], P[:, 2], P[:, 3])
    assert d.shape == (400,)
    ref = np.array([exact(*p) for p in P])
    assert np.allclose(d, ref, atol=1e-9)
    bf = np.array([brute(*p) for p in P[:60]])
    assert np.all(d[:60] <= bf + 1e-12) and np.all(bf - d[:60] < 1e-2)


def test_nearly_parallel_long_segments_are_accurate():
    a1, b1 = np.array([0.0, 0, 0]), np.array([100.0, 0, 0])
    for angle in (1e-6, 1e-9, 1e-12, 0.0):
        a2, b2 = np.array([-50.0, 1e-3, 0.0]), np.array([50.0, 1e-3 + 100 * np.sin(angle), 100 * angle])
        assert segment_distance(a1, b1, a2, b2) == pytest.approx(exact(a1, b1, a2, b2), abs=1e-9)


coord = st.floats(-10, 10, allow_nan=False)
point = st.tuples(coord, coord, coord)


@settings(max_examples=300, deadline=None)
@given(point, point, point, point)
def test_property_against_exact(a1, b1, a2, b2):
    p = [np.array(x) for x in (a1, b1, a2, b2)]
    d = segment_distance(*p)
    assert d == pytest.approx(exact(*p), abs=1e-7)
    assert d <= min(np.linalg.norm(x - y) for x in p[:2] for y in p[2:]) + 1e-12


def crossing(p1, p2, q1, j):
    """Float end points within half an ulp of segments that cross exactly: ``p1 p2`` and
    ``q1 q2`` with ``q2 = 2 X − q1`` through ``X = p1 + (j / 10) (p2 − p1)`` (decimal
    coordinates, tenths, made exact with fractions and rounded once)."""
    P1, P2, Q1 = ([Fraction(k, 10) for k in p] for p in (p1, p2, q1))
    Q2 = [2 * (a + Fraction(j, 10) * (b - a)) - c for a, b, c in zip(P1, P2, Q1)]
    return [np.array([float(x) for x in p]) for p in (P1, P2, Q1, Q2)]


tenths = st.lists(st.integers(-40, 40), min_size=3, max_size=3)


@settings(max_examples=300, deadline=None)
@given(tenths, tenths, tenths, st.integers(1, 9))
@example([-40, -4, 23], [31, 11, -37], [-33, -3, 17], 8)  # 143 ulps by (b f − c e) / (a e − b²)
def test_crossing_segments_are_at_distance_zero_to_a_few_ulps(p1, p2, q1, j):
    a1, b1, a2, b2 = crossing(p1, p2, q1, j)
    scale = np.abs([a1, b1, a2, b2]).max()
    assume(scale > 0)
    orders = [(a1, b1, a2, b2), (b1, a1, a2, b2), (a2, b2, a1, b1), (b2, a2, b1, a1)]
    # the float points are within half an ulp of crossing ones: the true distance is ≲ 2 ulps
    assert all(segment_distance(*o) <= 8 * np.finfo(float).eps * scale for o in orders)
