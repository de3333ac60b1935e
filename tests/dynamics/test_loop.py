"""The control-loop model (``taut.dynamics._loop``): the same numbers as the checked functions
(``rk4_step``, ``inverse_dynamics``), the fallback where the closed form gives up, and errors."""

import numpy as np
import pytest

from taut.dynamics import inverse_dynamics, loop_model, rk4_step
from taut.errors import SingularConfigurationError, TautError


def test_step_and_tensions_match_the_checked_functions(spatial, rng):
    lm = loop_model(spatial)
    for _ in range(5):
        q, qd, qdd = rng.uniform(-0.2, 0.2, 6), rng.normal(0, 0.5, 6), rng.normal(0, 0.5, 6)
        w = rng.normal(0, 2, 6)
        tau, ok = lm.tensions(q, qd, qdd, wrench=w)
        ref = inverse_dynamics(spatial, q, qd, qdd, method="closed-form", wrench=w)
        assert ok == bool(ref.feasible)
        np.testing.assert_allclose(tau, ref.tensions, rtol=1e-12, atol=1e-12)
        a, b = lm.step(q, qd, tau, 1e-3, wrench=w)
        ra, rb = rk4_step(spatial, q, qd, tau, 1e-3, wrench=w)
        np.testing.assert_array_equal(a, ra)
        np.testing.assert_array_equal(b, rb)


def test_fallback_where_the_closed_form_gives_up(spatial):
    """A fast motion where the closed form's mid-range tensions leave the bounds but the
    minimum-norm distribution exists: the loop model answers with ``qp``."""
    t = np.linspace(0, 2 * np.pi / 20, 41)[:, None]
    a = np.array([0.3, 0.0, 0.3, 0.0, 0.0, 0.0])
    q, qd, qdd = a * np.sin(20 * t), a * 20 * np.cos(20 * t), -a * 400 * np.sin(20 * t)
    closed = inverse_dynamics(spatial, q, qd, qdd, method="closed-form")
    qp = inverse_dynamics(spatial, q, qd, qdd, method="qp")
    k = int(np.flatnonzero(~closed.feasible & qp.feasible)[0])
    tau, ok = loop_model(spatial, method="qp").tensions(q[k], qd[k], qdd[k])
    assert ok
    np.testing.assert_allclose(tau, qp.tensions[k], rtol=1e-9, atol=1e-9)


def test_errors(spatial):
    lm = loop_model(spatial)
    with pytest.raises(SingularConfigurationError):
        lm.step(np.array([0, 0, 0, 0, np.pi / 2, 0]), np.zeros(6), np.full(8, 10.0), 1e-3)
    with pytest.raises(TautError, match="unknown"):
        loop_model(spatial, method="magic")
