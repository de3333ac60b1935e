"""Poses and platform frames.

A pose is the platform position, its orientation (θ for planar rigid platforms, three
angles in the robot's convention for spatial ones, nothing for a point mass) and the
joint coordinates of extra bodies (``docs/architecture.md`` §2.2).  Functions take arrays of poses
``(N, pose_size)``; a single pose ``(pose_size,)`` is accepted everywhere.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import PoseError
from taut.geometry import planar_rotation, rotation_matrix
from taut.model import MAX_MAGNITUDE, Robot


def as_poses(robot: Robot, poses: npt.ArrayLike) -> tuple[np.ndarray, bool]:
    """Check poses and return them as an ``(N, pose_size)`` array.

    Parameters
    ----------
    robot : Robot
        The robot whose poses these are (``docs/architecture.md`` §2.2).
    poses : array_like, shape (N, pose_size) or (pose_size,)
        Positions [m], orientation angles [rad] and joint coordinates [m or rad].

    Returns
    -------
    poses : ndarray, shape (N, pose_size)
        The poses as floats (a copy only where the input was not a float array).
    single : bool
        True when one pose ``(pose_size,)`` was given: the callers then drop the batch axis
        of their results.

    Raises
    ------
    PoseError
        A pose of the wrong size, a coordinate that is not a number, not finite or beyond
        ``1e9``, or a joint coordinate outside its limits.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import as_poses
    >>> robot = example("planar-4cable")
    >>> as_poses(robot, [0.1, 0.2, 0.0])
    (array([[0.1, 0.2, 0. ]]), True)
    """
    try:
        arr = np.asarray(poses, dtype=float)
    except (TypeError, ValueError):
        raise PoseError(f"a pose must be numbers, got {poses!r}") from None
    single = arr.ndim == 1
    arr = np.atleast_2d(arr)
    if arr.ndim != 2 or arr.shape[1] != robot.pose_size:
        raise PoseError(
            f"{robot.name}: a pose has {robot.pose_size} coordinates ({', '.join(robot.pose_names)}), got shape {np.shape(poses)}"
        )
    if not np.all(np.isfinite(arr)):
        bad = np.argwhere(~np.isfinite(arr))[0]
        raise PoseError(f"{robot.name}: pose {bad[0] + 1}, coordinate {robot.pose_names[bad[1]]} is not finite")
    if arr.size and np.abs(arr).max() > MAX_MAGNITUDE:
        k, j = np.unravel_index(np.argmax(np.abs(arr)), arr.shape)
        raise PoseError(
            f"{robot.name}: pose {k + 1}, coordinate {robot.pose_names[j]} = {arr[k, j]:g} is beyond {MAX_MAGNITUDE:g}"
        )
    if robot.n_joints:
        q = arr[:, robot.wrench_dim :]
        lo, hi = robot.joint_limits[:, 0], robot.joint_limits[:, 1]
        out = (q < lo) | (q > hi)
        if out.any():
            k, j = np.argwhere(out)[0]
            raise PoseError(
                f"{robot.name}: pose {k + 1}: joint {robot.pose_names[robot.wrench_dim + j]} = {q[k, j]:g} is outside its limits [{lo[j]:g}, {hi[j]:g}]"
            )
    return arr, single


def require_checked(robot: Robot, poses: np.ndarray) -> None:
    """Raise :class:`PoseError` unless ``poses`` is an ``(N, pose_size)`` array (the functions
    that skip the checks of :func:`as_poses` still refuse what would crash them)."""
    if not isinstance(poses, np.ndarray) or poses.ndim != 2 or poses.shape[1] != robot.pose_size:
        raise PoseError(
            f"{robot.name}: expected an (N, {robot.pose_size}) array of poses checked by as_poses, "
            f"got {type(poses).__name__} of shape {np.shape(poses)}"
        )


def platform_frame(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position and rotation of the platform frame at checked poses.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`as_poses` (this function does not check them again).

    Returns
    -------
    p : ndarray, shape (N, d)
        The platform reference point [m].
    R : ndarray, shape (N, d, d)
        The platform rotation in the robot's orientation convention (``docs/architecture.md``
        §2.3); the identity for a point mass.

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import platform_frame
    >>> p, R = platform_frame(example("planar-4cable"), np.array([[0.1, 0.2, np.pi / 2]]))
    >>> p, np.round(R, 3)
    (array([[0.1, 0.2]]), array([[[ 0., -1.],
            [ 1.,  0.]]]))
    """
    require_checked(robot, poses)
    d = robot.dimension
    p = poses[:, :d]
    n = poses.shape[0]
    if robot.is_point_mass:
        R = np.broadcast_to(np.eye(d), (n, d, d))
    elif d == 2:
        R = planar_rotation(poses[:, 2])
    else:
        R = rotation_matrix(poses[:, 3:6], robot.orientation)
    return p, R


def _axis_rotation(axis: np.ndarray, q: np.ndarray, d: int) -> np.ndarray:
    if d == 2:
        return planar_rotation(q)
    k = axis / np.linalg.norm(axis)
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    s, c = np.sin(q)[:, None, None], np.cos(q)[:, None, None]
    return np.eye(3) + s * K + (1 - c) * (K @ K)  # Rodrigues


def body_frames(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Frames of the platform and of its jointed bodies at checked poses.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`as_poses`.

    Returns
    -------
    positions : ndarray, shape (N, B, d)
        Origins of the body frames [m]: body 0 is the platform, body ``k`` the ``k``-th
        entry of ``platform.bodies``.
    rotations : ndarray, shape (N, B, d, d)
        Their rotations in the fixed frame.

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform
       Geometry", Bachelor thesis, Czech Technical University in Prague, 2020, §3.1.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    The adjustable platform's second body slides along the platform's z axis by ``s23``:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import body_frames
    >>> pos, rot = body_frames(example("adjustable-8cable"), np.array([[0, 0, 1.0, 0, 0, 0, 0.5]]))
    >>> pos[0]
    array([[0. , 0. , 1. ],
           [0. , 0. , 1.5]])
    """
    p, R = platform_frame(robot, poses)
    pos, rot = [p], [np.asarray(R)]
    names = {"platform": 0}
    d = robot.dimension
    for k, body in enumerate(robot.platform.bodies, 1):
        names[body.name] = k
        par = names[body.parent]
        pp, RR = pos[par], rot[par]
        q = poses[:, robot.wrench_dim + k - 1]
        origin = np.zeros(d) if body.joint.origin is None else np.asarray(body.joint.origin, float)
        axis = np.asarray(body.joint.axis, float)
        if body.joint.kind == "prismatic":
            offset = origin[None, :] + q[:, None] * (axis / np.linalg.norm(axis))[None, :]
            pos.append(pp + np.einsum("nij,nj->ni", RR, offset))
            rot.append(RR)
        else:
            pos.append(pp + RR @ origin)
            rot.append(RR @ _axis_rotation(axis, q, d))
    return np.stack(pos, 1), np.stack(rot, 1)


def anchor_points(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Platform anchors ``b_i = p + R r_i`` in the fixed frame (Rushton 2022, Eq. 2.1).

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)

    Returns
    -------
    ndarray, shape (N, n, d) or (n, d) for one pose
        The anchor of each cable [m], on its own body for a jointed platform.

    Raises
    ------
    PoseError
        Poses that :func:`as_poses` refuses.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis,
       University of Waterloo, 2022, §2.1.1, Eq. 2.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import anchor_points
    >>> anchor_points(example("planar-4cable"), [0.1, 0.2, 0.0]).round(3)
    array([[0.  , 0.15],
           [0.2 , 0.15],
           [0.2 , 0.25],
           [0.  , 0.25]])
    """
    arr, single = as_poses(robot, poses)
    b = anchors_at(robot, arr)
    return b[0] if single else b


def anchors_at(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """:func:`anchor_points` without the checks of :func:`as_poses`.

    Solvers and samplers call it on their own iterates, which may leave the joint limits.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`as_poses`.

    Returns
    -------
    ndarray, shape (N, n, d)
        The anchor of each cable in the fixed frame [m].

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import anchors_at
    >>> anchors_at(example("planar-4cable"), np.array([[0.1, 0.2, 0.0]]))[0, 0].round(3)
    array([0.  , 0.15])
    """
    require_checked(robot, poses)
    if robot.is_point_mass:
        return np.broadcast_to(poses[:, None, : robot.dimension], (poses.shape[0], robot.n_cables, robot.dimension))
    if robot.n_joints == 0:
        p, R = platform_frame(robot, poses)
        return p[:, None, :] + np.einsum("nij,kj->nki", R, robot.anchors)
    pos, rot = body_frames(robot, poses)
    idx = robot.cable_bodies
    return pos[:, idx, :] + np.einsum("nkij,kj->nki", rot[:, idx], robot.anchors)
