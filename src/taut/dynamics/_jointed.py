"""Equations of motion of a platform carrying jointed bodies, in taut's pose coordinates.

The pose ``q = (p, φ, q_J)`` of a robot with ``platform.bodies`` holds the platform pose and
the joint coordinates (:mod:`taut.kinematics._jointed`).  Its twist coordinates
``X = (ṗ, ω, q̇_J)`` — the velocity of the reference point ``p``, the platform's angular
velocity in the fixed frame and the joint rates, the columns of the jointed structure matrix —
are ``X = T q̇`` with ``T = diag(1, E(φ), 1)`` (:mod:`taut.geometry._rates`; planar: ``T = 1``).

Each body ``b`` (0 the platform, ``k`` the ``k``-th of ``platform.bodies``) with mass
``m_b``, centre of mass ``c_b`` and inertia ``I_b`` about it (body frame, rotation ``R_b``)
has the twist ``(ċ_b, ω_b) = J_b X`` in the fixed frame: a platform column ``e_i`` of ``ṗ``
gives ``(e_i, 0)``, a column ``a`` of ``ω`` gives ``(a × (c_b − p), a)``, and a joint ``j``
between the platform and ``b`` with unit axis ``e_j`` (in the fixed frame) through the
origin ``o_j`` of its child gives ``(e_j, 0)`` (prismatic) or ``(e_j × (c_b − o_j), e_j)``
(revolute; planar: about ``+z``).  Then (Siciliano et al. 2009, §7.2, Eqs. 7.15–7.17, and
§7.1.2 for the kinetic energy of a link)

    ``M_X = Σ_b J_bᵀ diag(m_b 1, R_b I_b R_bᵀ) J_b``,
    ``h_X = Σ_b J_bᵀ (m_b a_b, I_b^w α_b + ω_b × I_b^w ω_b) − Σ_b J_bᵀ (F_b, n_b)``,

with ``(a_b, α_b) = J̇_b X`` the accelerations of the centres of mass and the angular
accelerations at ``Ẋ = 0``, computed exactly by the recursion from the platform outwards
(for body ``k`` with parent ``P``, ``d = o_k − o_P``, ``ė_k = ω_P × e_k``):

    ``ω_k = ω_P + e_k q̇_k`` (revolute),  ``ḋ = ω_P × d + e_k q̇_k`` (prismatic),
    ``α_k = α_P + ė_k q̇_k`` (revolute),  ``ö_k = ö_P + α_P × d + ω_P × ḋ + ė_k q̇_k`` (prismatic),
    ``a_k = ö_k + α_k × ρ_k + ω_k × (ω_k × ρ_k)``,  ``ρ_k = c_k − o_k``,

starting from the platform's ``α_0 = 0``, ``ö_0 = 0`` at ``o_0 = p``.  ``F_b`` is the body's
weight (the platform's also its constant ``platform.wrench`` force) and ``n_b`` the
platform's constant moment.  In the pose coordinates, with ``Ẋ = T q̈ + Ṫ q̇``,

    ``M(q) q̈ + h(q, q̇) = Tᵀ Q_X``,  ``M = Tᵀ M_X T``,  ``h = Tᵀ (h_X + M_X Ṫ q̇)``,

and ``h = C q̇ + g`` with ``C = Tᵀ (M_X Ṫ + C_X T)``,
``C_X = Σ_b J_bᵀ (m_b J̇_v, I_b^w J̇_ω + [ω_b]× I_b^w J_ω)`` (``J_b = (J_v, J_ω)``), for which
``Ṁ − 2 C`` is skew-symmetric (Siciliano et al. 2009, §7.2.1); ``J̇_b`` differentiates the
columns above (``ė_j = ω_P × e_j``, and the velocities of ``c_b`` and ``o_j``).  Here
``Q_X`` are generalized forces in twist coordinates — the rows of the jointed structure
matrix ``A`` times ``(τ, ζ)`` (:func:`taut.kinematics.jointed_structure_matrix`: its
platform rows are ``W τ``, a wrench about ``p``, its joint rows forces along and torques
about the joint axes), plus an external wrench on the platform.  At rest (``q̇ = q̈ = 0``,
``h = g``) and with ``T`` regular the equations are the jointed statics
``A (τ, ζ) + Q_ext = 0`` of :func:`taut.kinematics.joint_forces`, ``g = −Tᵀ Q_ext``.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §7.1–7.2 (Lagrange formulation with link Jacobians).
   (docs/references.bib: siciliano2009)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.2–3.3, Eqs. 3.2.12 and
   3.3.7–3.3.12. (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taut.errors import UnsupportedRobotError
from taut.geometry import rate_matrix, rate_matrix_derivative
from taut.kinematics import body_frames
from taut.model import Robot

__all__ = [
    "BodyInertia",
    "BodyMotion",
    "body_inertia",
    "body_jacobians",
    "body_motion",
    "jointed_bias_forces",
    "jointed_coriolis_matrix",
    "jointed_gravity_forces",
    "jointed_mass_matrix",
    "twist_jacobian",
    "twist_jacobian_rate",
]


@dataclass(frozen=True)
class BodyInertia:
    """The inertial data of a jointed platform's bodies, body 0 being the platform, in 3-D
    (a planar robot's embedded in ``z = 0``)."""

    masses: np.ndarray  #: ``(B,)``
    coms: np.ndarray  #: ``(B, 3)`` centres of mass in the body frames
    inertias: np.ndarray  #: ``(B, 3, 3)`` about the centres of mass, body frames (planar: ``Izz`` only)
    forces: np.ndarray  #: ``(B, 3)`` constant forces at the centres of mass (weights, platform.wrench)
    moment: np.ndarray  #: ``(3,)`` the platform's constant moment (platform.wrench)


def _tensor(robot: Robot, values: tuple[float, ...]) -> np.ndarray:
    out = np.zeros((3, 3))
    if robot.dimension == 2:
        out[2, 2] = values[0]
        return out
    xx, yy, zz, xy, xz, yz = values
    return np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]], dtype=float)


def _in_space(values: np.ndarray) -> np.ndarray:
    """Vectors ``(..., d)`` as ``(..., 3)``."""
    out = np.zeros(values.shape[:-1] + (3,))
    out[..., : values.shape[-1]] = values
    return out


def body_inertia(robot: Robot) -> BodyInertia:
    """The masses, centres of mass, inertias and constant loads of the platform and its bodies.

    A body without mass and inertia that carries other bodies is a massless frame between two
    joints (the chain of a universal or spherical joint): it gets zero mass and inertia.

    Raises
    ------
    UnsupportedRobotError
        When the platform or one of ``platform.bodies`` that carries no other body has no
        ``mass`` or no ``inertia`` (bodies are numbered from 1, as in the robot file's checks),
        or the platform's inertia is not positive definite."""
    plat, d = robot.platform, robot.dimension
    if plat.mass is None:
        raise UnsupportedRobotError(f"{robot.name}: the dynamics needs the platform's mass (platform.mass)")
    if plat.inertia is None:
        raise UnsupportedRobotError(
            f"{robot.name}: the dynamics of a rigid platform needs its inertia (platform.inertia, "
            "about the centre of mass platform.wrench_point)"
        )
    tensors = [_tensor(robot, plat.inertia)]
    if np.linalg.eigvalsh(tensors[0]).max() <= 0 or (d == 3 and np.linalg.eigvalsh(tensors[0]).min() <= 0):
        raise UnsupportedRobotError(
            f"{robot.name}: platform.inertia {list(plat.inertia)} is singular: a rigid platform needs a positive definite inertia"
        )
    parents = {b.parent for b in plat.bodies}
    for k, body in enumerate(plat.bodies, 1):
        what = f"platform.bodies[{k}] ({body.name})"
        if body.mass is None and body.inertia is None and body.name in parents:
            # a frame between two joints of a chain (a universal or spherical joint's): it
            # carries the bodies beyond it and nothing of its own
            tensors.append(np.zeros((3, 3)))
            continue
        if body.mass is None or body.inertia is None:
            missing = "mass" if body.mass is None else "inertia"
            raise UnsupportedRobotError(
                f"{robot.name}: the dynamics of a jointed platform needs every body's mass, com and inertia: "
                f"{what} has no {missing}"
            )
        tensors.append(_tensor(robot, body.inertia))
    load = np.zeros(robot.wrench_dim) if plat.wrench is None else np.asarray(plat.wrench, dtype=float)
    forces = np.concatenate([(robot.weight + load[:d])[None], robot.body_weights], axis=0)
    moment = np.zeros(3)
    if d == 2:
        moment[2] = load[2]
    else:
        moment[:] = load[3:]
    com0 = np.zeros(d) if plat.wrench_point is None else np.asarray(plat.wrench_point, dtype=float)
    return BodyInertia(
        masses=np.array([plat.mass] + [b.mass or 0.0 for b in plat.bodies], dtype=float),
        coms=_in_space(np.concatenate([com0[None], robot.body_coms], axis=0)),
        inertias=np.stack(tensors),
        forces=_in_space(forces),
        moment=moment,
    )


@dataclass(frozen=True)
class BodyMotion:
    """Jacobians and, at a velocity, the velocity-product accelerations of every body."""

    jacobians: np.ndarray  #: ``(N, B, 6, P)``: ``(ċ_b, ω_b) = J_b X``
    rotations: np.ndarray  #: ``(N, B, 3, 3)``
    omegas: np.ndarray  #: ``(N, B, 3)`` angular velocities (zero without a velocity)
    accelerations: np.ndarray  #: ``(N, B, 6)`` ``J̇_b X``: ``(a_b, α_b)`` (zero without a velocity)
    rates: np.ndarray  #: ``(N, B, 6, P)`` ``J̇_b`` (zero without a velocity)


def _frames(robot: Robot, arr: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    pos, rot = body_frames(robot, arr)
    N, B = pos.shape[:2]
    R = np.broadcast_to(np.eye(3), (N, B, 3, 3)).copy()
    R[..., : robot.dimension, : robot.dimension] = rot
    return _in_space(pos), R


def _axes(robot: Robot, R: np.ndarray) -> tuple[np.ndarray, list[int], list[bool]]:
    """Unit joint axes in the fixed frame ``(N, n_joints, 3)``, parents, and which are revolute."""
    index = {"platform": 0} | {b.name: k for k, b in enumerate(robot.platform.bodies, 1)}
    parents = [index[b.parent] for b in robot.platform.bodies]
    revolute = [b.joint.kind == "revolute" for b in robot.platform.bodies]
    axes = np.zeros((R.shape[0], robot.n_joints, 3))
    for k, body in enumerate(robot.platform.bodies):
        if revolute[k] and robot.dimension == 2:
            axes[:, k, 2] = 1.0
            continue
        axis = _in_space(np.asarray(body.joint.axis, dtype=float))
        axes[:, k] = R[:, parents[k]] @ (axis / np.linalg.norm(axis))
    return axes, parents, revolute


def body_motion(robot: Robot, arr: np.ndarray, X: np.ndarray | None = None) -> BodyMotion:
    """:class:`BodyMotion` at poses ``arr (N, P)`` and, if given, twist coordinates ``X (N, P)``
    (the recursion of the module's docstring)."""
    inertia = body_inertia(robot)
    pos, R = _frames(robot, arr)
    N, B, d, m = arr.shape[0], robot.n_joints + 1, robot.dimension, robot.wrench_dim
    axes, parents, revolute = _axes(robot, R)
    coms = pos + np.einsum("nbij,bj->nbi", R, inertia.coms)
    rot_axes = np.eye(3) if d == 3 else np.eye(3)[2:]
    J = np.zeros((N, B, 6, arr.shape[1]))
    for i in range(d):
        J[:, :, i, i] = 1.0
    for c, a in enumerate(rot_axes):
        J[:, :, :3, d + c] = np.cross(a, coms - pos[:, :1])
        J[:, :, 3:, d + c] = a
    chains: list[list[int]] = [[]]
    for k in range(1, B):
        chains.append([k] + chains[parents[k - 1]])
        for j in chains[k]:
            col = m + j - 1
            if revolute[j - 1]:
                J[:, k, :3, col] = np.cross(axes[:, j - 1], coms[:, k] - pos[:, j])
                J[:, k, 3:, col] = axes[:, j - 1]
            else:
                J[:, k, :3, col] = axes[:, j - 1]
    omegas, acc, rates = np.zeros((N, B, 3)), np.zeros((N, B, 6)), np.zeros_like(J)
    if X is not None:
        omegas[:, 0] = X[:, d:m] @ rot_axes
        alphas, origin_acc, origin_vel = np.zeros((N, B, 3)), np.zeros((N, B, 3)), np.zeros((N, B, 3))
        origin_vel[:, 0, :d] = X[:, :d]
        for k in range(1, B):
            P, e, qd = parents[k - 1], axes[:, k - 1], X[:, m + k - 1 : m + k]
            arm = pos[:, k] - pos[:, P]
            e_rate = np.cross(omegas[:, P], e)
            arm_rate = np.cross(omegas[:, P], arm)
            omegas[:, k], alphas[:, k] = omegas[:, P], alphas[:, P]
            origin_acc[:, k] = origin_acc[:, P] + np.cross(alphas[:, P], arm)
            if revolute[k - 1]:
                omegas[:, k] = omegas[:, k] + e * qd
                alphas[:, k] = alphas[:, k] + e_rate * qd
            else:
                arm_rate = arm_rate + e * qd
                origin_acc[:, k] = origin_acc[:, k] + e_rate * qd
            origin_acc[:, k] = origin_acc[:, k] + np.cross(omegas[:, P], arm_rate)
            origin_vel[:, k] = origin_vel[:, P] + arm_rate
        rho = coms - pos
        acc[..., :3] = origin_acc + np.cross(alphas, rho) + np.cross(omegas, np.cross(omegas, rho))
        acc[..., 3:] = alphas
        com_vel = origin_vel + np.cross(omegas, rho)
        for c, a in enumerate(rot_axes):
            rates[:, :, :3, d + c] = np.cross(a, com_vel - origin_vel[:, :1])
        for k in range(1, B):
            for j in chains[k]:
                col, e = m + j - 1, axes[:, j - 1]
                e_rate = np.cross(omegas[:, parents[j - 1]], e)
                if revolute[j - 1]:
                    rates[:, k, :3, col] = np.cross(e_rate, coms[:, k] - pos[:, j]) + np.cross(
                        e, com_vel[:, k] - origin_vel[:, j]
                    )
                    rates[:, k, 3:, col] = e_rate
                else:
                    rates[:, k, :3, col] = e_rate
    return BodyMotion(jacobians=J, rotations=R, omegas=omegas, accelerations=acc, rates=rates)


def twist_jacobian(robot: Robot, arr: np.ndarray) -> np.ndarray:
    """``T (N, P, P)`` with ``X = T q̇``: ``diag(1, E(φ), 1)`` (planar: the identity)."""
    P, d = robot.pose_size, robot.dimension
    T = np.broadcast_to(np.eye(P), (arr.shape[0], P, P)).copy()
    if d == 3:
        T[:, 3:6, 3:6] = rate_matrix(arr[:, 3:6], robot.orientation)
    return T


def twist_jacobian_rate(robot: Robot, arr: np.ndarray, qd: np.ndarray) -> np.ndarray:
    """``Ṫ (N, P, P)``."""
    P = robot.pose_size
    Td = np.zeros((arr.shape[0], P, P))
    if robot.dimension == 3:
        Td[:, 3:6, 3:6] = rate_matrix_derivative(arr[:, 3:6], qd[:, 3:6], robot.orientation)
    return Td


def body_jacobians(robot: Robot, arr: np.ndarray) -> np.ndarray:
    """``J_b T`` ``(N, B, 6, P)``: ``(ċ_b, ω_b)`` of every body (0 the platform) from the pose
    rates ``q̇``, in the fixed frame (3-D; a planar robot's in ``z = 0``)."""
    return body_motion(robot, arr).jacobians @ twist_jacobian(robot, arr)[:, None]


def _twist_inertias(robot: Robot, motion: BodyMotion) -> tuple[np.ndarray, np.ndarray]:
    """``M_X (N, P, P)`` and the bodies' inertias in the fixed frame ``(N, B, 3, 3)``."""
    inertia = body_inertia(robot)
    R = motion.rotations
    Iw = R @ inertia.inertias @ np.swapaxes(R, -1, -2)
    J = motion.jacobians
    Jv, Jw = J[:, :, :3], J[:, :, 3:]
    M = np.einsum("b,nbip,nbiq->npq", inertia.masses, Jv, Jv) + np.einsum("nbip,nbij,nbjq->npq", Jw, Iw, Jw)
    return M, Iw


def jointed_mass_matrix(robot: Robot, arr: np.ndarray) -> np.ndarray:
    """``M = Tᵀ M_X T`` ``(N, P, P)`` at validated poses ``arr``."""
    T = twist_jacobian(robot, arr)
    M, _ = _twist_inertias(robot, body_motion(robot, arr))
    return np.swapaxes(T, 1, 2) @ M @ T


def _load(robot: Robot, motion: BodyMotion) -> np.ndarray:
    """``Σ_b J_bᵀ (F_b, n_b)`` ``(N, P)``: the constant loads in twist coordinates."""
    inertia = body_inertia(robot)
    J = motion.jacobians
    Q = np.einsum("nbip,bi->np", J[:, :, :3], inertia.forces)
    return Q + np.einsum("nip,i->np", J[:, 0, 3:], inertia.moment)


def jointed_gravity_forces(robot: Robot, arr: np.ndarray) -> np.ndarray:
    """``g = −Tᵀ Σ_b J_bᵀ (F_b, n_b)`` ``(N, P)`` at validated poses ``arr``."""
    T = twist_jacobian(robot, arr)
    return -np.einsum("npq,np->nq", T, _load(robot, body_motion(robot, arr)))


def jointed_bias_forces(robot: Robot, arr: np.ndarray, qd: np.ndarray) -> np.ndarray:
    """``h = Tᵀ (h_X + M_X Ṫ q̇)`` ``(N, P)`` at validated poses ``arr`` and rates ``qd``."""
    inertia = body_inertia(robot)
    T = twist_jacobian(robot, arr)
    X = np.einsum("npq,nq->np", T, qd)
    motion = body_motion(robot, arr, X)
    M, Iw = _twist_inertias(robot, motion)
    w, a = motion.omegas, motion.accelerations
    force = inertia.masses[None, :, None] * a[..., :3]
    spin = np.einsum("nbij,nbj->nbi", Iw, w)
    moment = np.einsum("nbij,nbj->nbi", Iw, a[..., 3:]) + np.cross(w, spin)
    J = motion.jacobians
    hX = np.einsum("nbip,nbi->np", J[:, :, :3], force) + np.einsum("nbip,nbi->np", J[:, :, 3:], moment)
    hX += np.einsum("npq,nq->np", M, np.einsum("npq,nq->np", twist_jacobian_rate(robot, arr, qd), qd))
    hX -= _load(robot, motion)
    return np.einsum("npq,np->nq", T, hX)


def jointed_coriolis_matrix(robot: Robot, arr: np.ndarray, qd: np.ndarray) -> np.ndarray:
    """``C = Tᵀ (M_X Ṫ + C_X T)`` ``(N, P, P)`` at validated poses ``arr`` and rates ``qd``,
    with ``C_X = Σ_b J_bᵀ (m_b J̇_v, I_b^w J̇_ω + [ω_b]× I_b^w J_ω)`` (``J_b = (J_v, J_ω)``),
    so that ``C q̇ = h − g`` and ``Ṁ − 2 C`` is skew-symmetric: ``Ṁ_X − 2 C_X`` is, its
    rotational part ``−([ω]× I + I [ω]×)`` being skew."""
    inertia = body_inertia(robot)
    T = twist_jacobian(robot, arr)
    motion = body_motion(robot, arr, np.einsum("npq,nq->np", T, qd))
    M, Iw = _twist_inertias(robot, motion)
    J, Jd, w = motion.jacobians, motion.rates, motion.omegas
    spin = np.zeros(w.shape + (3,))
    spin[..., 0, 1], spin[..., 0, 2], spin[..., 1, 2] = -w[..., 2], w[..., 1], -w[..., 0]
    spin -= np.swapaxes(spin, -1, -2)
    CX = np.einsum("b,nbip,nbiq->npq", inertia.masses, J[:, :, :3], Jd[:, :, :3])
    CX += np.einsum("nbip,nbij,nbjq->npq", J[:, :, 3:], Iw, Jd[:, :, 3:])
    CX += np.einsum("nbip,nbij,nbjq->npq", J[:, :, 3:], spin @ Iw, J[:, :, 3:])
    return np.swapaxes(T, 1, 2) @ (M @ twist_jacobian_rate(robot, arr, qd) + CX @ T)
