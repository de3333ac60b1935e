"""Forward dynamics (``taut.dynamics._forward``): conservation laws computed here from the
state (kinetic and potential energy, linear and angular momentum), the round trip of CASPR's
example (inverse dynamics of a quintic motion drives the forward dynamics back along it),
elastic cables (a slack cable pulls nothing, a static equilibrium stays put), the order of the
fixed-step RK4, and bad input."""

import numpy as np
import pytest

from taut.dynamics import (
    IntegrationError,
    acceleration,
    cable_tensions,
    forward_dynamics,
    inverse_dynamics,
    rk4_step,
)
from taut.errors import SingularConfigurationError, TautError
from taut.geometry import rate_matrix, rotation_matrix
from taut.kinematics import cable_lengths, unstretched_length
from taut.statics import distribute_tensions

TIGHT = {"method": "DOP853", "rtol": 1e-11, "atol": 1e-13}


def with_platform(robot, **fields):
    return robot.model_copy(update={"platform": robot.platform.model_copy(update=fields)})


def with_stiffness(robot, ea):
    return robot.model_copy(update={"cables": tuple(c.model_copy(update={"stiffness": ea}) for c in robot.cables)})


def spatial_state_quantities(robot, q, qd):
    """Kinetic energy, potential energy, linear momentum and angular momentum about the
    origin of a spatial rigid platform, from ``R``, ``ω = E q̇`` and ``v_c = ṗ + ω × R c``."""
    m, I = robot.platform.mass, robot.inertia
    c = np.asarray(robot.platform.wrench_point or (0, 0, 0), float)
    R = rotation_matrix(q[3:6], robot.orientation)
    omega = rate_matrix(q[3:6], robot.orientation) @ qd[3:6]
    pc = q[:3] + R @ c
    vc = qd[:3] + np.cross(omega, R @ c)
    Ic = R @ I @ R.T
    T = 0.5 * m * vc @ vc + 0.5 * omega @ Ic @ omega
    V = -robot.weight @ pc
    return T, V, m * vc, np.cross(pc, m * vc) + Ic @ omega


def test_free_platform_conserves_energy_and_momentum(spatial):
    """No cables pulling and no gravity: kinetic energy, linear and angular momentum are
    constant (a torque-free asymmetric top with the centre of mass off ``p``)."""
    robot = with_platform(spatial, gravity=(0.0, 0.0, 0.0))
    q0 = np.array([0.1, -0.1, 0.05, 0.2, -0.1, 0.3])
    qd0 = np.array([0.05, -0.1, 0.02, 0.6, 0.3, -0.5])
    res = forward_dynamics(robot, q0, qd0, 2.0, tensions=lambda t: np.zeros(8), **TIGHT)
    first = spatial_state_quantities(robot, q0, qd0)
    assert np.abs(res.poses[:, 4]).max() < 1.2  # away from the gimbal lock of xyz-fixed
    for q, qd in zip(res.poses, res.velocity):
        T, _, P, H = spatial_state_quantities(robot, q, qd)
        assert abs(T - first[0]) <= 1e-9 * first[0]
        np.testing.assert_allclose(P, first[2], atol=1e-9 * np.linalg.norm(first[2]))
        np.testing.assert_allclose(H, first[3], atol=1e-9 * np.linalg.norm(first[3]))
    assert abs(res.times[-1] - 2.0) < 1e-12


def test_free_fall_conserves_total_energy(spatial):
    """Gravity only: ``T + V`` constant while the platform falls and tumbles."""
    q0 = np.array([0.0, 0.0, 0.0, 0.1, 0.2, -0.1])
    qd0 = np.array([0.3, 0.0, 1.0, -0.4, 0.2, 0.7])
    res = forward_dynamics(spatial, q0, qd0, 1.0, tensions=lambda t: np.zeros(8), **TIGHT)
    T0, V0, _, _ = spatial_state_quantities(spatial, q0, qd0)
    drops = []
    for q, qd in zip(res.poses, res.velocity):
        T, V, _, _ = spatial_state_quantities(spatial, q, qd)
        assert abs(T + V - (T0 + V0)) <= 1e-9 * (abs(T0) + abs(V0) + 1)
        drops.append(V0 - V)
    assert max(drops) > 10  # it did fall: the check is not vacuous
    # the centre of mass follows the parabola of its initial velocity
    c = np.asarray(spatial.platform.wrench_point)
    pc = [q[:3] + rotation_matrix(q[3:6]) @ c for q in res.poses]
    w0 = rate_matrix(q0[3:6]) @ qd0[3:6]
    vc0 = qd0[:3] + np.cross(w0, rotation_matrix(q0[3:6]) @ c)
    g = spatial.weight / spatial.platform.mass
    for t, p in zip(res.times, pc):
        np.testing.assert_allclose(p, pc[0] + vc0 * t + 0.5 * g * t * t, atol=1e-9)


def quintic(q0, q1, duration):
    """A quintic point-to-point motion with zero boundary velocities and accelerations."""
    q0, q1 = np.asarray(q0, float), np.asarray(q1, float)

    def at(t):
        s = np.clip(t / duration, 0.0, 1.0)
        pos = 10 * s**3 - 15 * s**4 + 6 * s**5
        vel = (30 * s**2 - 60 * s**3 + 30 * s**4) / duration
        acc = (60 * s - 180 * s**2 + 120 * s**3) / duration**2
        d = q1 - q0
        return q0 + d * pos, d * vel, d * acc

    return at


@pytest.mark.slow
@pytest.mark.parametrize(
    ("name", "q0", "q1", "method"),
    [
        ("planar", [-0.2, 0.1, 0.0], [0.25, -0.15, 0.3], "improved-closed-form"),
        ("spatial_centred", [0.0, 0.0, 0.0, 0.0, 0.0, 0.0], [0.2, 0.1, -0.1, -0.1, 0.1, 0.2], "qp"),
    ],
)
def test_round_trip_inverse_then_forward(name, q0, q1, method, request):
    """CASPR's check: the tensions of the inverse dynamics of a 2 s quintic motion, evaluated
    at the times the integrator asks for (exact, no interpolation), drive the forward dynamics
    along the same motion: pose error at most 1e-6 over the 2 s.

    The open loop is unstable for spatial-8cable: its crossed cables give the platform a
    negative rotational stiffness (the linearization at the centre has a real eigenvalue of
    about 9.5²/s² with the minimum-norm tensions, 36²/s² with the closed form's mid-range
    tensions), so an error grows about e^{9.5 t}: ×2·10⁸ over 2 s.  Hence the minimum-norm
    (``qp``) tensions and DOP853 at rtol 1e-12 for it; the closed form's tensions would need
    an accuracy no integrator has."""
    robot = request.getfixturevalue(name)
    motion = quintic(q0, q1, 2.0)

    def tensions(t):
        q, qd, qdd = motion(t)
        res = inverse_dynamics(robot, q, qd, qdd, method=method)
        assert res.feasible.all(), res.reasons
        return res.tensions

    times = np.linspace(0, 2.0, 41)
    tight = {"method": "DOP853", "rtol": 1e-12, "atol": 1e-14}
    res = forward_dynamics(robot, q0, np.zeros(len(q0)), 2.0, tensions=tensions, times=times, **tight)
    want = np.array([motion(t)[0] for t in times])
    np.testing.assert_allclose(res.times, times)
    assert np.abs(res.poses - want).max() <= 1e-6
    assert np.abs(res.poses[-1] - np.asarray(q1)).max() <= 1e-6
    wantv = np.array([motion(t)[1] for t in times])
    assert np.abs(res.velocity - wantv).max() <= 1e-5


def test_rk4_converges_with_fourth_order(spatial):
    """Fixed-step RK4 against DOP853 at tight tolerances: halving the step divides the
    error by about 2⁴."""
    q0 = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    tau0 = distribute_tensions(spatial, q0, method="qp").tensions

    def tensions(t):
        return tau0 * (1 + 0.2 * np.floor(4 * t) / 4)  # piecewise constant on the RK4 grid

    ref = forward_dynamics(spatial, q0, np.zeros(6), 1.0, tensions=tensions, times=[1.0], step=0.25, **TIGHT)
    errors = []
    for dt in (0.05, 0.025, 0.0125):
        res = forward_dynamics(spatial, q0, np.zeros(6), 1.0, tensions=tensions, method="RK4", step=dt)
        assert len(res.times) == round(1.0 / dt) + 1
        errors.append(np.abs(res.poses[-1] - ref.poses[-1]).max())
    assert errors[0] > 1e-9  # the motion is not trivial
    for coarse, fine in zip(errors, errors[1:]):
        assert 10 < coarse / fine < 24, errors


def test_rk4_step_batch_matches_single(spatial, rng):
    Q = rng.uniform(-0.2, 0.2, (5, 6))
    QD = rng.normal(0, 0.5, (5, 6))
    tau = rng.uniform(10, 50, (5, 8))
    qn, vn = rk4_step(spatial, Q, QD, tau, 1e-3)
    for k in range(5):
        a, b = rk4_step(spatial, Q[k], QD[k], tau[k], 1e-3)
        np.testing.assert_allclose(a, qn[k], rtol=1e-14, atol=1e-15)
        np.testing.assert_allclose(b, vn[k], rtol=1e-14, atol=1e-15)
    # one step of RK4 agrees with the exact motion to O(dt⁵)
    exact = forward_dynamics(spatial, Q[0], QD[0], 1e-3, tensions=lambda t: tau[0], times=[1e-3], **TIGHT)
    np.testing.assert_allclose(qn[0], exact.poses[-1], atol=1e-12)


def test_elastic_static_equilibrium_stays_put(spatial):
    """Unstretched lengths from the tensions of a static equilibrium (Eq. 2.15 solved for
    ``l0``): the platform released at rest does not move."""
    robot = with_stiffness(spatial, 2e4)
    q = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    tau = distribute_tensions(robot, q, method="qp").tensions
    l0 = unstretched_length(cable_lengths(robot, q), tau, 2e4)
    np.testing.assert_allclose(cable_tensions(robot, q, l0), tau, rtol=1e-12)
    res = forward_dynamics(robot, q, np.zeros(6), 1.0, lengths=lambda t: l0, **TIGHT)
    assert np.abs(res.poses - q).max() <= 1e-8
    assert not res.slack.any()
    np.testing.assert_allclose(res.tensions, np.broadcast_to(tau, res.tensions.shape), rtol=1e-6)


def test_slack_cable_pulls_nothing(spatial):
    """A cable whose commanded length exceeds its length is slack: zero tension, and the
    motion is that of the robot without it."""
    robot = with_stiffness(spatial, 2e4)
    q = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    tau = distribute_tensions(robot, q, method="qp").tensions
    l0 = unstretched_length(cable_lengths(robot, q), tau, 2e4)
    l0[0] += 0.1
    assert cable_tensions(robot, q, l0)[0] == 0.0
    res = forward_dynamics(robot, q, np.zeros(6), 0.1, lengths=lambda t: l0, times=np.linspace(0, 0.1, 11), **TIGHT)
    assert res.slack[:, 0].all() and (res.tensions[:, 0] == 0).all()
    assert np.abs(res.poses - q).max() > 1e-4  # it moves: the other cables are out of balance
    seven = robot.model_copy(update={"cables": robot.cables[1:]})
    ref = forward_dynamics(seven, q, np.zeros(6), 0.1, lengths=lambda t: l0[1:], times=np.linspace(0, 0.1, 11), **TIGHT)
    np.testing.assert_allclose(res.poses, ref.poses, atol=1e-10)
    np.testing.assert_allclose(res.tensions[:, 1:], ref.tensions, rtol=1e-7, atol=1e-7)


def elastic_energy(robot, q, qd, l0, ea):
    """Kinetic, gravitational and elastic energy: a stretched cable stores
    ``EA (l − l0)² / (2 l0)`` (the integral of ``τ = EA (l − l0)/l0``), a slack one nothing."""
    T, V, _, _ = spatial_state_quantities(robot, q, qd)
    stretch = np.maximum(cable_lengths(robot, q) - l0, 0.0)
    return T + V + float(np.sum(ea * stretch**2 / (2 * l0)))


@pytest.mark.slow
def test_rejected_trial_stages_do_not_stop_the_motion(spatial):
    """Stiff cables released slack: the platform falls and the cables catch it.  A trial stage
    of a step that the controller rejects lands far out of range (angles beyond 1e9); the
    motion goes on (it stopped there, "left the representable range", when the range was
    checked in the right-hand side) and is scipy's DOP853 on ``acceleration`` directly, a
    trial stage that ``acceleration`` refuses returning NaN so that its step is rejected; the
    energy is conserved (no damping)."""
    from scipy.integrate import solve_ivp

    ea = 1e5
    robot = with_stiffness(spatial, ea)
    q0 = np.array([0.05, -0.03, 0.08, 0.05, -0.04, 0.1])
    l0 = cable_lengths(robot, q0) * 1.01
    res = forward_dynamics(robot, q0, np.zeros(6), 0.5, lengths=lambda t: l0, times=np.linspace(0, 0.5, 51))
    refused = []

    def rhs(t, y):
        try:
            tau = cable_tensions(robot, y[:6], l0)
            return np.concatenate([y[6:], acceleration(robot, y[:6], y[6:], tau)])
        except TautError:
            refused.append(t)
            return np.full(12, np.nan)

    ref = solve_ivp(rhs, (0, 0.5), np.concatenate([q0, np.zeros(6)]), method="DOP853", rtol=1e-9, atol=1e-12)
    assert ref.success and refused  # trial stages were refused, and rejected
    assert res.slack[0].all() and not res.slack.all()  # released slack, then caught
    # measured 2e-8 and 7e-8: the two take slightly different steps (rtol 1e-9)
    np.testing.assert_allclose(res.poses[-1], ref.y[:6, -1], atol=1e-6)
    np.testing.assert_allclose(res.velocity[-1], ref.y[6:, -1], atol=1e-6)
    e0 = elastic_energy(robot, q0, np.zeros(6), l0, ea)
    for q, qd in zip(res.poses, res.velocity):
        assert abs(elastic_energy(robot, q, qd, l0, ea) - e0) <= 1e-7 * abs(e0)  # measured 3e-9


def test_elastic_rk4_matches_adaptive(spatial):
    robot = with_stiffness(spatial, 2e4)
    q = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    l0 = cable_lengths(robot, q) * (1 - 1e-3)
    ref = forward_dynamics(robot, q, np.zeros(6), 0.2, lengths=lambda t: l0, times=[0.2], **TIGHT)
    res = forward_dynamics(robot, q, np.zeros(6), 0.2, lengths=lambda t: l0, method="RK4", step=1e-4)
    assert np.abs(ref.poses[-1] - q).max() > 1e-4
    np.testing.assert_allclose(res.poses[-1], ref.poses[-1], atol=1e-7)


@pytest.mark.parametrize("method", ["RK45", "LSODA", "Radau"])
def test_other_integrators(method, planar):
    q0 = np.array([0.1, -0.05, 0.1])
    tau = distribute_tensions(planar, q0, method="qp").tensions
    res = forward_dynamics(planar, q0, np.zeros(3), 0.5, tensions=lambda t: tau, method=method, rtol=1e-10, atol=1e-12)
    assert np.abs(res.poses - q0).max() < 1e-6
    assert res.method == method and res.evaluations > 0
    assert not res.poses.flags.writeable


def test_gimbal_lock(spatial):
    q = np.array([0, 0, 0, 0.3, np.pi / 2, 0.1])
    with pytest.raises(SingularConfigurationError, match="gimbal lock"):
        acceleration(spatial, q, np.zeros(6), np.full(8, 10.0))
    with pytest.raises(IntegrationError, match="gimbal lock"):
        forward_dynamics(spatial, q, np.ones(6), 1.0, tensions=lambda t: np.zeros(8), **TIGHT)
    with pytest.raises(IntegrationError, match="gimbal lock"):
        forward_dynamics(spatial, q, np.ones(6), 1.0, tensions=lambda t: np.zeros(8), method="RK4", step=0.01)


def test_bad_input(spatial, no_inertia):
    q, z = np.zeros(6), np.zeros(6)
    zero = lambda t: np.zeros(8)  # noqa: E731
    with pytest.raises(TautError, match="exactly one"):
        forward_dynamics(spatial, q, z, 1.0)
    with pytest.raises(TautError, match="exactly one"):
        forward_dynamics(spatial, q, z, 1.0, tensions=zero, lengths=zero)
    with pytest.raises(TautError, match="unknown integrator"):
        forward_dynamics(spatial, q, z, 1.0, tensions=zero, method="Euler")
    with pytest.raises(TautError, match="duration"):
        forward_dynamics(spatial, q, z, -1.0, tensions=zero)
    with pytest.raises(TautError, match="step"):
        forward_dynamics(spatial, q, z, 1.0, tensions=zero, method="RK4")
    with pytest.raises(TautError, match="shape"):
        forward_dynamics(spatial, q, z, 1.0, tensions=lambda t: np.zeros(7))
    with pytest.raises(TautError, match="not finite"):
        forward_dynamics(spatial, q, z, 1.0, tensions=lambda t: np.full(8, np.nan))
    with pytest.raises(TautError, match="stiffness"):
        forward_dynamics(spatial, q, z, 1.0, lengths=lambda t: np.ones(8))
    with pytest.raises(TautError, match="positive"):
        cable_tensions(with_stiffness(spatial, 1e4), q, -np.ones(8))
    with pytest.raises(TautError):
        acceleration(spatial, q, z, np.zeros(7))
    with pytest.raises(TautError):
        acceleration(spatial, q, z[:5], np.zeros(8))
    with pytest.raises(TautError):
        acceleration(spatial, np.full(6, np.nan), z, np.zeros(8))
    with pytest.raises(TautError):
        rk4_step(spatial, q, z, np.zeros(8), 0.0)
    with pytest.raises(TautError):
        acceleration(no_inertia, q, z, np.zeros(8))


def test_swivelling_pulleys(spatial):
    """Cables through swivelling pulleys in the compiled kernels: the acceleration solves the
    Lagrange form with the structure matrix of the kinematics (tangent points), RK4 agrees
    with DOP853, and inverse dynamics balances the required wrench."""
    from taut.dynamics import bias_forces, generalized_forces, mass_matrix, required_wrench
    from taut.kinematics import structure_matrix

    robot = with_stiffness(
        spatial.model_copy(
            update={
                "cables": tuple(
                    c.model_copy(update={"swivel": {"axis": (0, 0, 1), "radius": 0.03}}) for c in spatial.cables
                )
            }
        ),
        2e4,
    )
    q = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    qd = np.array([0.1, 0.0, -0.1, 0.2, 0.1, 0.0])
    tau = distribute_tensions(robot, q, method="qp").tensions + 1.0
    W = structure_matrix(robot, q)
    want = np.linalg.solve(mass_matrix(robot, q), generalized_forces(robot, q, W @ tau) - bias_forces(robot, q, qd))
    np.testing.assert_allclose(acceleration(robot, q, qd, tau), want, rtol=1e-10, atol=1e-10)
    res = forward_dynamics(robot, q, qd, 0.05, tensions=lambda t: tau, method="RK4", step=1e-3)
    ref = forward_dynamics(robot, q, qd, 0.05, tensions=lambda t: tau, times=[0.05], **TIGHT)
    np.testing.assert_allclose(res.poses[-1], ref.poses[-1], atol=1e-10)
    l0 = cable_lengths(robot, q) * (1 - 1e-3)
    np.testing.assert_allclose(cable_tensions(robot, q, l0), 2e4 * (1 / (1 - 1e-3) - 1), rtol=1e-9)
    el = forward_dynamics(robot, q, qd, 0.01, lengths=lambda t: l0, method="RK4", step=1e-3)
    assert np.isfinite(el.poses).all() and (el.tensions > 0).all()
    ident = inverse_dynamics(robot, q, qd, np.zeros(6), method="qp")
    assert ident.feasible.all()
    np.testing.assert_allclose(W @ ident.tensions, required_wrench(robot, q, qd, np.zeros(6)), atol=1e-8)
