"""Waypoints of a trajectory: validation, completion of positions to poses, and the short
way between orientations.

A waypoint is a pose (``docs/architecture.md`` §2.2): position, orientation angles in the
robot's convention, joint coordinates.  Adding 2π to one orientation angle leaves the
rotation unchanged in every convention of :mod:`taut.geometry._rotation`: each angle enters
``R`` only through a rotation about a coordinate axis (for ``tilt-torsion``, ``φ`` enters
the first and last factors with opposite signs, ``σ − φ``).  :func:`unwrap_angles` therefore
shifts each angle of a waypoint by a multiple of 2π so that it differs from the previous
waypoint's by at most π: every angle takes the short way.  It keeps the waypoint's own
angle triple otherwise: the other triple of the same rotation (e.g. ``(a + π, π − b, c + π)``
in the ``xyz`` conventions) is not searched.  Joint coordinates are never shifted (they
have limits).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from taut.errors import TrajectoryError
from taut.model import Robot

__all__ = ["angle_columns", "complete_waypoints", "unwrap_angles", "validate_waypoints"]


def angle_columns(robot: Robot) -> slice:
    """The columns of a pose that hold orientation angles.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    slice
        None for a point mass, ``θ`` for a planar rigid platform, the three angles of a
        spatial one.

    Examples
    --------
    >>> from taut.model import example
    >>> angle_columns(example("planar-4cable")), angle_columns(example("spatial-8cable"))
    (slice(2, 3, None), slice(3, 6, None))
    """
    d = robot.dimension
    return slice(d, robot.wrench_dim)


def validate_waypoints(robot: Robot, waypoints: npt.ArrayLike, what: str = "waypoints") -> np.ndarray:
    """Waypoints as an array ``(N, pose_size)``, ``N ≥ 2``: raises :class:`TrajectoryError`
    for fewer than two, a wrong size, a coordinate that is not finite, or a joint coordinate
    outside its limits."""
    try:
        W = np.array(waypoints, dtype=float)
    except (TypeError, ValueError):
        raise TrajectoryError(f"{what}: expected lists of numbers, got {waypoints!r}") from None
    if W.size == 0:
        raise TrajectoryError(f"{what}: a trajectory needs at least 2 waypoints, got none")
    if W.ndim != 2 or W.shape[1] != robot.pose_size:
        raise TrajectoryError(
            f"{what}: {robot.name} takes poses of {robot.pose_size} coordinates ({', '.join(robot.pose_names)}), "
            f"got an array of shape {W.shape}"
        )
    if len(W) < 2:
        raise TrajectoryError(f"{what}: a trajectory needs at least 2 waypoints, got {len(W)}")
    bad = np.argwhere(~np.isfinite(W))
    if len(bad):
        k, j = bad[0]
        raise TrajectoryError(f"{what}: waypoint {k + 1}, coordinate {robot.pose_names[j]} is not finite ({W[k, j]})")
    if robot.n_joints:
        q = W[:, robot.wrench_dim :]
        lo, hi = robot.joint_limits[:, 0], robot.joint_limits[:, 1]
        out = np.argwhere((q < lo) | (q > hi))
        if len(out):
            k, j = out[0]
            raise TrajectoryError(
                f"{what}: waypoint {k + 1}: joint {robot.pose_names[robot.wrench_dim + j]} = {q[k, j]:g} "
                f"is outside its limits [{lo[j]:g}, {hi[j]:g}]"
            )
    return W


def complete_waypoints(robot: Robot, waypoints: npt.ArrayLike, *, what: str = "waypoints") -> np.ndarray:
    """Waypoints that give only a position become poses: the rest of the pose is taken from the
    robot's first reference pose, or is zero orientation with every joint at mid-range when it
    has none.  Anything else is returned as an array, unchecked
    (:func:`trajectory_from_waypoints` checks it).

    Parameters
    ----------
    robot : Robot
    waypoints : array_like, shape (N, dimension) or (N, pose_size)
    what : str, default "waypoints"
        What the waypoints are, for error messages.

    Returns
    -------
    ndarray, shape (N, pose_size)

    Raises
    ------
    TrajectoryError
        For waypoints that are not numbers.

    Examples
    --------
    >>> from taut.model import example
    >>> complete_waypoints(example("planar-4cable"), [[0.1, 0.2], [0.3, 0.4]])
    array([[0.1, 0.2, 0. ],
           [0.3, 0.4, 0. ]])
    """
    try:
        W = np.atleast_2d(np.array(waypoints, dtype=float))
    except (TypeError, ValueError):
        raise TrajectoryError(f"{what}: expected lists of numbers, got {waypoints!r}") from None
    d = robot.dimension
    if W.ndim != 2 or W.shape[1] != d or d == robot.pose_size:
        return W
    if robot.reference is not None and robot.reference.poses:
        rest = np.asarray(next(iter(robot.reference.poses.values())), float)[d:]
    else:
        rest = np.concatenate([np.zeros(robot.wrench_dim - d), robot.joint_limits.mean(axis=1)])
    return np.concatenate([W, np.broadcast_to(rest, (len(W), robot.pose_size - d))], axis=1)


def unwrap_angles(robot: Robot, waypoints: npt.ArrayLike) -> np.ndarray:
    """The waypoints with each orientation angle shifted by a multiple of 2π so that it differs
    from the previous waypoint's by at most π (the short way); the first waypoint is kept,
    joint coordinates are never shifted (module docstring).

    Parameters
    ----------
    robot : Robot
    waypoints : array_like, shape (N, pose_size)

    Returns
    -------
    ndarray, shape (N, pose_size)
        A new array.

    Raises
    ------
    TrajectoryError
        For waypoints that are not numbers or not poses of the robot.

    Examples
    --------
    From ``θ = 3`` to ``θ = −3`` the short way goes on through π:

    >>> from taut.model import example
    >>> unwrap_angles(example("planar-4cable"), [[0.0, 0.0, 3.0], [0.0, 0.0, -3.0]])[1, 2]
    np.float64(3.283...)
    """
    try:
        W = np.array(waypoints, dtype=float)
    except (TypeError, ValueError):
        raise TrajectoryError(f"waypoints: expected lists of numbers, got {waypoints!r}") from None
    if W.ndim != 2 or W.shape[1] != robot.pose_size:
        raise TrajectoryError(
            f"waypoints: {robot.name} takes poses of {robot.pose_size} coordinates, got an array of shape {W.shape}"
        )
    cols = angle_columns(robot)
    for k in range(1, len(W)):
        step = W[k, cols] - W[k - 1, cols]
        W[k, cols] -= 2 * math.pi * np.round(step / (2 * math.pi))
    return W
