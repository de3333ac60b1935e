"""The compiled rotation kernels, in a module of their own so that Numba is imported only by
the code that calls them: the angles of a matrix (:func:`taut.geometry.angles_from_matrix`),
and the matrix of three angles built one axis rotation at a time, which the batched inverse
kinematics and the dynamics kernels share (the conventions are those of
:data:`taut.geometry.CONVENTIONS`, by index)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True)
def matrix_angles(R: np.ndarray, code: int) -> np.ndarray:
    """Angles of the matrices ``R`` (``(N, 3, 3)``), convention ``code`` (index in
    :data:`~taut.geometry.CONVENTIONS`).  Compiled: tracking converts one matrix
    per update, where array ufuncs on a single matrix cost more than the arithmetic."""
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


@njit(cache=True, nogil=True)
def rotate_about_axis(axis: int, t: float, P: np.ndarray, out: np.ndarray) -> None:
    """``out = P @ Rot(axis, t)`` for a 3×3 ``P``: a rotation by ``t`` [rad] about the fixed
    axis ``axis`` (0 x, 1 y, 2 z) applied on the right.

    Parameters
    ----------
    axis : int
        0, 1 or 2 for x, y or z.
    t : float
        The angle [rad].
    P : numpy.ndarray, shape (3, 3)
        The matrix to rotate.
    out : numpy.ndarray, shape (3, 3)
        Where the product is written (not ``P``).

    Examples
    --------
    >>> import numpy as np
    >>> from taut.geometry import rotate_about_axis
    >>> out = np.empty((3, 3))
    >>> rotate_about_axis(2, np.pi / 2, np.eye(3), out)
    >>> np.round(out, 12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
    """
    c, s = np.cos(t), np.sin(t)
    i, j = (axis + 1) % 3, (axis + 2) % 3
    for r in range(3):
        out[r, axis] = P[r, axis]
        out[r, i] = c * P[r, i] + s * P[r, j]
        out[r, j] = -s * P[r, i] + c * P[r, j]


@njit(cache=True, nogil=True)
def rotation_into(code: int, a: float, b: float, c: float, R: np.ndarray, work: np.ndarray) -> None:
    """Write into ``R`` the rotation of the angles ``(a, b, c)`` in convention ``code``:
    0 ``xyz-fixed`` ``Rz(c) Ry(b) Rx(a)``, 1 ``xyz-moving`` ``Rx(a) Ry(b) Rz(c)``,
    2 ``tilt-torsion`` ``Rz(a) Ry(b) Rz(c − a)`` (:func:`taut.geometry.rotation_matrix`).

    Parameters
    ----------
    code : int
        Index of the convention in :data:`taut.geometry.CONVENTIONS`.
    a, b, c : float
        The three angles [rad].
    R, work : numpy.ndarray, shape (3, 3)
        The result, and scratch space.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.geometry import rotation_into, rotation_matrix
    >>> R, work = np.empty((3, 3)), np.empty((3, 3))
    >>> rotation_into(2, 0.3, 0.2, 0.1, R, work)
    >>> bool(np.allclose(R, rotation_matrix([0.3, 0.2, 0.1], "tilt-torsion")))
    True
    """
    if code == 0:
        axes, angles = (2, 1, 0), (c, b, a)
    elif code == 1:
        axes, angles = (0, 1, 2), (a, b, c)
    else:
        axes, angles = (2, 1, 2), (a, b, c - a)
    for r in range(3):
        for q in range(3):
            R[r, q] = 1.0 if r == q else 0.0
    for k in range(3):
        rotate_about_axis(axes[k], angles[k], R, work)
        R[:, :] = work
