"""The compiled kernel of :func:`taut.geometry.angles_from_matrix`, in a module of
its own so that Numba is imported only by the code that calls it (the conventions are those
of :data:`taut.geometry.CONVENTIONS`, by index)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True)
def matrix_angles(R: np.ndarray, code: int) -> np.ndarray:
    """The angles of rotation matrices, compiled: the kernel of :func:`angles_from_matrix`
    (tracking converts one matrix per update, where array ufuncs on a single matrix cost more
    than the arithmetic).

    Parameters
    ----------
    R : ndarray, shape (N, 3, 3)
        Rotation matrices, C-contiguous floats.
    code : int
        The convention's index in :data:`~taut.geometry.CONVENTIONS`.

    Returns
    -------
    ndarray, shape (N, 3)
        Angles [rad], as :func:`~taut.geometry.angles_from_matrix` gives them.

    Examples
    --------
    >>> from taut.geometry import rotation_matrix
    >>> matrix_angles(rotation_matrix([[0.1, 0.2, 0.3]]), 0)
    array([[0.1, 0.2, 0.3]])
    """
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
