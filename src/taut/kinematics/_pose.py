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
    """Validate poses; return ``(array (N, pose_size), was_single)``.

    Raises :class:`PoseError` for a wrong size, a non-finite coordinate, or a joint
    coordinate outside its limits."""
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


def platform_frame(robot: Robot, poses: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Position ``p (N, d)`` and rotation ``R (N, d, d)`` of the platform frame."""
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
    """Frames of all bodies: positions ``(N, B, d)`` and rotations ``(N, B, d, d)``,
    body 0 being the platform, body ``k`` the ``k``-th entry of ``platform.bodies``."""
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
    """Platform anchors ``b_i`` in the fixed frame, ``(N, n, d)`` (``(n, d)`` for one pose)."""
    arr, single = as_poses(robot, poses)
    b = anchors_at(robot, arr)
    return b[0] if single else b


def anchors_at(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """:func:`anchor_points` without the checks: ``poses`` is an ``(N, pose_size)`` array
    already checked by :func:`~taut.kinematics.as_poses` (solvers and samplers call it
    on their own iterates, which may leave the joint limits); returns ``(N, n, d)``."""
    if robot.is_point_mass:
        return np.broadcast_to(poses[:, None, : robot.dimension], (poses.shape[0], robot.n_cables, robot.dimension))
    if robot.n_joints == 0:
        p, R = platform_frame(robot, poses)
        return p[:, None, :] + np.einsum("nij,kj->nki", R, robot.anchors)
    pos, rot = body_frames(robot, poses)
    idx = robot.cable_bodies
    return pos[:, idx, :] + np.einsum("nkij,kj->nki", rot[:, idx], robot.anchors)
