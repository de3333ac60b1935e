"""Vector products of points given as arrays (leading batch axes allowed)."""

from __future__ import annotations

import numpy as np


def cross(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cross product over the last axis: the scalar ``a_x b_y − a_y b_x`` for planar vectors
    (shape ``(..., 2)`` → ``(...)``), the vector product for spatial ones (``(..., 3)`` →
    ``(..., 3)``) — the moment of a force ``b`` applied at ``a`` in either dimension."""
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
