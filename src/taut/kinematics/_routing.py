"""Routed cables (``cables[].via``): a cable through via points on the fixed frame or on
platform bodies is the chain of straight segments exit → via points → anchor, with one tension
along it (a frictionless eyelet passes it on unchanged).

Its length is the sum of the segments' lengths.  By virtual work the cable, of tension ``τ``,
pulls each point ``P_k`` of its chain towards both its neighbours, with the force ``τ f_k``,
``f_k = û(P_{k−1} − P_k) + û(P_{k+1} − P_k)`` (``û`` the unit vector; the anchor has one
neighbour, so ``f`` is its ``u_i``), and ``l̇ = −Σ_k f_k · Ṗ_k`` over the points that move:
the cable's column of the structure matrix is ``Σ_k [f_k ; (P_k − p) × f_k]`` over the anchor
and the via points on moving bodies, and its joint rows ``Σ_k f_k · ∂P_k/∂q_j`` (the
cable-routing matrix of Lau, Oetomo & Halgamuge 2013, §III–IV, which sums each segment's
force on the two links it joins).  The anchor's term is that of a straight cable from the last
via point.

References
----------
.. [1] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
   manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions on
   Robotics 29(5), 2013, §III (the cable-routing matrix), §IV (the Jacobian and the joint-space
   forces). (docs/references.bib: lau2013)
"""

from __future__ import annotations

import numpy as np

from taut.kinematics._pose import body_frames, require_checked
from taut.model import Robot

#: The body index of a via point on the fixed frame (:attr:`~taut.model.Robot.via_points`).
FIXED = -1


def via_points_at(robot: Robot, poses: np.ndarray) -> np.ndarray:
    """The via points of the routed cables (``cables[].via``) in the fixed frame.

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`~taut.kinematics.as_poses`.

    Returns
    -------
    ndarray, shape (N, V, d)
        Every via point [m], in cable order then in the order the cable runs through them
        from its exit point; ``V = 0`` for a robot without routed cables.

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.

    References
    ----------
    .. [1] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
       manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions
       on Robotics 29(5), 2013, §III. (docs/references.bib: lau2013)

    Examples
    --------
    A cable through an eyelet 0.1 m above the platform's origin:

    >>> import numpy as np
    >>> from taut.model import example, robot_from_dict, robot_to_dict
    >>> from taut.kinematics import via_points_at
    >>> data = robot_to_dict(example("spatial-8cable"))
    >>> data["cables"][0]["via"] = [{"point": [0.0, 0.0, 0.1]}]
    >>> via_points_at(robot_from_dict(data), np.array([[0.2, 0.0, 0.0, 0.0, 0.0, 0.0]]))
    array([[[0.2, 0. , 0.1]]])
    """
    require_checked(robot, poses)
    _, bodies, points = robot.via_points
    out = np.broadcast_to(points, (poses.shape[0], *points.shape)).copy()
    moving = bodies != FIXED
    if moving.any():
        pos, rot = body_frames(robot, poses)
        k = bodies[moving]
        out[:, moving] = pos[:, k] + np.einsum("nvij,vj->nvi", rot[:, k], points[moving])
    return out


def routed_segments(
    robot: Robot, anchors: np.ndarray, vias: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The chains of the routed cables at each pose.

    Returns the length of each routed cable's chain from its exit point to its last via point
    ``(N, n)`` (0 for the other cables), its last via point ``(N, n, d)`` (the exit point for
    the others: where the straight segment to the anchor starts), the shortest segment of that
    part of each chain ``(N, n)`` (``inf`` for the others) and the directions
    ``f_k`` of the force the cable's unit tension exerts on each via point ``(N, V, d)``
    (zero where a segment is shorter than 1e-300 m)."""
    cables, _, _ = robot.via_points
    N = vias.shape[0]
    prev = np.empty_like(vias)
    first = np.r_[True, cables[1:] != cables[:-1]]
    prev[:, first] = robot.exits[cables[first]]
    prev[:, ~first] = vias[:, np.flatnonzero(~first) - 1]
    last = np.r_[cables[1:] != cables[:-1], True]
    after = np.empty_like(vias)
    after[:, last] = anchors[:, cables[last]]
    after[:, ~last] = vias[:, np.flatnonzero(~last) + 1]
    back, ahead = prev - vias, after - vias
    lb = np.sqrt(np.einsum("nvi,nvi->nv", back, back))
    la = np.sqrt(np.einsum("nvi,nvi->nv", ahead, ahead))
    f = back / np.maximum(lb, 1e-300)[..., None] + ahead / np.maximum(la, 1e-300)[..., None]
    chain = np.zeros((N, robot.n_cables))
    np.add.at(chain.T, cables, lb.T)  # on the transposed views: one index array, the cable's
    shortest = np.full((N, robot.n_cables), np.inf)
    np.minimum.at(shortest.T, cables, lb.T)
    starts = np.broadcast_to(robot.exits, anchors.shape).copy()
    starts[:, cables[last]] = vias[:, last]
    return chain, starts, shortest, f


def via_wrench(robot: Robot, poses: np.ndarray, vias: np.ndarray, forces: np.ndarray) -> np.ndarray:
    """The via points' part of the structure matrix, ``Σ_k [f_k ; (P_k − p) × f_k]`` over the
    via points on moving bodies, ``(N, m, n)``."""
    cables, bodies, _ = robot.via_points
    d, m = robot.dimension, robot.wrench_dim
    moving = bodies != FIXED
    f = np.where(moving[None, :, None], forces, 0.0)
    rows = [f]
    if not robot.is_point_mass:
        r = vias - poses[:, None, :d]
        if d == 2:
            rows.append((r[..., 0] * f[..., 1] - r[..., 1] * f[..., 0])[..., None])
        else:
            rows.append(np.cross(r, f))
    per_point = np.concatenate(rows, axis=-1)  # (N, V, m)
    W = np.zeros((poses.shape[0], m, robot.n_cables))
    np.add.at(W.transpose(2, 0, 1), cables, per_point.transpose(1, 0, 2))
    return W
