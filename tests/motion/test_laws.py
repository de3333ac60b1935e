"""Time laws: boundary conditions, derivatives by finite differences, peaks within limits."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taut
from taut.motion import LAWS, trajectory_from_waypoints

SPATIAL = taut.example("spatial-8cable")
PLANAR = taut.example("planar-4cable")

coordinate = st.floats(-0.8, 0.8)
pose = st.tuples(*[coordinate] * 6)
positive = st.floats(0.2, 5.0)


def _p2p(start, end, T, law, **kw):
    return trajectory_from_waypoints(SPATIAL, [start, end], durations=T, law=law, **kw)


@pytest.mark.parametrize("law", LAWS)
@settings(max_examples=30, deadline=None)
@given(start=pose, end=pose, T=positive)
def test_boundary_conditions_and_straight_line(law, start, end, T):
    q0, q1 = np.array(start), np.array(end)
    m = _p2p(start, end, T, law)
    s = m.at([0.0, T])
    assert np.allclose(s.poses, [q0, q1], atol=1e-12)
    d = q1 - q0
    if law != "linear":
        # every rest-to-rest law starts and ends at rest
        assert np.allclose(s.velocity, 0.0, atol=1e-9)
    expected_start_acceleration = {
        "linear": 0.0 * d,
        "cubic": 6 * d / T**2,  # s(τ) = 3τ² − 2τ³
        "quintic": 0.0 * d,  # s(τ) = 10τ³ − 15τ⁴ + 6τ⁵
        "trapezoidal": d / ((T / 3) * (T - T / 3)),  # blend T/3: a = Δ / (t_b (T − t_b))
    }[law]
    assert np.allclose(s.acceleration[0], expected_start_acceleration, rtol=1e-9, atol=1e-9)
    assert np.allclose(s.acceleration[1], -expected_start_acceleration, rtol=1e-9, atol=1e-9)
    # one scalar time law for all coordinates: a straight line, s rising monotonically 0 → 1
    inner = m.sample(200 / T)
    offset = inner.poses - q0
    k = int(np.argmax(np.abs(d)))
    if abs(d[k]) > 1e-6:
        sv = offset[:, k] / d[k]
        assert np.allclose(offset, sv[:, None] * d, atol=1e-9)
        assert np.all(np.diff(sv) >= -1e-12) and sv.min() >= -1e-12 and sv.max() <= 1 + 1e-12


def _smooth_times(m, n=40, h=1e-4):
    """Times at least 2h away from every break of the piecewise polynomial (where a
    trapezoidal acceleration jumps)."""
    t = np.linspace(0, m.duration, n + 2)[1:-1]
    gap = np.min(np.abs(t[:, None] - m.breaks[None, :]), axis=1)
    return t[gap > 2 * h]


COMBINATIONS = [(law, "stop") for law in LAWS] + [("cubic", "average"), ("quintic", "average"), ("cubic", "spline")]


@pytest.mark.parametrize(("law", "via"), COMBINATIONS)
@settings(max_examples=15, deadline=None)
@given(points=st.lists(pose, min_size=2, max_size=5), durations=st.lists(positive, min_size=4, max_size=4))
def test_derivatives_match_finite_differences_of_the_pose(law, via, points, durations):
    m = trajectory_from_waypoints(SPATIAL, points, durations=durations[: len(points) - 1], law=law, via=via)
    h = 1e-4
    t = _smooth_times(m, h=h)
    s, plus, minus = m.at(t), m.at(t + h), m.at(t - h)
    # truncation errors h²/6 q⃛ and h²/12 q⁗ are below 1e-5 of the scale for segments ≥ 0.2 s
    v_scale = 1e-5 * (np.abs(s.velocity).max() + 1.0)
    a_scale = 1e-4 * (np.abs(s.acceleration).max() + 1.0)
    assert np.abs(s.velocity - (plus.poses - minus.poses) / (2 * h)).max() <= v_scale
    assert np.abs(s.acceleration - (plus.poses - 2 * s.poses + minus.poses) / h**2).max() <= a_scale


@pytest.mark.parametrize("law", LAWS)
@settings(max_examples=25, deadline=None)
@given(
    points=st.lists(pose, min_size=2, max_size=4),
    vmax=st.lists(st.floats(0.05, 2.0), min_size=6, max_size=6),
    amax=st.lists(st.floats(0.05, 5.0), min_size=6, max_size=6),
)
def test_shortest_segments_keep_within_limits_and_reach_one(law, points, vmax, amax):
    W = np.array(points)
    assume(np.all(np.abs(np.diff(W, axis=0)).max(axis=1) > 1e-6))
    m = trajectory_from_waypoints(SPATIAL, W, law=law, max_velocity=vmax, max_acceleration=amax)
    s = m.sample(4000 / m.duration)
    vratio = np.abs(s.velocity) / np.array(vmax)
    aratio = np.abs(s.acceleration) / np.array(amax)
    assert vratio.max() <= 1 + 1e-9
    if law != "linear":
        assert aratio.max() <= 1 + 1e-9
    # the shortest duration: in every segment, some coordinate is at its velocity or
    # acceleration limit (sampled 4000 times over the motion: within 1 %)
    for k in range(len(W) - 1):
        inside = (s.times >= m.times[k]) & (s.times <= m.times[k + 1])
        reached = max(vratio[inside].max(), 0.0 if law == "linear" else aratio[inside].max())
        assert reached >= 0.99


def test_trapezoidal_is_triangular_when_the_cruise_speed_is_out_of_reach():
    # distance 0.1 m, v ≤ 1 m/s, a ≤ 1 m/s²: v²/a = 1 > 0.1, so t_b = √(0.1) and T = 2 t_b
    m = trajectory_from_waypoints(
        PLANAR,
        [[0.5, 0.5, 0.0], [0.6, 0.5, 0.0]],
        law="trapezoidal",
        max_velocity=[1.0, 1.0, 1.0],
        max_acceleration=[1.0, 1.0, 1.0],
    )
    assert m.duration == pytest.approx(2 * np.sqrt(0.1))
    s = m.at([m.duration / 2])
    assert s.velocity[0, 0] == pytest.approx(np.sqrt(0.1))  # the peak of the triangle, a t_b
    # a long move cruises at the limit: T = d/v + v/a
    m = trajectory_from_waypoints(
        PLANAR, [[0.0, 0.5, 0.0], [3.0, 0.5, 0.0]], law="trapezoidal", max_velocity=0.5, max_acceleration=1.0
    )
    assert m.duration == pytest.approx(3.0 / 0.5 + 0.5 / 1.0)
    assert m.at([m.duration / 2]).velocity[0, 0] == pytest.approx(0.5)


@pytest.mark.parametrize("blend", [0.1, 0.25, 0.5])
def test_trapezoidal_blend_fraction(blend):
    T, d = 2.0, 0.3
    m = trajectory_from_waypoints(
        PLANAR, [[0.5, 0.5, 0.0], [0.8, 0.5, 0.0]], durations=T, law="trapezoidal", blend=blend
    )
    tb = blend * T
    a = d / (tb * (T - tb))
    s = m.at([tb / 2, T / 2, T - tb / 2])
    # triangular (blend 1/2): T/2 is where the acceleration jumps; the piece ending there counts
    assert s.acceleration[:, 0] == pytest.approx([a, 0.0 if blend < 0.5 else a, -a])
    assert s.velocity[1, 0] == pytest.approx(a * tb)
