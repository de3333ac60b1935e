"""Inverse kinematics of the standard CDPR model (Rushton 2022, §2.1.1).

Cable *i* runs from its exit point ``a_i`` to ``b_i = p + R r_i`` (Eq. 2.1); its length is
``l_i = ‖a_i − b_i‖`` and its unit vector ``u_i = (a_i − b_i)/l_i`` points from the
platform to the exit point.  The structure matrix is ``W = [u_i ; (b_i − p) × u_i]``
(Eq. 2.8; Eq. 2.10 for a point mass), so that equilibrium reads ``W τ + w_ext = 0``
(Eq. 2.11).  For jointed platforms (Lieskovský 2020) ``b_i`` is the anchor on the cable's own
body and moments are still taken about the platform reference point ``p``.

A cable that leaves the frame through a swivelling pulley (Pott 2018) has the arc wound on
the pulley in its length, and runs straight from the pulley's tangent point ``c_i``: ``u_i =
(c_i − b_i)/‖c_i − b_i‖`` (:mod:`taut.kinematics._swivel`).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8, 2.10 and 2.11. (docs/references.bib: rushton2022)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.2.
   (docs/references.bib: lieskovsky2020)
.. [3] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut.errors import InfeasiblePoseError
from taut.geometry import cross
from taut.kinematics._paths import CABLE_OK, MIN_LENGTH, STATUS_REASONS, ZERO_LENGTH, cable_paths
from taut.kinematics._pose import anchors_at, as_poses
from taut.model import Robot

#: From this many poses on, rigid platforms go through the Numba kernel; below it NumPy is
#: as fast per call and spares the process the import of Numba.
BATCH_POSES = 32


@dataclass(frozen=True)
class IKResult:
    """Inverse kinematics over ``N`` poses of a robot with ``n`` cables in ``d`` dimensions."""

    lengths: np.ndarray  #: ``(N, n)`` cable lengths
    directions: np.ndarray  #: ``(N, n, d)`` unit vectors ``u_i`` (platform → exit point)
    anchors: np.ndarray  #: ``(N, n, d)`` platform anchors ``b_i`` in the fixed frame
    structure_matrix: np.ndarray  #: ``(N, m, n)`` wrench matrix ``W``
    #: ``(N, n, d)`` where the straight part of each cable begins: its exit point ``a_i``, or
    #: the tangent point on its swivelling pulley
    exit_points: np.ndarray


def _infeasible(robot: Robot, status: np.ndarray) -> InfeasiblePoseError:
    k, i = np.argwhere(status != CABLE_OK)[0]
    return InfeasiblePoseError(f"{robot.name}: at pose {k + 1} cable {i + 1} {STATUS_REASONS[int(status[k, i])]}")


def ik_status(robot: Robot, poses: np.ndarray) -> tuple[IKResult, np.ndarray]:
    """:func:`inverse_kinematics` of ``(N, pose_size)`` poses already checked by
    :func:`~taut.kinematics.as_poses`, without raising: the result at every pose and the
    status ``(N, n)`` of each cable (:data:`CABLE_OK`, :data:`ZERO_LENGTH`, :data:`ON_SWIVEL_AXIS`,
    :data:`ON_PULLEY`).  Lengths and exit points are finite everywhere; directions and the
    structure matrix are zero for the cables and poses whose status is not :data:`CABLE_OK`.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
    .. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
    """
    d = robot.dimension
    b = anchors_at(robot, poses)
    lengths, exits, status = cable_paths(robot, b)
    v = exits - b
    free = np.sqrt(np.einsum("nki,nki->nk", v, v))
    good = status == CABLE_OK
    u = np.where(good[..., None], v / np.where(good, free, 1.0)[..., None], 0.0)
    W = np.swapaxes(u, 1, 2)
    if not robot.is_point_mass:
        m = cross(b - poses[:, None, :d], u)
        m = m[..., None] if m.ndim == 2 else m
        W = np.concatenate([W, np.swapaxes(m, 1, 2)], axis=1)
    W = np.where(good.all(axis=1)[:, None, None], W, 0.0)
    return IKResult(lengths, u, b, W, exits), status


def lengths_at(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """Cable lengths ``(N, n)`` at ``(N, pose_size)`` poses without checks (solvers call it on
    their own iterates): finite everywhere, also where :func:`ik_status` flags a cable."""
    return cable_paths(robot, anchors_at(robot, poses))[0]


def inverse_kinematics(robot: Robot, poses: npt.ArrayLike) -> IKResult:
    """Lengths, unit vectors, anchors and structure matrix at each pose.

    Robots without jointed bodies or swivelling pulleys go through the Numba kernel of
    :mod:`taut.kinematics._batch` from :data:`BATCH_POSES` poses on; fewer poses, jointed
    platforms and robots with swivelling pulleys (:mod:`taut.kinematics._swivel`) through NumPy.
    Raises :class:`InfeasiblePoseError` when a cable has zero length, or its anchor is on the
    axis or inside the circle of its swivelling pulley (its direction and the structure matrix
    do not exist there).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
    .. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
    """
    arr, single = as_poses(robot, poses)
    d = robot.dimension
    batched = _batched(robot, arr)
    if batched is not None:
        lengths, W, ok = batched
        if not ok.all():
            raise _infeasible(robot, np.where(lengths < MIN_LENGTH, ZERO_LENGTH, CABLE_OK))
        u = np.swapaxes(W[:, :d, :], 1, 2)
        b = robot.exits[None, :, :] - u * lengths[..., None]
        res = IKResult(lengths, u, b, W, np.broadcast_to(robot.exits[None], b.shape))
    else:
        res, status = ik_status(robot, arr)
        if (status != CABLE_OK).any():
            raise _infeasible(robot, status)
    if single:
        return IKResult(res.lengths[0], res.directions[0], res.anchors[0], res.structure_matrix[0], res.exit_points[0])
    return res


def _batched(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``(lengths, W, ok)`` of :func:`batch_structure_matrices`, or None
    for fewer than :data:`BATCH_POSES` poses, a robot the kernel does not handle, or one with
    swivelling pulleys (the kernel does not return their tangent points)."""
    if poses.shape[0] < BATCH_POSES or robot.swivel_cables:
        return None
    from taut.kinematics._batch import kernel_structure_matrices, supports_batch  # Numba, for large batches only

    return kernel_structure_matrices(robot, poses) if supports_batch(robot) else None


def cable_lengths(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Cable lengths ``(N, n)`` (``(n,)`` for one pose)."""
    return inverse_kinematics(robot, poses).lengths


def structure_matrix(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Structure (wrench) matrix ``W`` of shape ``(N, m, n)`` (``(m, n)`` for one pose).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.8 and 2.10. (docs/references.bib: rushton2022)
    """
    return inverse_kinematics(robot, poses).structure_matrix


def batch_structure_matrices(robot: Robot, poses: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cable lengths ``(N, n)``, structure matrices ``W (N, m, n)`` and a mask ``ok (N,)``
    of the poses where every cable has a length of at least ``MIN_LENGTH`` and, through a
    swivelling pulley, a tangent point (elsewhere ``W`` is zero).  Robots with jointed bodies
    and planar robots with swivelling pulleys go through the NumPy implementation
    (:func:`ik_status`)."""
    from taut.kinematics._batch import kernel_structure_matrices, supports_batch

    arr, _ = as_poses(robot, poses)
    if not supports_batch(robot):
        ik, status = ik_status(robot, arr)
        return ik.lengths, ik.structure_matrix, (status == CABLE_OK).all(axis=1)
    return kernel_structure_matrices(robot, arr)
