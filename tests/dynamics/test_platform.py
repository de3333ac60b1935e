"""Equations of motion (``taut.dynamics._platform``) against the Lagrangian computed here from
first principles: ``T = ½ m |v_c|² + ½ ωᵀ R I Rᵀ ω`` with ``v_c`` and ``ω`` from finite
differences of ``p_c(q(t))`` and ``R(q(t))``, ``V = −m gᵀ p_c``; the Euler–Lagrange
equations by finite differences.  Cable forces through virtual work: the generalized force of
the tensions is ``−(∂l/∂q)ᵀ τ`` with ``∂l/∂q`` from finite differences of the cable lengths."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taut
from taut.dynamics import (
    acceleration,
    bias_forces,
    coriolis_matrix,
    generalized_forces,
    gravity_forces,
    mass_matrix,
    velocity_jacobian,
)
from taut.dynamics._inverse import required_wrench
from taut.errors import PoseError, UnsupportedRobotError
from taut.geometry import planar_rotation, rotation_matrix
from taut.kinematics import cable_lengths, structure_matrix
from taut.statics import external_wrench

#: 4th-order central difference weights at offsets −2, −1, 1, 2 (times 1/h).
STENCIL = ((-2, 1 / 12), (-1, -8 / 12), (1, 8 / 12), (2, -1 / 12))


def derivative(f, h):
    """4th-order central difference of the scalar/array function ``f(s)`` at ``s = 0``."""
    return sum(c * np.asarray(f(k * h)) for k, c in STENCIL) / h


def rotation(robot, q):
    if robot.is_point_mass:
        return np.eye(3)
    R = np.eye(3)
    if robot.dimension == 2:
        R[:2, :2] = planar_rotation(q[2])
    else:
        R = rotation_matrix(q[3:6], robot.orientation)
    return R


def com(robot, q):
    """Centre of mass in the fixed frame (3-D)."""
    d = robot.dimension
    c = np.zeros(3)
    if robot.platform.wrench_point is not None and not robot.is_point_mass:
        c[:d] = robot.platform.wrench_point
    p = np.zeros(3)
    p[:d] = q[:d]
    return p + rotation(robot, q) @ c


def inertia3(robot):
    if robot.is_point_mass:
        return np.zeros((3, 3))
    if robot.dimension == 2:
        return np.diag([0.0, 0.0, robot.inertia[0, 0]])
    return robot.inertia


def kinetic(robot, q, qd, h=1e-3):
    """``T`` with ``v_c`` and ``ω`` from finite differences along ``q + s q̇``."""
    vc = derivative(lambda s: com(robot, q + s * qd), h)
    Rd = derivative(lambda s: rotation(robot, q + s * qd), h)
    R = rotation(robot, q)
    Om = Rd @ R.T
    omega = np.array([Om[2, 1], Om[0, 2], Om[1, 0]])
    m = robot.platform.mass
    return 0.5 * m * vc @ vc + 0.5 * omega @ R @ inertia3(robot) @ R.T @ omega


def potential(robot, q):
    g = np.zeros(3)
    g[: robot.dimension] = robot.weight
    return -g @ com(robot, q)


def lagrangian(robot, q, qd):
    return kinetic(robot, q, qd) - potential(robot, q)


def mass_matrix_fd(robot, q):
    """``M`` by polarization of the quadratic form ``T(q̇) = ½ q̇ᵀ M q̇``."""
    n = robot.pose_size
    E = np.eye(n)
    Tk = [kinetic(robot, q, E[i]) for i in range(n)]
    M = np.empty((n, n))
    for i in range(n):
        for j in range(n):
            M[i, j] = Tk[i] if i == j else 0.0
    for i in range(n):
        M[i, i] = 2 * Tk[i]
        for j in range(i):
            M[i, j] = M[j, i] = kinetic(robot, q, E[i] + E[j]) - Tk[i] - Tk[j]
    return M


def euler_lagrange(robot, q, qd, qdd, h=1e-3):
    """``d/dt ∂L/∂q̇ − ∂L/∂q`` along ``q(t) = q + t q̇ + ½ t² q̈`` by finite differences."""

    def momentum(t):
        qt, qdt = q + t * qd + 0.5 * t * t * qdd, qd + t * qdd
        return mass_matrix_fd(robot, qt) @ qdt

    n = robot.pose_size
    dL = np.array([derivative(lambda s, k=k: lagrangian(robot, q + s * np.eye(n)[k], qd), h) for k in range(n)])
    return derivative(momentum, h) - dL


ROBOTS = ["spatial", "planar", "point_mass", "spatial_centred", "planar_point"]


@pytest.mark.parametrize("name", ROBOTS)
def test_mass_matrix_is_the_kinetic_energy(name, request, random_state):
    robot = request.getfixturevalue(name)
    for _ in range(3):
        q, _, _ = random_state(robot)
        M = mass_matrix(robot, q)
        ref = mass_matrix_fd(robot, q)
        np.testing.assert_allclose(M, ref, rtol=0, atol=1e-9 * np.abs(ref).max())


@pytest.mark.parametrize("name", ROBOTS)
def test_equations_of_motion_are_euler_lagrange(name, request, random_state):
    """``M q̈ + C q̇ + g`` equals the Euler–Lagrange expression of ``L = T − V``."""
    robot = request.getfixturevalue(name)
    for _ in range(3):
        q, qd, qdd = random_state(robot)
        lhs = mass_matrix(robot, q) @ qdd + bias_forces(robot, q, qd)
        ref = euler_lagrange(robot, q, qd, qdd)
        np.testing.assert_allclose(lhs, ref, rtol=0, atol=1e-6 * max(np.abs(ref).max(), 1.0))


@pytest.mark.parametrize("orientation", ["xyz-fixed", "xyz-moving", "tilt-torsion"])
def test_every_orientation_convention(orientation, spatial, random_state):
    robot = spatial.model_copy(update={"orientation": orientation})
    q, qd, qdd = random_state(robot)
    q[4] += 0.6  # tilt-torsion is singular at θ = 0
    lhs = mass_matrix(robot, q) @ qdd + bias_forces(robot, q, qd)
    ref = euler_lagrange(robot, q, qd, qdd)
    np.testing.assert_allclose(lhs, ref, rtol=0, atol=1e-6 * np.abs(ref).max())


@pytest.mark.parametrize("name", ["spatial", "planar", "point_mass", "planar_point"])
def test_cable_generalized_forces_by_virtual_work(name, request, random_state, rng):
    """``Jᵀ W τ = −(∂l/∂q)ᵀ τ``: the moment rows of ``W`` pair with ``ω``, not with the angle
    rates, and ``velocity_jacobian`` converts them."""
    robot = request.getfixturevalue(name)
    q, _, _ = random_state(robot)
    tau = rng.uniform(1, 10, robot.n_cables)
    n = robot.pose_size
    dl = np.stack([derivative(lambda s, k=k: cable_lengths(robot, q + s * np.eye(n)[k]), 1e-4) for k in range(n)], 1)
    Q = generalized_forces(robot, q, structure_matrix(robot, q) @ tau)
    np.testing.assert_allclose(Q, -dl.T @ tau, rtol=1e-8, atol=1e-9)
    J = velocity_jacobian(robot, q)
    np.testing.assert_allclose(Q, J.T @ structure_matrix(robot, q) @ tau, rtol=1e-12)


@pytest.mark.parametrize("name", [*ROBOTS, "loaded"])
def test_gravity_is_the_statics_wrench(name, request, random_state):
    """``g(q) = −Jᵀ w₀`` with ``w₀`` the external wrench of the statics (weight and constant
    ``platform.wrench``), and ``∂V/∂q`` without a constant wrench."""
    robot = request.getfixturevalue(name)
    q, _, _ = random_state(robot)
    g = gravity_forces(robot, q)
    np.testing.assert_allclose(g, -velocity_jacobian(robot, q).T @ external_wrench(robot, q), atol=1e-12)
    if robot.platform.wrench is not None:
        return
    n = robot.pose_size
    dV = np.array([derivative(lambda s, k=k: potential(robot, q + s * np.eye(n)[k]), 1e-4) for k in range(n)])
    np.testing.assert_allclose(g, dV, atol=1e-8)


@settings(max_examples=40, deadline=None)
@given(
    pose=st.lists(st.floats(-0.3, 0.3), min_size=6, max_size=6),
    rates=st.lists(st.floats(-3, 3), min_size=6, max_size=6),
)
def test_mass_matrix_spd_and_skew_property(pose, rates):
    """``M`` symmetric positive definite away from the gimbal lock; ``Ṁ − 2C`` skew-symmetric
    with ``Ṁ`` by finite differences along ``q̇``; ``C q̇ + g`` is the bias."""
    robot = _SPATIAL
    q, qd = np.array(pose), np.array(rates)
    M = mass_matrix(robot, q)
    np.testing.assert_allclose(M, M.T, atol=1e-14)
    assert np.linalg.eigvalsh(M).min() > 0
    C = coriolis_matrix(robot, q, qd)
    Md = derivative(lambda s: mass_matrix(robot, q + s * qd), 1e-4)
    S = Md - 2 * C
    np.testing.assert_allclose(S, -S.T, atol=1e-8 * max(1.0, np.abs(Md).max()))
    np.testing.assert_allclose(C @ qd + gravity_forces(robot, q), bias_forces(robot, q, qd), atol=1e-12)


_PLATFORM = taut.example("spatial-8cable").platform.model_copy(
    update={"inertia": (0.12, 0.2, 0.15, 0.01, -0.02, 0.005), "wrench_point": (0.02, -0.01, 0.03)}
)
_SPATIAL = taut.example("spatial-8cable").model_copy(update={"platform": _PLATFORM})


def test_planar_skew_property(planar, random_state):
    q, qd, _ = random_state(planar)
    Md = derivative(lambda s: mass_matrix(planar, q + s * qd), 1e-4)
    S = Md - 2 * coriolis_matrix(planar, q, qd)
    np.testing.assert_allclose(S, -S.T, atol=1e-9)


@pytest.mark.parametrize("name", [*ROBOTS, "loaded"])
def test_acceleration_solves_the_lagrange_form(name, request, random_state, rng):
    """The compiled Newton–Euler solution equals ``M⁻¹ (Jᵀ (W τ + w_ext) − h)``, for one state
    and a batch."""
    robot = request.getfixturevalue(name)
    states = [random_state(robot) for _ in range(5)]
    Q = np.array([s[0] for s in states])
    QD = np.array([s[1] for s in states])
    tau = rng.uniform(1, 20, (5, robot.n_cables))
    w = rng.normal(0, 3, (5, robot.pose_size))
    A = acceleration(robot, Q, QD, tau, wrench=w)
    for k in range(5):
        M = mass_matrix(robot, Q[k])
        rhs = generalized_forces(robot, Q[k], structure_matrix(robot, Q[k]) @ tau[k] + w[k]) - bias_forces(
            robot, Q[k], QD[k]
        )
        np.testing.assert_allclose(A[k], np.linalg.solve(M, rhs), rtol=1e-10, atol=1e-10)
        np.testing.assert_allclose(acceleration(robot, Q[k], QD[k], tau[k], wrench=w[k]), A[k], rtol=1e-13, atol=1e-13)


@pytest.mark.parametrize("name", [*ROBOTS, "loaded"])
def test_required_wrench_is_the_inverse_of_acceleration(name, request, random_state):
    """Newton–Euler inverse dynamics: ``Jᵀ (required wrench) = M q̈ + h`` and at rest it is
    minus the statics' external wrench."""
    robot = request.getfixturevalue(name)
    q, qd, qdd = random_state(robot)
    w = required_wrench(robot, q, qd, qdd)
    np.testing.assert_allclose(
        generalized_forces(robot, q, w), mass_matrix(robot, q) @ qdd + bias_forces(robot, q, qd), atol=1e-10
    )
    zero = np.zeros(robot.pose_size)
    np.testing.assert_allclose(required_wrench(robot, q, zero, zero), -external_wrench(robot, q), atol=1e-12)


def test_robots_without_mass_data_are_refused(no_inertia):
    with pytest.raises(UnsupportedRobotError, match="inertia"):
        mass_matrix(no_inertia, np.zeros(6))
    with pytest.raises(UnsupportedRobotError, match="mass"):
        mass_matrix(taut.example("suspended-3cable"), np.zeros(6))
    adjustable = taut.example("adjustable-8cable")
    massless = adjustable.model_copy(
        update={
            "platform": adjustable.platform.model_copy(update={"mass": None, "inertia": None, "wrench_point": None})
        }
    )
    with pytest.raises(UnsupportedRobotError, match="platform.mass"):
        mass_matrix(massless, np.r_[np.zeros(6), 1.0])


def test_singular_inertia_is_refused():
    base = taut.example("spatial-8cable")
    robot = base.model_copy(update={"platform": base.platform.model_copy(update={"inertia": (0.1, 0.1, 0.0, 0, 0, 0)})})
    with pytest.raises(UnsupportedRobotError, match="singular"):
        acceleration(robot, np.zeros(6), np.zeros(6), np.full(8, 10.0))


def test_bad_shapes(spatial):
    with pytest.raises(PoseError):
        mass_matrix(spatial, np.zeros(5))
    with pytest.raises(PoseError):
        bias_forces(spatial, np.zeros(6), np.zeros(4))
    with pytest.raises(PoseError):
        bias_forces(spatial, np.zeros((3, 6)), np.zeros((2, 6)))
    with pytest.raises(PoseError):
        bias_forces(spatial, np.zeros(6), np.full(6, np.nan))


def test_batches_match_single_poses(spatial, rng):
    Q = rng.uniform(-0.2, 0.2, (4, 6))
    QD = rng.normal(0, 1, (4, 6))
    M, h = mass_matrix(spatial, Q), bias_forces(spatial, Q, QD)
    assert M.shape == (4, 6, 6) and h.shape == (4, 6)
    for k in range(4):
        np.testing.assert_allclose(M[k], mass_matrix(spatial, Q[k]), rtol=1e-14)
        np.testing.assert_allclose(h[k], bias_forces(spatial, Q[k], QD[k]), rtol=1e-14)


@settings(max_examples=40, deadline=None)
@given(
    pose=st.lists(st.floats(-0.25, 0.25), min_size=6, max_size=6),
    rates=st.lists(st.floats(-2, 2), min_size=6, max_size=6),
    accelerations=st.lists(st.floats(-3, 3), min_size=6, max_size=6),
)
def test_inverse_then_forward_is_the_identity(pose, rates, accelerations):
    """At any state, the tensions of the inverse dynamics for ``q̈`` give back ``q̈`` through
    the forward dynamics (when they are admissible)."""
    from taut.dynamics import inverse_dynamics

    q, qd, qdd = np.array(pose), np.array(rates), np.array(accelerations)
    res = inverse_dynamics(_SPATIAL, q, qd, qdd, method="qp")
    if res.feasible:
        np.testing.assert_allclose(acceleration(_SPATIAL, q, qd, res.tensions), qdd, atol=1e-7)
    else:
        assert res.status == "infeasible"
