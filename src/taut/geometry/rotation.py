"""Rotation matrices for the orientation conventions of ``DESIGN.md`` §2.

* ``xyz-fixed``: ``R = Rz(c) Ry(b) Rx(a)`` — rotations about the fixed x, y, z axes
  (the convention of Tables 4.3–4.6 of ``001_eb92e2f6589fc229.txt``).
* ``xyz-moving``: ``R = Rx(a) Ry(b) Rz(c)`` — Eq. (3.1.1) of ``004_f30792d78b61e7c2.txt``.
* ``tilt-torsion``: ``R = Rz(φ) Ry(θ) Rz(σ − φ)`` — Eq. (1) of ``002_19d5d688a3999fb0.txt``;
  the angles are given in the order ``(φ, θ, σ)``.

All functions work over arrays: angles of shape ``(..., 3)`` give matrices ``(..., 3, 3)``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

CONVENTIONS = ("xyz-fixed", "xyz-moving", "tilt-torsion")


@njit(cache=True)
def _axis(k: int, t: float) -> np.ndarray:
    """Rotation by ``t`` about axis ``k`` (0: x, 1: y, 2: z)."""
    c, s = math.cos(t), math.sin(t)
    M = np.zeros((3, 3))
    i, j = (k + 1) % 3, (k + 2) % 3
    M[k, k] = 1.0
    M[i, i], M[i, j], M[j, i], M[j, j] = c, -s, s, c
    return M


@njit(cache=True)
def _matrices(angles: np.ndarray, code: int) -> np.ndarray:
    """Matrices ``(N, 3, 3)`` of the angles ``(N, 3)``, convention ``code`` (index in
    :data:`CONVENTIONS`).  Compiled for the same reason as :func:`angles_kernel`."""
    out = np.empty((angles.shape[0], 3, 3))
    for n in range(angles.shape[0]):
        a, b, c = angles[n, 0], angles[n, 1], angles[n, 2]
        if code == 0:
            out[n] = _axis(2, c) @ _axis(1, b) @ _axis(0, a)
        elif code == 1:
            out[n] = _axis(0, a) @ _axis(1, b) @ _axis(2, c)
        else:
            out[n] = _axis(2, a) @ _axis(1, b) @ _axis(2, c - a)
    return out


def planar_rotation(theta) -> np.ndarray:
    """``R(θ)`` of shape ``(..., 2, 2)`` for angles of shape ``(...)``."""
    theta = np.asarray(theta, dtype=float)
    c, s = np.cos(theta), np.sin(theta)
    return np.stack([np.stack([c, -s], -1), np.stack([s, c], -1)], -2)


def rotation_matrix(angles, convention: str = "xyz-fixed") -> np.ndarray:
    """Rotation matrices ``(..., 3, 3)`` from three angles ``(..., 3)`` in ``convention``."""
    if convention not in CONVENTIONS:
        raise ValueError(f"unknown orientation convention {convention!r}; expected one of {CONVENTIONS}")
    angles = np.asarray(angles, dtype=float)
    flat = np.ascontiguousarray(angles.reshape(-1, 3))
    return _matrices(flat, CONVENTIONS.index(convention)).reshape(angles.shape[:-1] + (3, 3))


@njit(cache=True)
def angles_kernel(R: np.ndarray, code: int) -> np.ndarray:
    """Angles of the matrices ``R`` (``(N, 3, 3)``), convention ``code`` (index in
    :data:`CONVENTIONS`): the core of :func:`angles_from_matrix`, for compiled callers.  Compiled: tracking converts one matrix per update, where array
    ufuncs on a single matrix cost more than the arithmetic."""
    out = np.empty((R.shape[0], 3))
    for k in range(R.shape[0]):
        M = R[k]
        if code == 0:
            b = math.asin(min(1.0, max(-1.0, -M[2, 0])))
            a = math.atan2(M[2, 1], M[2, 2])
            c = math.atan2(M[1, 0], M[0, 0])
        elif code == 1:
            b = math.asin(min(1.0, max(-1.0, M[0, 2])))
            a = math.atan2(-M[1, 2], M[2, 2])
            c = math.atan2(-M[0, 1], M[0, 0])
        else:
            b = math.acos(min(1.0, max(-1.0, M[2, 2])))
            a = math.atan2(M[1, 2], M[0, 2])
            c = math.atan2(M[2, 1], -M[2, 0]) + a  # σ − φ, then σ
        out[k, 0], out[k, 1], out[k, 2] = a, b, c
    return out


def angles_from_matrix(R, convention: str = "xyz-fixed") -> np.ndarray:
    """Inverse of :func:`rotation_matrix`: angles ``(..., 3)`` with the middle angle in
    ``[-π/2, π/2]`` (``[0, π]`` for tilt-and-torsion)."""
    if convention not in CONVENTIONS:
        raise ValueError(f"unknown orientation convention {convention!r}; expected one of {CONVENTIONS}")
    R = np.asarray(R, dtype=float)
    flat = np.ascontiguousarray(R.reshape(-1, 3, 3))
    return angles_kernel(flat, CONVENTIONS.index(convention)).reshape(R.shape[:-2] + (3,))
