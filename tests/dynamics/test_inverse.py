"""Inverse dynamics (``taut.dynamics._inverse``): tensions that produce the required wrench
within bounds (checked with the structure matrix of the kinematics), infeasible samples
reported with index and reason, the plot, and bad input."""

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

import taut  # noqa: E402
from taut.dynamics import inverse_dynamics, required_wrench  # noqa: E402
from taut.errors import TautError, UnsupportedRobotError  # noqa: E402
from taut.kinematics import structure_matrix  # noqa: E402
from taut.statics import solve_tensions  # noqa: E402
from taut.viz import plot_motion_tensions  # noqa: E402


def sinusoid(robot, n, amplitude, omega):
    """Samples of ``q = a sin(ω t)`` over one period, with exact rates."""
    t = np.linspace(0, 2 * np.pi / omega, n)
    a = np.asarray(amplitude, float)
    s, c = np.sin(omega * t)[:, None], np.cos(omega * t)[:, None]
    return t, a * s, a * omega * c, -a * omega**2 * s


@pytest.mark.parametrize("method", ["closed-form", "improved-closed-form", "qp", "lp"])
def test_tensions_give_the_required_wrench(method, spatial):
    t, q, qd, qdd = sinusoid(spatial, 25, [0.1, 0.05, 0.1, 0.05, 0.05, 0.1], 2.0)
    res = inverse_dynamics(spatial, q, qd, qdd, method=method, time=t)
    assert res.feasible.all(), res.failures()
    W = structure_matrix(spatial, q)
    wrench = required_wrench(spatial, q, qd, qdd)
    got = np.einsum("kij,kj->ki", W, res.tensions)
    np.testing.assert_allclose(got, wrench, atol=1e-8 * np.abs(wrench).max())
    lo, hi = spatial.tension_bounds
    assert (res.tensions >= lo).all() and (res.tensions <= hi).all()
    assert res.first_failure is None and res.failures() == []
    np.testing.assert_array_equal(res.time, t)
    assert not res.tensions.flags.writeable


@settings(max_examples=15, deadline=None)
@given(
    amp=st.lists(st.floats(0.0, 0.15), min_size=3, max_size=3),
    omega=st.floats(0.5, 6.0),
)
def test_planar_tensions_balance_or_are_reported(amp, omega):
    """Every sample is either balanced within bounds or reported with a reason."""
    robot = _PLANAR
    _, q, qd, qdd = sinusoid(robot, 12, amp, omega)
    res = inverse_dynamics(robot, q, qd, qdd, method="qp")
    W = structure_matrix(robot, q)
    wrench = required_wrench(robot, q, qd, qdd)
    lo, hi = robot.tension_bounds
    for k in range(len(q)):
        if res.feasible[k]:
            np.testing.assert_allclose(W[k] @ res.tensions[k], wrench[k], atol=1e-8 * max(1, np.abs(wrench[k]).max()))
            assert (res.tensions[k] >= lo).all() and (res.tensions[k] <= hi).all()
            assert res.reasons[k] == ""
        else:
            assert res.status[k] == "infeasible" and "bounds" in res.reasons[k]
            assert (res.tensions[k] == 0).all()


_BASE = taut.example("planar-4cable")
_PLANAR = _BASE.model_copy(update={"platform": _BASE.platform.model_copy(update={"inertia": (0.004,)})})


def test_infeasible_samples_are_reported(spatial):
    """A fast motion needs more than 500 N in some cable: those samples are reported with
    their index, the status of the exact method and a reason, and the others are solved."""
    t, q, qd, qdd = sinusoid(spatial, 41, [0.3, 0.0, 0.3, 0.0, 0.0, 0.0], 30.0)
    res = inverse_dynamics(spatial, q, qd, qdd, method="qp", time=t)
    bad = np.flatnonzero(~res.feasible)
    assert 0 < bad.size < len(t)
    assert res.first_failure == bad[0]
    assert [k for k, _ in res.failures()] == bad.tolist()
    assert all(res.status[k] == "infeasible" for k in bad)
    assert all("bounds" in why for _, why in res.failures())
    # the exact method is right: the least-squares tensions of a failing sample leave the bounds
    # or the wrench is out of reach; a feasible neighbour is within bounds
    ok = np.flatnonzero(res.feasible)
    lo, hi = spatial.tension_bounds
    assert (res.tensions[ok] >= lo).all() and (res.tensions[ok] <= hi).all()
    closed = inverse_dynamics(spatial, q, qd, qdd, method="closed-form")
    assert not closed.feasible[bad].any()  # no method finds what does not exist
    assert all(s in ("infeasible", "not-found") for s in closed.status[bad])


def test_plot(spatial, tmp_path):
    t, q, qd, qdd = sinusoid(spatial, 41, [0.3, 0.0, 0.3, 0.0, 0.0, 0.0], 20.0)
    res = inverse_dynamics(spatial, q, qd, qdd, method="closed-form", time=t)
    ax = plot_motion_tensions(spatial, res)
    lines = [line for line in ax.get_lines() if str(line.get_gid()).startswith("tension-")]
    assert len(lines) == 8
    np.testing.assert_allclose(lines[0].get_xdata(), t)
    marks = next(line for line in ax.get_lines() if line.get_gid() == "infeasible")
    np.testing.assert_allclose(marks.get_xdata(), t[~res.feasible])
    path = tmp_path / "tensions.png"
    ax.figure.savefig(path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_bad_input(spatial, no_inertia):
    q = np.zeros((3, 6))
    with pytest.raises(TautError, match="unknown tension distribution method"):
        inverse_dynamics(spatial, q, q, q, method="magic")
    with pytest.raises(TautError):
        inverse_dynamics(spatial, q, q[:2], q)
    with pytest.raises(TautError):
        inverse_dynamics(spatial, q, q, np.full((3, 6), np.inf))
    with pytest.raises(TautError, match="times"):
        inverse_dynamics(spatial, q, q, q, time=[0, 1])
    with pytest.raises(UnsupportedRobotError):
        inverse_dynamics(no_inertia, q, q, q)


@pytest.mark.parametrize("name", ["spatial", "planar", "point_mass"])
def test_compiled_closed_form_is_the_statics_closed_form(name, request):
    """The compiled closed form (Cholesky of ``W Wᵀ``) gives the tensions of
    ``solve_tensions(..., "closed-form")`` (SVD pseudo-inverse) on the same wrenches."""
    robot = request.getfixturevalue(name)
    amp = [0.1, 0.05, 0.1, 0.05, 0.05, 0.1][: robot.pose_size]
    t, q, qd, qdd = sinusoid(robot, 30, amp, 3.0)
    res = inverse_dynamics(robot, q, qd, qdd, method="closed-form", time=t)
    ref = solve_tensions(
        structure_matrix(robot, q), -required_wrench(robot, q, qd, qdd), *robot.tension_bounds, "closed-form"
    )
    np.testing.assert_array_equal(res.feasible, ref.feasible)
    np.testing.assert_array_equal(res.status, ref.status)
    assert res.feasible.any()
    np.testing.assert_allclose(res.tensions, ref.tensions, rtol=1e-9, atol=1e-9)


def test_progress_and_forward_plot(spatial, monkeypatch):
    """``progress(done, total)`` reaches the total; the plot of a simulated motion marks the
    samples where an elastic cable is slack."""
    import taut.dynamics._inverse as inverse_module
    from taut.dynamics import forward_dynamics
    from taut.kinematics import cable_lengths

    monkeypatch.setattr(inverse_module, "CHUNK", 10)
    calls = []
    t, q, qd, qdd = sinusoid(spatial, 25, [0.1, 0.05, 0.1, 0.05, 0.05, 0.1], 2.0)
    chunked = inverse_dynamics(spatial, q, qd, qdd, method="closed-form", progress=lambda d, n: calls.append((d, n)))
    assert calls == [(10, 25), (20, 25), (25, 25)]
    whole = inverse_dynamics(spatial, q, qd, qdd, method="closed-form")
    np.testing.assert_array_equal(chunked.tensions, whole.tensions)

    robot = spatial.model_copy(
        update={"cables": tuple(c.model_copy(update={"stiffness": 2e4}) for c in spatial.cables)}
    )
    q0 = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    l0 = cable_lengths(robot, q0) * (1 - 1e-3)
    l0[2] += 0.2
    steps = []
    res = forward_dynamics(
        robot,
        q0,
        np.zeros(6),
        0.02,
        lengths=lambda t: l0,
        method="RK4",
        step=1e-3,
        progress=lambda d, n: steps.append(d),
    )
    assert steps == list(range(1, 21))
    ax = plot_motion_tensions(robot, res)
    marks = next(line for line in ax.get_lines() if line.get_gid() == "infeasible")
    np.testing.assert_allclose(marks.get_xdata(), res.time)  # cable 3 is slack throughout
    assert "simulated motion" in ax.get_title()


def test_one_sample_has_no_batch_axis(spatial):
    q, qd, qdd = np.full(6, 0.05), np.full(6, 0.1), np.full(6, -0.2)
    one = inverse_dynamics(spatial, q, qd, qdd, method="qp", time=0.5)
    batch = inverse_dynamics(spatial, q[None], qd[None], qdd[None], method="qp", time=[0.5])
    assert one.tensions.shape == (8,) and one.wrench.shape == (6,) and one.feasible.shape == ()
    assert bool(one.feasible) and str(one.status) == "optimal" and str(one.reasons) == "" and float(one.time) == 0.5
    np.testing.assert_array_equal(one.tensions, batch.tensions[0])
    assert one.failures() == [] and one.first_failure is None
    fast = np.array([0.0, 0.0, 400.0, 0.0, 0.0, 0.0])
    bad = inverse_dynamics(spatial, q, qd, fast, method="qp")
    assert bad.first_failure == 0 and bad.failures()[0][0] == 0 and "bounds" in bad.failures()[0][1]
