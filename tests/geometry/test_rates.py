"""Angular velocity and acceleration from angle rates against finite differences of ``R(q(t))``."""

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

from taut.errors import ArgumentError
from taut.geometry._rates import angular_acceleration, angular_velocity, rate_matrix
from taut.geometry._rotation import CONVENTIONS, rotation_matrix

finite = st.floats(-3.0, 3.0)
triple = st.tuples(finite, finite, finite)


def _derivative(f, t, h):
    """``f'(t)`` by the five-point central stencil (Richardson's extrapolation of two central
    differences): truncation error ``h⁴ |f⁽⁵⁾| / 30``, round-off about ``ε |f| / h``."""
    return (8 * (f(t + h) - f(t - h)) - (f(t + 2 * h) - f(t - 2 * h))) / (12 * h)


def _time_scale(qd, qdd):
    """The time over which ``R(q(t))`` turns by about a radian: steps are a fraction of it, so
    that ``h |q̇|`` (hence the truncation error) does not grow with the rates."""
    return 1.0 / (1.0 + np.abs(qd).sum() + np.sqrt(np.abs(qdd).sum()))


def _omega_fd(q, qd, qdd, t, convention):
    """ω(t) from ``[ω]× = Ṙ Rᵀ`` along ``q(t) = q + qd t + qdd t²/2``, by finite differences
    with a step of 1e-3 of the time scale: truncation ~1e-13, round-off ~1e-12 (rates ≤ 3)."""

    def R(s):
        return rotation_matrix(q + qd * s + 0.5 * qdd * s * s, convention)

    W = _derivative(R, t, 1e-3 * _time_scale(qd, qdd)) @ R(t).T
    return np.array([W[2, 1], W[0, 2], W[1, 0]]), W


@pytest.mark.parametrize("convention", CONVENTIONS)
@settings(max_examples=60, deadline=None)
@given(q=triple, qd=triple, qdd=triple)
@example(q=(0.0, 1.0, 0.0), qd=(-3.0, 3.0, 3.0), qdd=(-3.0, 0.0, 0.0))  # two-point FD: skew by 1.1e-8
def test_velocity_and_acceleration_match_finite_differences(convention, q, qd, qdd):
    q, qd, qdd = map(np.array, (q, qd, qdd))
    w, W = _omega_fd(q, qd, qdd, 0.0, convention)
    assert np.allclose(W, -W.T, rtol=0, atol=1e-9)  # Ṙ Rᵀ is skew: the finite difference is sound
    assert np.allclose(angular_velocity(q, qd, convention), w, rtol=0, atol=1e-9)
    # α = dω/dt by the same stencil on the ω above (their 1e-12 error over a 1e-2 step)
    alpha = _derivative(lambda t: _omega_fd(q, qd, qdd, t, convention)[0], 0.0, 1e-2 * _time_scale(qd, qdd))
    assert np.allclose(angular_acceleration(q, qd, qdd, convention), alpha, rtol=0, atol=1e-6)


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
