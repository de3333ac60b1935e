import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from taut.errors import ArgumentError
from taut.geometry import CONVENTIONS, angles_from_matrix, planar_rotation, rotation_matrix

angles = arrays(float, (3,), elements=st.floats(-1.4, 1.4))


def _rx(a):
    return np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])


def _rz(a):
    return np.array([[np.cos(a), -np.sin(a), 0], [np.sin(a), np.cos(a), 0], [0, 0, 1]])


def _ry(a):
    return np.array([[np.cos(a), 0, np.sin(a)], [0, 1, 0], [-np.sin(a), 0, np.cos(a)]])


@settings(deadline=None)  # the first call may compile the kernel
@given(angles)
def test_conventions_match_their_definitions(v):
    a, b, c = v
    np.testing.assert_allclose(rotation_matrix(v, "xyz-fixed"), _rz(c) @ _ry(b) @ _rx(a), atol=1e-14)
    np.testing.assert_allclose(rotation_matrix(v, "xyz-moving"), _rx(a) @ _ry(b) @ _rz(c), atol=1e-14)
    np.testing.assert_allclose(rotation_matrix(v, "tilt-torsion"), _rz(a) @ _ry(b) @ _rz(c - a), atol=1e-14)


@pytest.mark.parametrize("convention", CONVENTIONS)
@settings(max_examples=60, deadline=None)  # the first call may compile the kernel
@given(v=angles)
def test_angles_round_trip(convention, v):
    if convention == "tilt-torsion":
        v = np.array([v[0], abs(v[1]) + 0.05, v[2]])
    R = rotation_matrix(v, convention)
    np.testing.assert_allclose(R @ R.T, np.eye(3), atol=1e-13)
    assert np.linalg.det(R) == pytest.approx(1.0)
    back = angles_from_matrix(R, convention)
    np.testing.assert_allclose(rotation_matrix(back, convention), R, atol=1e-12)


def test_batches_and_planar():
    v = np.random.default_rng(0).uniform(-1, 1, (5, 4, 3))
    R = rotation_matrix(v)
    assert R.shape == (5, 4, 3, 3)
    for i, j in np.ndindex(5, 4):
        a, b, c = v[i, j]
        np.testing.assert_allclose(R[i, j], _rz(c) @ _ry(b) @ _rx(a), atol=1e-14)
    R = planar_rotation(np.pi / 2)
    np.testing.assert_allclose(R @ [1, 0], [0, 1], atol=1e-15)
    with pytest.raises(ArgumentError, match="unknown orientation"):
        rotation_matrix([0, 0, 0], "zyz")
