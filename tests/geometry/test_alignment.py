"""The rigid alignment of point sets (Kabsch 1976): a known rigid motion is recovered, the
rotation is proper even where a reflection would fit better, and no other rigid motion fits
noisy points better."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from taut.errors import TautError
from taut.geometry import rigid_alignment

seeds = st.integers(0, 2**32 - 1)


@settings(max_examples=60, deadline=None)
@given(seeds, st.integers(3, 12))
def test_a_rigid_motion_is_recovered(seed, n):
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(n, 3))
    Q = Rotation.random(random_state=rng).as_matrix()
    t = rng.normal(size=3)
    got_Q, got_t = rigid_alignment(points, points @ Q.T + t)
    np.testing.assert_allclose(got_Q, Q, atol=1e-9)
    np.testing.assert_allclose(got_t, t, atol=1e-9)


@settings(max_examples=40, deadline=None)
@given(seeds)
def test_no_rigid_motion_fits_noisy_points_better(seed):
    """The least-squares optimum: small random rigid motions away from it fit worse."""
    rng = np.random.default_rng(seed)
    points = rng.normal(size=(8, 3))
    target = points @ Rotation.random(random_state=rng).as_matrix().T + rng.normal(size=3)
    target += rng.normal(scale=0.05, size=target.shape)
    Q, t = rigid_alignment(points, target)
    assert np.linalg.det(Q) == pytest.approx(1.0)
    best = np.sum((points @ Q.T + t - target) ** 2)
    for _ in range(20):
        dQ = Rotation.from_rotvec(rng.normal(scale=0.01, size=3)).as_matrix()
        other = np.sum((points @ (dQ @ Q).T + t + rng.normal(scale=0.01, size=3) - target) ** 2)
        assert other >= best - 1e-12


def test_mirrored_points_get_a_rotation_not_a_reflection():
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], float)
    mirrored = square * [-1, 1]
    Q, _ = rigid_alignment(square, mirrored)
    assert np.linalg.det(Q) == pytest.approx(1.0)


@pytest.mark.parametrize(
    ("source", "target"),
    [(np.zeros((3, 3)), np.zeros((4, 3))), (np.zeros((3, 4)), np.zeros((3, 4))), ([[np.nan, 0.0]], [[0.0, 0.0]])],
)
def test_bad_point_sets(source, target):
    with pytest.raises(TautError, match="rigid_alignment"):
        rigid_alignment(source, target)


def test_a_reflection_is_recovered_where_allowed():
    rng = np.random.default_rng(3)
    points = rng.normal(size=(6, 3))
    mirror = np.diag([1.0, 1.0, -1.0]) @ Rotation.random(random_state=rng).as_matrix()
    target = points @ mirror.T + [0.5, -1.0, 2.0]
    Q, t = rigid_alignment(points, target, reflection=True)
    np.testing.assert_allclose(Q, mirror, atol=1e-9)
    np.testing.assert_allclose(points @ Q.T + t, target, atol=1e-9)
    proper, _ = rigid_alignment(points, target)
    assert np.linalg.det(proper) == pytest.approx(1.0)
