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

from taut._results import Result
from taut.errors import InfeasiblePoseError
from taut.geometry import cross
from taut.kinematics._paths import (
    CABLE_OK,
    MIN_LENGTH,
    STATUS_REASONS,
    WRAPPED,
    ZERO_LENGTH,
    cable_paths,
    first_obstacle,
    wrapped_error,
)
from taut.kinematics._pose import anchors_at, as_poses
from taut.kinematics._routing import routed_segments, via_points_at, via_wrench
from taut.model import Robot

#: From this many poses on, rigid platforms go through the Numba kernel; below it NumPy is
#: as fast per call and spares the process the import of Numba.
BATCH_POSES = 32


@dataclass(frozen=True)
class IKResult(Result):
    """Inverse kinematics over ``N`` poses of a robot with ``n`` cables in ``d`` dimensions
    (:func:`inverse_kinematics`; without the batch axis for one pose).

    Attributes
    ----------
    lengths : ndarray, shape (N, n)
        Cable lengths [m], the arc on a swivelling pulley included.
    directions : ndarray, shape (N, n, d)
        Unit vectors ``u_i``, from the anchor towards the exit (or tangent) point.
    anchors : ndarray, shape (N, n, d)
        Platform anchors ``b_i`` in the fixed frame [m].
    structure_matrix : ndarray, shape (N, m, n)
        The wrench matrix ``W = [u_i ; (b_i − p) × u_i]``.
    exit_points : ndarray, shape (N, n, d)
        Where the straight part of each cable begins [m]: its exit point, or the tangent
        point on its swivelling pulley.

    Examples
    --------
    >>> import json
    >>> from taut.model import example
    >>> from taut.kinematics import inverse_kinematics
    >>> ik = inverse_kinematics(example("planar-4cable"), [0.0, 0.0, 0.0])
    >>> ik.lengths.flags.writeable, sorted(ik.as_dict())[:2]
    (False, ['anchors', 'directions'])
    """

    lengths: np.ndarray  #: ``(N, n)`` cable lengths
    directions: np.ndarray  #: ``(N, n, d)`` unit vectors ``u_i`` (platform → exit point)
    anchors: np.ndarray  #: ``(N, n, d)`` platform anchors ``b_i`` in the fixed frame
    structure_matrix: np.ndarray  #: ``(N, m, n)`` wrench matrix ``W``
    #: ``(N, n, d)`` where the straight part of each cable begins: its exit point ``a_i``, or
    #: the tangent point on its swivelling pulley
    exit_points: np.ndarray


def _infeasible(robot: Robot, status: np.ndarray, poses: np.ndarray) -> InfeasiblePoseError:
    k, i = np.argwhere(status != CABLE_OK)[0]
    if status[k, i] == WRAPPED:
        b = anchors_at(robot, poses[k : k + 1])
        met = first_obstacle(robot, cable_paths(robot, b)[1], b)
        return wrapped_error(robot, f"at pose {k + 1}", int(i), int(met[0, i]))
    return InfeasiblePoseError(f"{robot.name}: at pose {k + 1} cable {i + 1} {STATUS_REASONS[int(status[k, i])]}")


def ik_status(robot: Robot, poses: np.ndarray) -> tuple[IKResult, np.ndarray]:
    """:func:`inverse_kinematics` of checked poses, without raising where it does not exist.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`~taut.kinematics.as_poses`.

    Returns
    -------
    result : IKResult
        The result at every pose.  Lengths and exit points are finite everywhere;
        directions and the structure matrix are zero for the cables and poses whose status
        is not :data:`CABLE_OK`.
    status : ndarray of int, shape (N, n)
        The status of each cable: :data:`CABLE_OK`, or why its direction does not exist
        (a zero length, an anchor on the axis or inside the circle of its swivelling pulley), or
        why its straight line is not the cable (it meets an obstacle of a variable-structure
        robot, :func:`~taut.kinematics.obstacles_met`).

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
    .. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    At the second pose the anchor of cable 1 (index 0) is at its exit point:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import CABLE_OK, ik_status
    >>> ik, status = ik_status(example("planar-4cable"), np.array([[0, 0, 0.0], [-0.9, -0.95, 0]]))
    >>> status == CABLE_OK
    array([[ True,  True,  True,  True],
           [False,  True,  True,  True]])
    """
    d = robot.dimension
    b = anchors_at(robot, poses)
    vias = _vias(robot, poses)
    lengths, exits, status = cable_paths(robot, b, via=vias)
    v = exits - b
    free = np.sqrt(np.einsum("nki,nki->nk", v, v))
    good = status == CABLE_OK
    u = np.where(good[..., None], v / np.where(good, free, 1.0)[..., None], 0.0)
    W = np.swapaxes(u, 1, 2)
    if not robot.is_point_mass:
        m = cross(b - poses[:, None, :d], u)
        m = m[..., None] if m.ndim == 2 else m
        W = np.concatenate([W, np.swapaxes(m, 1, 2)], axis=1)
    if vias is not None:
        W = W + via_wrench(robot, poses, vias, routed_segments(robot, b, vias)[3])
    W = np.where(good.all(axis=1)[:, None, None], W, 0.0)
    return IKResult(lengths, u, b, W, exits), status


def lengths_at(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """Cable lengths at checked poses, without the checks of :func:`as_poses`.

    Solvers call it on their own iterates.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`~taut.kinematics.as_poses`.

    Returns
    -------
    ndarray, shape (N, n)
        Cable lengths [m], finite everywhere, also where :func:`ik_status` flags a cable.

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import lengths_at
    >>> lengths_at(example("planar-4cable"), np.zeros((1, 3))).round(4)
    array([[1.3086, 1.3086, 1.3086, 1.3086]])
    """
    return cable_paths(robot, anchors_at(robot, poses), via=_vias(robot, poses))[0]


def _vias(robot: Robot, poses: np.ndarray) -> np.ndarray | None:
    return via_points_at(robot, poses) if robot.routed_cables else None


def inverse_kinematics(robot: Robot, poses: npt.ArrayLike) -> IKResult:
    """Lengths, unit vectors, anchors and structure matrix of the cables at each pose.

    Robots without jointed bodies or swivelling pulleys go through a Numba kernel from
    :data:`BATCH_POSES` poses on; fewer poses, jointed platforms and robots with swivelling
    pulleys through NumPy (the same numbers).

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    IKResult
        Without the batch axis for one pose.

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.
    InfeasiblePoseError
        A cable of zero length, or whose anchor is on the axis or inside the circle of its
        swivelling pulley: its direction and the structure matrix do not exist there.
    WrappedCableError
        A cable of a variable-structure robot whose straight line meets an obstacle
        (:func:`~taut.kinematics.obstacles_met`): it wraps around it, and its length depends
        on the motion (:mod:`taut.wrapping` follows it along a trajectory).  Where every
        straight cable clears every obstacle, the straight cables are the answer.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
    .. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)

    Examples
    --------
    At the centre of the planar robot every cable is ``‖(0.9, 0.95)‖ = 1.3086`` m long:

    >>> from taut.model import example
    >>> from taut.kinematics import inverse_kinematics
    >>> ik = inverse_kinematics(example("planar-4cable"), [0.0, 0.0, 0.0])
    >>> ik.lengths.round(4)
    array([1.3086, 1.3086, 1.3086, 1.3086])
    >>> ik.directions[0].round(3)
    array([-0.688, -0.726])
    """
    arr, single = as_poses(robot, poses)
    d = robot.dimension
    batched = _batched(robot, arr)
    if batched is not None:
        lengths, W, ok = batched
        if not ok.all():
            raise _infeasible(robot, np.where(lengths < MIN_LENGTH, ZERO_LENGTH, CABLE_OK), arr)
        u = np.swapaxes(W[:, :d, :], 1, 2)
        b = robot.exits[None, :, :] - u * lengths[..., None]
        res = IKResult(lengths, u, b, W, np.broadcast_to(robot.exits[None], b.shape))
    else:
        res, status = ik_status(robot, arr)
        if (status != CABLE_OK).any():
            raise _infeasible(robot, status, arr)
    if single:
        return IKResult(res.lengths[0], res.directions[0], res.anchors[0], res.structure_matrix[0], res.exit_points[0])
    return res


def _batched(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
    """``(lengths, W, ok)`` of :func:`batch_structure_matrices`, or None
    for fewer than :data:`BATCH_POSES` poses, a robot the kernel does not handle, or one with
    swivelling pulleys (the kernel does not return their tangent points)."""
    if poses.shape[0] < BATCH_POSES or robot.swivel_cables or robot.routed_cables:
        return None
    from taut.kinematics._batch import kernel_structure_matrices, supports_batch  # Numba, for large batches only

    return kernel_structure_matrices(robot, poses) if supports_batch(robot) else None


def cable_lengths(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Cable lengths at each pose: the ``lengths`` of :func:`inverse_kinematics`.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, n) or (n,) for one pose
        Lengths [m], the arc on a swivelling pulley included.

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.
    InfeasiblePoseError
        Where a cable's direction does not exist, or (:class:`~taut.errors.WrappedCableError`)
        a straight cable meets an obstacle (see :func:`inverse_kinematics`).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eq. 2.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import cable_lengths
    >>> cable_lengths(example("planar-4cable"), [0.0, 0.0, 0.0]).round(4)
    array([1.3086, 1.3086, 1.3086, 1.3086])
    """
    return inverse_kinematics(robot, poses).lengths


def structure_matrix(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Structure (wrench) matrix ``W = [u_i ; (b_i − p) × u_i]`` at each pose.

    Equilibrium reads ``W τ + w_ext = 0`` (``docs/architecture.md`` §2.4).

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, m, n) or (m, n) for one pose
        Forces in the first ``d`` rows, moments about the platform reference point in the
        others (``m`` the wrench size).

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.
    InfeasiblePoseError
        Where a cable's direction does not exist, or (:class:`~taut.errors.WrappedCableError`)
        a straight cable meets an obstacle (see :func:`inverse_kinematics`).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.8 and 2.10. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import structure_matrix
    >>> structure_matrix(example("planar-4cable"), [0.0, 0.0, 0.0]).round(3)
    array([[-0.688,  0.688,  0.688, -0.688],
           [-0.726, -0.726,  0.726,  0.726],
           [ 0.038, -0.038,  0.038, -0.038]])
    """
    return inverse_kinematics(robot, poses).structure_matrix


def batch_structure_matrices(robot: Robot, poses: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Cable lengths and structure matrices of many poses, without raising where ``W`` does not exist.

    Made for workspace grids: the Numba kernel of :mod:`taut.kinematics._batch`; robots with
    jointed bodies and planar robots with swivelling pulleys go through :func:`ik_status`.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size)

    Returns
    -------
    lengths : ndarray, shape (N, n)
        Cable lengths [m].
    W : ndarray, shape (N, m, n)
        Structure matrices; zero where ``ok`` is False.
    ok : ndarray of bool, shape (N,)
        The poses where every cable has a length of at least ``MIN_LENGTH`` (1e-12 m),
        through a swivelling pulley a tangent point, and as a straight line meets no obstacle
        of a variable-structure robot.

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import batch_structure_matrices
    >>> lengths, W, ok = batch_structure_matrices(example("planar-4cable"), [[0, 0, 0], [-0.9, -0.95, 0]])
    >>> ok, W.shape, bool(np.all(W[1] == 0))
    (array([ True, False]), (2, 3, 4), True)
    """
    from taut.kinematics._batch import kernel_structure_matrices, supports_batch

    arr, _ = as_poses(robot, poses)
    if not supports_batch(robot):
        ik, status = ik_status(robot, arr)
        return ik.lengths, ik.structure_matrix, (status == CABLE_OK).all(axis=1)
    return kernel_structure_matrices(robot, arr)
