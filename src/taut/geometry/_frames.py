"""Frames about an axis: the one construction of a unit normal to a given axis that taut uses
wherever a frame must be attached to a direction (a swivelling pulley's winch frame, the zero
direction of its hinge angle, the pulley plane of an anchor on its axis).

The normal is the fixed ``x`` axis made normal to ``k`` by Gram–Schmidt, or the fixed ``y``
axis when ``k`` is within about 26° of ``x`` (``|k_x| ≥ 0.9``), so that the construction is
well conditioned for every axis and gives the identity frame for ``k = (0, 0, 1)``; WireX
writes winch frames the same way, so swivel angles read back from its files agree.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import TautError

__all__ = ["axis_frames"]


def axis_frames(axes: npt.ArrayLike) -> np.ndarray:
    """Rotations whose third column is each unit axis.

    Parameters
    ----------
    axes : array_like, shape (s, 3) or (3,)
        Axes, normalised here; none may be zero.

    Returns
    -------
    numpy.ndarray, shape (s, 3, 3) or (3, 3)
        ``[e, k × e, k]`` with ``e`` the unit normal of ``k`` nearest the fixed ``x`` axis
        (``y`` for an axis within 26° of ``x``).

    Raises
    ------
    TautError
        If an axis is zero or not finite.

    Examples
    --------
    >>> from taut.geometry import axis_frames
    >>> axis_frames([0.0, 0.0, 2.0])
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    k = np.asarray(axes, dtype=float)
    single = k.ndim == 1
    k = np.atleast_2d(k)
    if k.shape[-1] != 3 or k.ndim != 2:
        raise TautError(f"axis_frames: expected axes of shape (s, 3), got {np.shape(axes)}")
    norm = np.linalg.norm(k, axis=1, keepdims=True)
    if not (np.isfinite(norm).all() and (norm > 0).all()):
        raise TautError("axis_frames: an axis is zero or not finite")
    k = k / norm
    helper = np.where(np.abs(k[:, :1]) < 0.9, np.array([[1.0, 0.0, 0.0]]), np.array([[0.0, 1.0, 0.0]]))
    e = helper - np.einsum("si,si->s", helper, k)[:, None] * k
    e /= np.linalg.norm(e, axis=1, keepdims=True)
    frames = np.stack([e, np.cross(k, e), k], axis=2)
    return frames[0] if single else frames
