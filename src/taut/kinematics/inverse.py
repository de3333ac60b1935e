"""Inverse kinematics of the standard CDPR model (Rushton 2022, §2.1.1).

Cable *i* runs from its exit point ``a_i`` to ``b_i = p + R r_i`` (Eq. 2.1); its length is
``l_i = ‖a_i − b_i‖`` and its unit vector ``u_i = (a_i − b_i)/l_i`` points from the
platform to the exit point.  The structure matrix is ``W = [u_i ; (b_i − p) × u_i]``
(Eq. 2.8; Eq. 2.10 for a point mass), so that equilibrium reads ``W τ + w_ext = 0``
(Eq. 2.11).  For jointed platforms (Lieskovský 2020) ``b_i`` is the anchor on the cable's own
body and moments are still taken about the platform reference point ``p``.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8, 2.10 and 2.11. (docs/references.bib: rushton2022)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.2.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut.errors import InfeasiblePoseError
from taut.geometry.vectors import cross
from taut.kinematics.pose import as_poses, body_frames, platform_frame
from taut.model.robot import Robot

#: A cable shorter than this [m] has no direction: the pose is rejected.
MIN_LENGTH = 1e-12

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


def anchor_points(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Platform anchors ``b_i`` in the fixed frame, ``(N, n, d)`` (``(n, d)`` for one pose)."""
    arr, single = as_poses(robot, poses)
    b = anchors_at(robot, arr)
    return b[0] if single else b


def anchors_at(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """:func:`anchor_points` without the checks: ``poses`` is an ``(N, pose_size)`` array
    already checked by :func:`~taut.kinematics.pose.as_poses` (solvers and samplers call it
    on their own iterates, which may leave the joint limits); returns ``(N, n, d)``."""
    if robot.is_point_mass:
        return np.broadcast_to(poses[:, None, : robot.dimension], (poses.shape[0], robot.n_cables, robot.dimension))
    if robot.n_joints == 0:
        p, R = platform_frame(robot, poses)
        return p[:, None, :] + np.einsum("nij,kj->nki", R, robot.anchors)
    pos, rot = body_frames(robot, poses)
    idx = robot.cable_bodies
    return pos[:, idx, :] + np.einsum("nkij,kj->nki", rot[:, idx], robot.anchors)


def _zero_length(robot: Robot, lengths: np.ndarray) -> InfeasiblePoseError:
    k, i = np.unravel_index(np.argmin(lengths), lengths.shape)
    return InfeasiblePoseError(
        f"{robot.name}: at pose {k + 1} cable {i + 1} has zero length (its anchor is at its exit point)"
    )


def inverse_kinematics(robot: Robot, poses: npt.ArrayLike) -> IKResult:
    """Lengths, unit vectors, anchors and structure matrix at each pose.

    Robots without jointed bodies go through the Numba kernel of
    :mod:`taut.kinematics.batch` from :data:`BATCH_POSES` poses on; fewer poses and jointed
    platforms through NumPy over body frames.
    Raises :class:`InfeasiblePoseError` when a cable has zero length (its direction and the
    structure matrix do not exist there).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
    """
    arr, single = as_poses(robot, poses)
    d = robot.dimension
    batched = _batched(robot, arr)
    if batched is not None:
        lengths, W, ok = batched
        if not ok.all():
            raise _zero_length(robot, lengths)
        u = np.swapaxes(W[:, :d, :], 1, 2)
        b = robot.exits[None, :, :] - u * lengths[..., None]
    else:
        b = anchors_at(robot, arr)
        v = robot.exits[None, :, :] - b
        lengths = np.sqrt(np.einsum("nki,nki->nk", v, v))
        if lengths.size and lengths.min() < MIN_LENGTH:
            raise _zero_length(robot, lengths)
        u = v / lengths[..., None]
        W = np.swapaxes(u, 1, 2)
        if not robot.is_point_mass:
            m = cross(b - arr[:, None, :d], u)
            m = m[..., None] if m.ndim == 2 else m
            W = np.concatenate([W, np.swapaxes(m, 1, 2)], axis=1)
    if single:
        return IKResult(lengths[0], u[0], b[0], W[0])
    return IKResult(lengths, u, b, W)


def _batched(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``(lengths, W, ok)`` of :func:`taut.kinematics.batch.batch_structure_matrices`, or None
    for fewer than :data:`BATCH_POSES` poses or a robot the kernel does not handle."""
    if poses.shape[0] < BATCH_POSES:
        return None
    from taut.kinematics.batch import batch_structure_matrices, supports_batch

    return batch_structure_matrices(robot, poses) if supports_batch(robot) else None


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
