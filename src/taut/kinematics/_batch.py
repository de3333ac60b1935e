"""Batched inverse kinematics in a Numba kernel: cable lengths and structure matrices of
many poses at once, for workspace grids (Rushton 2022, §2.1.1, Eqs. 2.1,
2.8 and 2.10; the conventions of :mod:`taut.kinematics._inverse`).

Same quantities as :func:`taut.kinematics.inverse_kinematics` for robots without
jointed bodies (point-mass, planar and spatial rigid platforms, all orientation
conventions, cables through swivelling pulleys as in :mod:`taut.kinematics._swivel`), in one
pass over the poses instead of a chain of NumPy temporaries.  A pose with a zero-length
cable, or an anchor on a swivel axis or inside a pulley, does not raise: it is flagged in
``ok`` and its structure matrix is left zero, which is what a workspace grid needs.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.1, Eqs. 2.1, 2.8 and 2.10. (docs/references.bib: rushton2022)
.. [2] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
"""

from __future__ import annotations

import numpy as np
from numba import njit

from taut.geometry import CONVENTIONS, axis_frames, rotation_into
from taut.kinematics._paths import MIN_LENGTH
from taut.kinematics._swivel import SINGULAR_TOL, swivel_parameters
from taut.model import Robot


@njit(cache=True, nogil=True)
def _swivel_cable(
    b: np.ndarray, i: int, exits: np.ndarray, axes: np.ndarray, r: float, normals: np.ndarray, tol: float, u: np.ndarray
) -> tuple[float, bool]:
    """Length of cable ``i`` from its pulley at ``exits[i]`` (unit ``axes[i]``, radius ``r``)
    to the anchor ``b``, and whether it has a tangent point; ``u`` receives its unit vector
    (the formulas of :func:`taut.kinematics.swivel_paths`, ``normals[i]`` the pulley
    plane's normal direction for an anchor on the axis)."""
    v0, v1, v2 = b[0] - exits[i, 0], b[1] - exits[i, 1], b[2] - exits[i, 2]
    k0, k1, k2 = axes[i, 0], axes[i, 1], axes[i, 2]
    h = v0 * k0 + v1 * k1 + v2 * k2
    w0, w1, w2 = v0 - h * k0, v1 - h * k1, v2 - h * k2
    d = np.sqrt(w0 * w0 + w1 * w1 + w2 * w2)
    scale = r + np.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
    good = d > tol * scale
    if good:
        e0, e1, e2 = w0 / d, w1 / d, w2 / d
    else:
        e0, e1, e2 = normals[i, 0], normals[i, 1], normals[i, 2]
    x = d - r
    free = np.sqrt(max(x * x + h * h - r * r, 0.0))
    good = good and free > tol * scale
    wrap = np.arctan2(x, h) + np.arctan2(r, free)
    if wrap < 0.0:
        wrap += 2.0 * np.pi
    if good:
        # tangent point D + r e + r (−cos β e + sin β k), relative to b
        ce, sk = r - r * np.cos(wrap), r * np.sin(wrap)
        t0, t1, t2 = ce * e0 + sk * k0 - v0, ce * e1 + sk * k1 - v1, ce * e2 + sk * k2 - v2
        span = np.sqrt(t0 * t0 + t1 * t1 + t2 * t2)
        u[0], u[1], u[2] = t0 / span, t1 / span, t2 / span
    return r * wrap + free, good


@njit(cache=True, nogil=True)
def _ik_kernel(
    poses: np.ndarray,
    exits: np.ndarray,
    anchors: np.ndarray,
    dim: int,
    point_mass: bool,
    conv: int,
    min_length: float,
    swivel: np.ndarray,
    axes: np.ndarray,
    radii: np.ndarray,
    normals: np.ndarray,
    swivel_tol: float,
    lengths: np.ndarray,
    W: np.ndarray,
    ok: np.ndarray,
) -> None:
    N = poses.shape[0]
    n = exits.shape[0]
    R = np.zeros((3, 3))
    work = np.empty((3, 3))
    arm = np.zeros(3)
    u = np.zeros(3)
    b = np.zeros(3)
    for k in range(N):
        if not point_mass:
            if dim == 2:
                ct = np.cos(poses[k, 2])
                st = np.sin(poses[k, 2])
                R[0, 0] = ct
                R[0, 1] = -st
                R[1, 0] = st
                R[1, 1] = ct
            else:
                rotation_into(conv, poses[k, 3], poses[k, 4], poses[k, 5], R, work)
        good = True
        for i in range(n):
            for r in range(dim):
                acc = 0.0
                if not point_mass:
                    for s in range(dim):
                        acc += R[r, s] * anchors[i, s]
                arm[r] = acc
            if swivel[i]:
                for r in range(3):
                    b[r] = poses[k, r] + arm[r]
                ll, tangent = _swivel_cable(b, i, exits, axes, radii[i], normals, swivel_tol, u)
                lengths[k, i] = ll
                if not tangent:
                    good = False
                    continue
            else:
                ll = 0.0
                for r in range(dim):
                    v = exits[i, r] - poses[k, r] - arm[r]
                    u[r] = v
                    ll += v * v
                ll = np.sqrt(ll)
                lengths[k, i] = ll
                if ll < min_length:
                    good = False
                    continue
                for r in range(dim):
                    u[r] /= ll
            for r in range(dim):
                W[k, r, i] = u[r]
            if point_mass:
                continue
            if dim == 2:
                W[k, 2, i] = arm[0] * u[1] - arm[1] * u[0]
            else:
                W[k, 3, i] = arm[1] * u[2] - arm[2] * u[1]
                W[k, 4, i] = arm[2] * u[0] - arm[0] * u[2]
                W[k, 5, i] = arm[0] * u[1] - arm[1] * u[0]
        ok[k] = good
        if not good:
            for r in range(W.shape[1]):
                for i in range(n):
                    W[k, r, i] = 0.0


def supports_batch(robot: Robot) -> bool:
    """True when the kernel handles the robot (no jointed bodies, no swivelling pulleys on a
    planar robot, no obstacles its straight cables could meet, no cables through via points)."""
    return (
        robot.n_joints == 0
        and not (robot.dimension == 2 and robot.swivel_cables)
        and not robot.obstacles
        and not robot.routed_cables
    )


def kernel_structure_matrices(robot: Robot, arr: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`taut.kinematics.batch_structure_matrices` through the Numba kernel, for a robot
    it supports (:func:`supports_batch`) and ``(N, pose_size)`` poses already checked."""
    N, n, m, d = arr.shape[0], robot.n_cables, robot.wrench_dim, robot.dimension
    lengths = np.empty((N, n))
    W = np.zeros((N, m, n))
    ok = np.empty(N, np.bool_)
    swivel = np.zeros(n, np.bool_)
    axes, radii, normals = np.zeros((n, 3)), np.zeros(n), np.zeros((n, 3))
    if robot.swivel_cables:
        idx, unit_axes, pulley_radii = swivel_parameters(robot)
        axes[idx], radii[idx], swivel[idx] = unit_axes, pulley_radii, True
        normals[idx] = axis_frames(axes[idx])[:, :, 1]
    _ik_kernel(
        np.ascontiguousarray(arr),
        robot.exits,
        robot.anchors,
        d,
        robot.is_point_mass,
        CONVENTIONS.index(robot.orientation),
        MIN_LENGTH,
        swivel,
        axes,
        radii,
        normals,
        SINGULAR_TOL,
        lengths,
        W,
        ok,
    )
    return lengths, W, ok
