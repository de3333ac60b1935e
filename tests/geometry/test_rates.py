"""Angular velocity and acceleration from angle rates against finite differences of ``R(q(t))``."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.errors import ArgumentError
from taut.geometry._rates import angular_acceleration, angular_velocity, rate_matrix
from taut.geometry._rotation import CONVENTIONS, rotation_matrix

finite = st.floats(-3.0, 3.0)
triple = st.tuples(finite, finite, finite)


def _omega_fd(q, qd, qdd, t, convention, h=1e-5):
    """ω(t) from ``[ω]× = Ṙ Rᵀ`` along ``q(t) = q + qd t + qdd t²/2``, by central differences."""

    def R(s):
        return rotation_matrix(q + qd * s + 0.5 * qdd * s * s, convention)

    W = (R(t + h) - R(t - h)) / (2 * h) @ R(t).T
    return np.array([W[2, 1], W[0, 2], W[1, 0]]), W


@pytest.mark.parametrize("convention", CONVENTIONS)
@settings(max_examples=60, deadline=None)
@given(q=triple, qd=triple, qdd=triple)
def test_velocity_and_acceleration_match_finite_differences(convention, q, qd, qdd):
    q, qd, qdd = map(np.array, (q, qd, qdd))
    w, W = _omega_fd(q, qd, qdd, 0.0, convention)
    assert np.allclose(W, -W.T, atol=1e-8)  # Ṙ Rᵀ is skew: the finite difference is sound
    assert np.allclose(angular_velocity(q, qd, convention), w, atol=1e-7)
    h = 1e-4
    alpha = (_omega_fd(q, qd, qdd, h, convention)[0] - _omega_fd(q, qd, qdd, -h, convention)[0]) / (2 * h)
    assert np.allclose(angular_acceleration(q, qd, qdd, convention), alpha, atol=1e-5)


def test_batched_shapes_and_gimbal_lock():
    rng = np.random.default_rng(0)
    q, qd = rng.uniform(-1, 1, (2, 4, 5, 3))
    E = rate_matrix(q, "xyz-moving")
    w = angular_velocity(q, qd, "xyz-fixed")
    assert E.shape == (4, 5, 3, 3) and w.shape == (4, 5, 3)
    for i, j in np.ndindex(4, 5):
        zero = np.zeros(3)
        np.testing.assert_allclose(
            E[i, j] @ qd[i, j], _omega_fd(q[i, j], qd[i, j], zero, 0.0, "xyz-moving")[0], atol=1e-7
        )
        np.testing.assert_allclose(w[i, j], _omega_fd(q[i, j], qd[i, j], zero, 0.0, "xyz-fixed")[0], atol=1e-7)
    # xyz-fixed locks at b = ±π/2 and tilt-torsion at θ = 0: E loses rank exactly there
    assert np.linalg.matrix_rank(rate_matrix([0.3, np.pi / 2, 0.2], "xyz-fixed")) == 2
    assert np.linalg.matrix_rank(rate_matrix([0.3, 0.0, 0.2], "tilt-torsion")) == 2
    assert np.linalg.matrix_rank(rate_matrix([0.3, 0.4, 0.2], "tilt-torsion")) == 3


def test_unknown_convention():
    with pytest.raises(ArgumentError, match="unknown orientation convention"):
        rate_matrix([0, 0, 0], "zyz")
