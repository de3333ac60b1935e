"""Vector products of points given as arrays (leading batch axes allowed)."""

from __future__ import annotations

import numpy as np


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product over the last axis: the moment of a force ``b`` applied at ``a``, in the
    plane or in space.

    Parameters
    ----------
    a, b : ndarray, shape (..., 2) or (..., 3)
        Vectors, broadcast together.

    Returns
    -------
    ndarray, shape (...) or (..., 3)
        The scalar ``a_x b_y − a_y b_x`` for planar vectors, the vector product for spatial
        ones.

    Examples
    --------
    >>> cross(np.array([2.0, 0.0]), np.array([0.0, 3.0]))
    np.float64(6.0)
    >>> cross(np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]))
    array([0., 0., 1.])
    """
    if a.shape[-1] == 2:
        return a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return np.stack(
        [
            a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1],
            a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2],
            a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0],
        ],
        -1,
    )
