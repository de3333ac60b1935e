"""Equations of motion of jointed platforms (``taut.dynamics._jointed`` through ``mass_matrix``,
``bias_forces``, ``gravity_forces``, ``generalized_forces``) checked against MuJoCo's (the
robots exported by ``taut.model._mjcf``), against the Lagrangian by finite differences of
taut's body frames, and against the jointed statics and cable lengths."""

import numpy as np
import pytest
from jointed_robots import ROBOTS, adjustable

from taut.dynamics import (
    bias_forces,
    coriolis_matrix,
    generalized_forces,
    gravity_forces,
    mass_matrix,
    velocity_jacobian,
)
from taut.errors import UnsupportedRobotError
from taut.geometry import rate_matrix, rate_matrix_derivative, rotation_matrix
from taut.kinematics import body_frames, inverse_kinematics, joint_forces, jointed_structure_matrix
from taut.statics import external_wrench


def random_poses(robot, n, rng, spread=0.5, tilt=1.0):
    """Platform poses around the centre of the exit points, angles within ``tilt``, joint
    coordinates strictly inside their limits."""
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    d = robot.dimension
    pos = (lo + hi) / 2 + spread * (hi - lo) / 2 * rng.uniform(-1, 1, (n, d))
    ang = rng.uniform(-tilt, tilt, (n, robot.wrench_dim - d))
    limits = robot.joint_limits
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.uniform(1e-3, 1 - 1e-3, (n, robot.n_joints))
    return np.concatenate([pos, ang, q], axis=1)


def velocity_map(robot, model, q, qd):
    """``T`` and ``Ṫ q̇`` with MuJoCo's ``qvel = T q̇``: the freejoint takes ``ṗ`` and the
    angular velocity in the body frame ``Rᵀ E φ̇``, each joint its coordinate's rate
    (``d/dt (Rᵀ E) = Rᵀ (Ė − [ω]× E)`` with ``ω = E φ̇``)."""
    mujoco = pytest.importorskip("mujoco")
    P, m = robot.pose_size, robot.wrench_dim
    T, Td = np.zeros((model.nv, P)), np.zeros((model.nv, P))
    T[:m, :m] = np.eye(m)
    if robot.dimension == 3:
        R = rotation_matrix(q[3:6], robot.orientation)
        E = rate_matrix(q[3:6], robot.orientation)
        w = E @ qd[3:6]
        W = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        T[3:6, 3:6] = R.T @ E
        Td[3:6, 3:6] = R.T @ (rate_matrix_derivative(q[3:6], qd[3:6], robot.orientation) - W @ E)
    for k in range(1, robot.n_joints + 1):
        T[model.jnt_dofadr[mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, f"joint{k}")], m + k - 1] = 1.0
    return T, Td @ qd


@pytest.mark.parametrize("name", list(ROBOTS))
def test_mass_matrix_and_bias_forces_are_mujoco_s(name):
    """At 50 random poses and velocities ``M = Tᵀ M_mj T`` (MuJoCo's ``mj_fullM``) and
    ``h = Tᵀ (M_mj Ṫ q̇ + qfrc_bias)`` (gravity included) with ``qvel = T q̇``.  Measured
    (MuJoCo 4.0.0): 6e-15 relative for ``M``, 4e-15 for ``h``."""
    mujoco = pytest.importorskip("mujoco")
    from taut.model import mjcf_text, pose_to_qpos

    robot = ROBOTS[name]()
    rng = np.random.default_rng(40)
    poses = random_poses(robot, 50, rng)
    rates = rng.normal(0, 1, poses.shape)
    M, h = mass_matrix(robot, poses), bias_forces(robot, poses, rates)
    model = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    data = mujoco.MjData(model)
    worst_M = worst_h = 0.0
    full = np.zeros((model.nv, model.nv))
    for k, qpos in enumerate(pose_to_qpos(robot, poses)):
        T, Tdqd = velocity_map(robot, model, poses[k], rates[k])
        data.qpos[:], data.qvel[:] = qpos, T @ rates[k]
        mujoco.mj_forward(model, data)
        mujoco.mj_fullM(model, data, full)
        M_mj = T.T @ full @ T
        h_mj = T.T @ (full @ Tdqd + data.qfrc_bias)
        worst_M = max(worst_M, np.abs(M[k] - M_mj).max() / np.abs(M_mj).max())
        worst_h = max(worst_h, np.abs(h[k] - h_mj).max() / np.abs(h_mj).max())
    assert worst_M < 1e-12, worst_M
    assert worst_h < 1e-12, worst_h


def frames_of(robot, q):
    """Centres of mass ``(B, 3)`` and rotations ``(B, 3, 3)`` of all bodies from taut's
    kinematics (``body_frames``), in 3-D."""
    pos, rot = body_frames(robot, q[None])
    d = robot.dimension
    R = np.broadcast_to(np.eye(3), (pos.shape[1], 3, 3)).copy()
    R[:, :d, :d] = rot[0]
    com0 = np.zeros(d) if robot.platform.wrench_point is None else np.array(robot.platform.wrench_point)
    coms = np.concatenate([com0[None], robot.body_coms])
    c = pos[0] + np.einsum("bij,bj->bi", rot[0], coms)
    return np.pad(c, ((0, 0), (0, 3 - d))), R


def inertia_data(robot):
    """Masses, inertia tensors ``(B, 3, 3)`` (body frames) and weights ``(B, 3)``."""
    plat = robot.platform
    masses = np.array([plat.mass] + [b.mass for b in plat.bodies])
    tensors = []
    for values in [plat.inertia] + [b.inertia for b in plat.bodies]:
        if robot.dimension == 2:
            tensors.append(np.diag([0.0, 0.0, values[0]]))
        else:
            xx, yy, zz, xy, xz, yz = values
            tensors.append(np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]))
    g = np.pad(robot.gravity, (0, 3 - robot.dimension))
    return masses, np.array(tensors), masses[:, None] * g


def lagrangian_mass_matrix(robot, q, step=1e-6):
    """``M = Σ m J_cᵀ J_c + J_ωᵀ I J_ω`` with the Jacobians of the centres of mass and of the
    rotations (``[ω]× = Ṙ Rᵀ``) by central differences of ``body_frames`` along each coordinate."""
    masses, tensors, _ = inertia_data(robot)
    P = robot.pose_size
    c0, R0 = frames_of(robot, q)
    Jc, Jw = np.zeros((len(masses), 3, P)), np.zeros((len(masses), 3, P))
    for i in range(P):
        e = np.zeros(P)
        e[i] = step
        cp, Rp = frames_of(robot, q + e)
        cm, Rm = frames_of(robot, q - e)
        Jc[:, :, i] = (cp - cm) / (2 * step)
        S = (Rp - Rm) / (2 * step) @ np.swapaxes(R0, 1, 2)
        Jw[:, :, i] = np.stack([S[:, 2, 1], S[:, 0, 2], S[:, 1, 0]], axis=1)
    Iw = R0 @ tensors @ np.swapaxes(R0, 1, 2)
    return np.einsum("b,bip,biq->pq", masses, Jc, Jc) + np.einsum("bip,bij,bjq->pq", Jw, Iw, Jw)


def potential(robot, q):
    _, _, weights = inertia_data(robot)
    return -np.sum(weights * frames_of(robot, q)[0])


@pytest.mark.parametrize("name", ["adjustable-8cable", "branching tree", "planar slider and arm"])
def test_lagrangian_by_finite_differences(name):
    """Without MuJoCo: ``M`` is the Lagrangian's (Jacobians of taut's body frames by central
    differences; measured 3e-10 relative), and ``h = Ṁ q̇ − ½ ∂(q̇ᵀ M q̇)/∂q + ∂V/∂q``
    (Christoffel symbols of taut's ``M`` and the potential of the weights, by central
    differences) is ``bias_forces`` (measured 1e-10 relative, ``g`` 7e-11); ``M`` is
    symmetric positive definite."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(41)
    step = 1e-5
    for q in random_poses(robot, 5, rng, tilt=0.6):
        qd = rng.normal(0, 1, q.shape)
        M = mass_matrix(robot, q)
        assert np.abs(M - M.T).max() <= 1e-13 * np.abs(M).max()
        assert np.linalg.eigvalsh(M).min() > 0
        M_fd = lagrangian_mass_matrix(robot, q)
        assert np.abs(M - M_fd).max() < 1e-8 * np.abs(M).max()
        Mdot = (mass_matrix(robot, q + step * qd) - mass_matrix(robot, q - step * qd)) / (2 * step)
        dT, dV = np.zeros(q.size), np.zeros(q.size)
        for i in range(q.size):
            e = np.zeros(q.size)
            e[i] = step
            dT[i] = qd @ (mass_matrix(robot, q + e) - mass_matrix(robot, q - e)) @ qd / (4 * step)
            dV[i] = (potential(robot, q + e) - potential(robot, q - e)) / (2 * step)
        expected = Mdot @ qd - dT + dV
        h = bias_forces(robot, q, qd)
        assert np.abs(h - expected).max() < 1e-8 * np.abs(expected).max(), np.abs(h - expected).max()
        assert np.allclose(gravity_forces(robot, q), dV, rtol=0, atol=1e-8 * np.abs(dV).max())
        assert np.allclose(bias_forces(robot, q, np.zeros(q.size)), gravity_forces(robot, q), rtol=0, atol=1e-12)


@pytest.mark.parametrize("name", list(ROBOTS))
def test_generalized_forces_of_the_jointed_statics(name):
    """At rest the cables' generalized forces ``Tᵀ A[:, :n] τ`` (``generalized_forces`` of the
    jointed structure matrix's rows) are ``−(∂l/∂q)ᵀ τ`` by virtual work (central differences
    of the cable lengths over the pose coordinates), and ``gravity_forces`` is
    ``−Tᵀ (w_ext, −ζ₀)``: the statics' external wrench (the bodies' weights included) and the
    joint forces ``ζ₀`` that hold the bodies' weights without cables."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(42)
    n, m, step = robot.n_cables, robot.wrench_dim, 1e-6
    for q in random_poses(robot, 5, rng):
        tau = rng.uniform(10, 100, n)
        A = jointed_structure_matrix(robot, q)
        Q = generalized_forces(robot, q, A[:, :n] @ tau)
        dl = np.zeros((n, q.size))
        for i in range(q.size):
            e = np.zeros(q.size)
            e[i] = step
            dl[:, i] = (inverse_kinematics(robot, q + e).lengths - inverse_kinematics(robot, q - e).lengths) / (
                2 * step
            )
        assert np.abs(Q + dl.T @ tau).max() < 1e-7 * np.abs(Q).max()
        load = np.concatenate([external_wrench(robot, q), -joint_forces(robot, q, np.zeros(n))])
        T = velocity_jacobian(robot, q)
        assert np.abs(gravity_forces(robot, q) + T.T @ load).max() < 1e-12 * max(1.0, np.abs(load).max())
        assert np.allclose(generalized_forces(robot, q, load), T.T @ load, rtol=0, atol=1e-12)
        assert T.shape == (robot.pose_size, robot.pose_size) and np.allclose(T[m:, m:], np.eye(robot.n_joints))


def test_bodies_without_mass_or_inertia_are_refused_by_name():
    robot = adjustable()
    upper = robot.platform.bodies[0]
    q = random_poses(robot, 1, np.random.default_rng(43))[0]
    # the robot file refuses a com or inertia without a mass
    for fields, word in [(("mass", "com", "inertia"), "no mass"), (("inertia",), "no inertia")]:
        body = upper.model_copy(update=dict.fromkeys(fields))
        bare = robot.model_copy(update={"platform": robot.platform.model_copy(update={"bodies": (body,)})})
        with pytest.raises(UnsupportedRobotError, match=rf"platform.bodies\[1\] \(upper\) has {word}"):
            mass_matrix(bare, q)
        with pytest.raises(UnsupportedRobotError, match=word):
            bias_forces(bare, q, np.zeros(q.size))


@pytest.mark.parametrize("name", ["adjustable-8cable", "branching tree", "planar slider and arm"])
def test_coriolis_matrix_factorizes_the_bias_with_a_skew_symmetric_remainder(name):
    """``C q̇ + g = h`` (``h`` checked against MuJoCo above), ``C`` is linear in ``q̇``, and
    ``Ṁ − 2 C`` is skew-symmetric with ``Ṁ`` by central differences of ``M`` along ``q̇``
    (measured: 3e-16 relative for ``C q̇ + g − h``, 7e-10 for the symmetric part)."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(45)
    step = 1e-5
    for q in random_poses(robot, 5, rng, tilt=0.6):
        qd, other = rng.normal(0, 1, (2, q.size))
        C = coriolis_matrix(robot, q, qd)
        h = bias_forces(robot, q, qd)
        assert np.abs(C @ qd + gravity_forces(robot, q) - h).max() < 1e-12 * np.abs(h).max()
        both = coriolis_matrix(robot, q, qd + 2 * other)
        assert np.abs(both - C - 2 * coriolis_matrix(robot, q, other)).max() < 1e-12 * np.abs(both).max()
        Mdot = (mass_matrix(robot, q + step * qd) - mass_matrix(robot, q - step * qd)) / (2 * step)
        N = Mdot - 2 * C
        assert np.abs(N + N.T).max() < 1e-8 * np.abs(N).max()
