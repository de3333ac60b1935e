"""Actuator positions, inverse-kinematics Jacobian and structure matrix of robots whose
platform carries jointed bodies — §3.2–3.3 of Lieskovský (2020) — written for
any robot of taut (without bodies they reduce to the standard model).

* **Actuator positions** (Eqs. 3.2.3–3.2.4): ``q = [l_1 … l_n, q_{n+1} …]``, the cable
  lengths followed by the joint coordinates (the joint actuators).
* **Inverse-kinematics Jacobian** (Eqs. 3.2.6–3.2.12): ``q̇ = J Ẋ`` with the *twist*
  ``Ẋ = [v, ω, q̇_joints]`` of the platform (velocity of its reference point ``p``,
  angular velocity, joint rates).  Cable ``i`` on body ``k`` has the row
  ``[−u_iᵀ, −((b_i − p) × u_i)ᵀ, −u_i·∂b_i/∂q_j …]`` where ``∂b_i/∂q_j`` is, for each joint
  ``j`` between the platform and body ``k``, the joint axis ``e_j`` in the fixed frame
  (prismatic, Eq. 3.2.7: ``ṡ_23 u_23``) or ``e_j × (b_i − o_j)`` about the joint origin
  ``o_j`` (revolute; planar: ``(b_i − o_j)`` turned by 90°); each joint row is a unit row
  (Eq. 3.2.8).  With ``u_i`` pointing from the platform to the exit point (``docs/architecture.md``
  §2.4) ``l̇_i = −u_i · ḃ_i``: Eq. 3.2.12 prints the same rows with the opposite sign.  For the
  adjustable platform ``J`` is 9×7.
* **Structure matrix with joint forces** (Eqs. 3.3.7–3.3.12): by virtual work a cable
  tension ``τ_i`` acts on the generalised coordinates as ``−τ_i ∂l_i/∂X`` and a joint force
  ``ζ_j`` (pushing the child body along ``+e_j``) as ``+ζ_j ∂q_j/∂X``, so equilibrium reads
  ``A [τ; ζ] + Q_ext = 0`` with ``A = [−J_cablesᵀ, J_jointsᵀ]``.  Its first ``m`` rows and
  ``n`` columns are the platform structure matrix ``W = [u_i ; (b_i − p) × u_i]`` of
  Eq. 3.3.10 (``A = −W`` there: the source writes the wrench the cables exert as ``w``).
  A joint row gives the joint force (Eq. 3.3.12): ``ζ_j = −Σ τ_i u_i·∂b_i/∂q_j`` over the
  cables beyond the joint, minus the generalised force ``Σ_k F_k·∂c_k/∂q_j`` of the
  weights ``F_k`` of the bodies beyond it at their centres of mass ``c_k`` (the platform's
  own wrench acts on the platform body itself and does not enter the joint rows).

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.2–3.3, Eqs. 3.2.3–3.2.12 and
   3.3.7–3.3.12. (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import TautError
from taut.kinematics._inverse import inverse_kinematics, lengths_at
from taut.kinematics._pose import as_poses, body_frames
from taut.kinematics._routing import routed_segments, via_points_at
from taut.model import Robot

__all__ = ["actuator_jacobian", "actuator_positions", "joint_forces", "jointed_structure_matrix"]


def actuator_positions(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """``q`` of Eqs. 3.2.3–3.2.4: cable lengths then joint coordinates, ``(N, n + n_joints)``.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, Eqs. 3.2.3–3.2.4.
       (docs/references.bib: lieskovsky2020)
    """
    arr, single = as_poses(robot, poses)
    q = np.concatenate([lengths_at(robot, arr), arr[:, robot.wrench_dim :]], axis=1)
    return q[0] if single else q


def _chains(robot: Robot) -> list[list[int]]:
    """For each body (0 = platform) the joints (1-based body indices) from it to the platform."""
    index = {"platform": 0} | {b.name: k for k, b in enumerate(robot.platform.bodies, 1)}
    chains: list[list[int]] = [[]]
    for k, body in enumerate(robot.platform.bodies, 1):
        chains.append([k] + chains[index[body.parent]])
    return chains


def _joint_derivatives(robot: Robot, arr: np.ndarray, b: np.ndarray) -> np.ndarray:
    """``∂b_i/∂q_j`` in the fixed frame, ``(N, n, n_joints, d)``."""
    return _point_derivatives(robot, arr, b, robot.cable_bodies)


def _point_derivatives(robot: Robot, arr: np.ndarray, b: np.ndarray, bodies: np.ndarray) -> np.ndarray:
    """``∂b_i/∂q_j`` in the fixed frame of points ``b (N, n, d)`` fixed to the bodies
    ``bodies (n,)`` (0 = platform), ``(N, n, n_joints, d)``."""
    N, n, d = b.shape
    out = np.zeros((N, n, robot.n_joints, d))
    if robot.n_joints == 0:
        return out
    pos, rot = body_frames(robot, arr)
    index = {"platform": 0} | {bd.name: k for k, bd in enumerate(robot.platform.bodies, 1)}
    chains = _chains(robot)
    for i, body in enumerate(bodies):
        for k in chains[body]:
            joint = robot.platform.bodies[k - 1].joint
            parent = index[robot.platform.bodies[k - 1].parent]
            if joint.kind == "prismatic":
                axis = np.asarray(joint.axis, float)
                out[:, i, k - 1] = rot[:, parent] @ (axis / np.linalg.norm(axis))
            elif d == 2:
                r = b[:, i] - pos[:, k]
                out[:, i, k - 1] = np.stack([-r[:, 1], r[:, 0]], -1)
            else:
                axis = np.asarray(joint.axis, float)
                e = rot[:, parent] @ (axis / np.linalg.norm(axis))
                out[:, i, k - 1] = np.cross(e, b[:, i] - pos[:, k])
    return out


def actuator_jacobian(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Inverse-kinematics Jacobian ``J`` with ``q̇ = J [v, ω, q̇_joints]`` (Eq. 3.2.12).

    The actuator rates ``q̇`` are the cable length rates then the joint rates; the twist is the
    velocity of the platform reference point, the angular velocity and the joint rates.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, n + n_joints, m + n_joints), or without the batch axis for one pose
        ``m`` is the platform wrench size (9×7 for the adjustable platform).

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.
    InfeasiblePoseError
        A zero-length cable.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.2.2, Eqs. 3.2.6–3.2.12.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    The joint row of the adjustable platform is a unit row (Eq. 3.2.8):

    >>> from taut.model import example
    >>> from taut.kinematics import actuator_jacobian, default_guess
    >>> robot = example("adjustable-8cable")
    >>> J = actuator_jacobian(robot, default_guess(robot))
    >>> J.shape, J[8]
    ((9, 7), array([0., 0., 0., 0., 0., 0., 1.]))
    """
    arr, single = as_poses(robot, poses)
    ik = inverse_kinematics(robot, arr)
    n, m, nj = robot.n_cables, robot.wrench_dim, robot.n_joints
    J = np.zeros((arr.shape[0], n + nj, m + nj))
    J[:, :n, :m] = -np.swapaxes(ik.structure_matrix, 1, 2)
    if nj:
        db = _joint_derivatives(robot, arr, ik.anchors)
        J[:, :n, m:] = -np.einsum("nid,nijd->nij", ik.directions, db)
        if robot.routed_cables:
            cables, bodies, _ = robot.via_points
            vias = via_points_at(robot, arr)
            f = routed_segments(robot, ik.anchors, vias)[3]
            on = bodies > 0  # points on the platform or fixed do not move with the joints
            dv = _point_derivatives(robot, arr, vias[:, on], bodies[on])
            joint_columns = J[:, :, m:].transpose(1, 0, 2)  # a view: (cable rows, N, joints)
            np.add.at(joint_columns, cables[on], -np.einsum("nvd,nvjd->vnj", f[:, on], dv))
        J[:, n:, m:] = np.eye(nj)
    return J[0] if single else J


def jointed_structure_matrix(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """The structure matrix of a jointed platform, ``A = [−J_cablesᵀ, J_jointsᵀ]``.

    Equilibrium reads ``A [τ; ζ] + Q_ext = 0`` (Eqs. 3.3.7–3.3.12; the sign convention is in the
    module's docstring).  Its top-left ``m × n`` block is the platform structure matrix ``W``.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, m + n_joints, n + n_joints), or without the batch axis for one pose

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.
    InfeasiblePoseError
        A zero-length cable.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eqs. 3.3.7–3.3.11.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import default_guess, jointed_structure_matrix, structure_matrix
    >>> robot = example("adjustable-8cable")
    >>> A = jointed_structure_matrix(robot, default_guess(robot))
    >>> A.shape, bool(np.allclose(A[:6, :8], structure_matrix(robot, default_guess(robot))))
    ((7, 9), True)
    """
    J = actuator_jacobian(robot, poses)
    n = robot.n_cables
    A = np.swapaxes(J, -1, -2).copy()
    A[..., :n] *= -1.0
    return A


def joint_forces(robot: Robot, poses: npt.ArrayLike, tensions: npt.ArrayLike) -> np.ndarray:
    """Joint actuator forces ``ζ`` balancing the cable tensions and the bodies' weights (Eq. 3.3.12).

    ``ζ = −A_joints,cables τ − Q_gravity`` along the joint coordinates: a positive ``ζ``
    pushes the child body along its joint axis; a revolute joint gets a torque about its axis.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)
    tensions : array_like, shape (n,) or (N, n)
        Cable tensions [N].

    Returns
    -------
    ndarray, shape (N, n_joints) or (n_joints,) for one pose
        Forces [N] (prismatic joints) or torques [N·m] (revolute joints).

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.
    InfeasiblePoseError
        A zero-length cable.
    TautError
        Tensions that are not finite numbers of the right shape.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.3.2, Eq. 3.3.12.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import default_guess, joint_forces
    >>> robot = example("adjustable-8cable")
    >>> joint_forces(robot, default_guess(robot), np.full(8, 100.0)).round(3)
    array([325.494])
    """
    arr, single = as_poses(robot, poses)
    A = jointed_structure_matrix(robot, arr)
    try:
        tau = np.asarray(tensions, dtype=float)
    except (TypeError, ValueError):
        raise TautError(f"{robot.name}: tensions must be numbers, got {tensions!r}") from None
    if tau.shape not in ((robot.n_cables,), (arr.shape[0], robot.n_cables)):
        raise TautError(
            f"{robot.name}: tensions must have shape ({robot.n_cables},) or ({arr.shape[0]}, {robot.n_cables}), got {tau.shape}"
        )
    if not np.isfinite(tau).all():
        raise TautError(f"{robot.name}: tensions must be finite, got {tau.tolist()}")
    tau = np.broadcast_to(tau, (arr.shape[0], robot.n_cables))
    m, n = robot.wrench_dim, robot.n_cables
    zeta = -np.einsum("kjc,kc->kj", A[:, m:, :n], tau)
    if np.any(robot.body_weights != 0):
        zeta -= _gravity_forces(robot, arr)
    return zeta[0] if single else zeta


def _gravity_forces(robot: Robot, arr: np.ndarray) -> np.ndarray:
    """The generalised forces of the bodies' weights along the joint coordinates,
    ``Q_j = Σ_k F_k · ∂c_k/∂q_j`` over the bodies ``k`` beyond joint ``j`` (``c_k`` the centre
    of mass in the fixed frame), ``(N, n_joints)``: the weight part of ``Q_ext`` in
    ``A [τ; ζ] + Q_ext = 0``."""
    pos, rot = body_frames(robot, arr)
    coms = pos[:, 1:] + np.einsum("nkij,kj->nki", rot[:, 1:], robot.body_coms)
    dc = _point_derivatives(robot, arr, coms, np.arange(1, robot.n_joints + 1))
    return np.einsum("kd,nkjd->nj", robot.body_weights, dc)
