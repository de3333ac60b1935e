"""Compiled kernels of :mod:`taut.geometry.rotation`, in a module of their own so that
Numba is imported only by the code that calls them (the conventions are those of
:data:`taut.geometry.rotation.CONVENTIONS`, by index)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit


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
def matrices(angles: np.ndarray, code: int) -> np.ndarray:
    """Matrices ``(N, 3, 3)`` of the angles ``(N, 3)``, convention ``code`` (index in
    :data:`~taut.geometry.rotation.CONVENTIONS`).  Compiled for the same reason as :func:`angles`."""
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


@njit(cache=True)
def angles(R: np.ndarray, code: int) -> np.ndarray:
    """Angles of the matrices ``R`` (``(N, 3, 3)``), convention ``code`` (index in
    :data:`~taut.geometry.rotation.CONVENTIONS`).  Compiled: tracking converts one matrix per update, where array
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
