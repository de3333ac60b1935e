"""Segment–segment distance (the *proximity* ``δ_ij`` of two line segments), §3.5 of
Lieskovský (2020) (Eq. 3.5.1: ``ξ_i v_i + d_ij = a_ij + ξ_j v_j``).

Given ``s_i = A_i B_i`` and ``s_j = A_j B_j``, find ``ξ_i, ξ_j ∈ [0, 1]`` minimising
``‖A_i + ξ_i v_i − A_j − ξ_j v_j‖``.  The source splits parallel (Tables 3.1–3.2) and skew
(§3.5.2) configurations; here one robust procedure covers every case, including collinear
and zero-length segments:

1. the skew (interior) candidate: the stationary point of the convex quadratic
   (``ξ_i = (b f − c e)/(a e − b²)``, clamped), followed by one alternation of clamped
   projections (``ξ_j`` from ``ξ_i``, then ``ξ_i`` from ``ξ_j``) — Ericson, *Real-Time
   Collision Detection* §5.1.9; when ``a e − b² ≤ 1e-14 a e`` (parallel) the stationary
   point is replaced by ``ξ_i = 0`` and the alternation finds an optimal pair, as for the
   configurations a–i of Table 3.1.  ``ξ_i`` is computed as ``−r'·u' / ‖u'‖²`` from the
   components ``r'``, ``u'`` of ``A_i − A_j`` and ``v_i`` orthogonal to ``v_j``: its error
   grows as ``1/sin θ`` with the angle ``θ`` of the segments, not as ``1/sin² θ``, so that
   the distance of crossing segments is within a few units in the last place of their
   coordinates at any angle;
2. the four endpoint candidates: each end point projected (clamped) onto the other segment.

The minimum over the candidates is returned.  Every candidate is the distance between two
actual points of the segments, so the result never under-estimates the proximity, and the
true minimum is among them (it lies in the interior of both segments — the skew candidate —
or involves an end point), so nearly parallel segments, where the stationary point is
ill-conditioned, are still measured to rounding accuracy.  A zero-length segment is a point.

Points may be 2-D (planar robots) or 3-D.  The kernel is compiled with Numba and runs over
flat batches; :func:`segment_distance` broadcasts any leading shapes.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.5, Eq. 3.5.1, Tables 3.1–3.2.
   (docs/references.bib: lieskovsky2020)
.. [2] C. Ericson, "Real-Time Collision Detection", Morgan Kaufmann, 2005, §5.1.9.
   (docs/references.bib: ericson2005)
"""

from __future__ import annotations

from typing import Literal, overload

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.errors import ArgumentError

__all__ = ["segment_distance"]

#: ``a e − b² ≤ PARALLEL_TOL · a e`` counts as parallel.
PARALLEL_TOL = 1e-14


@njit(cache=True, inline="always")
def _clamp01(x: float) -> float:
    return 0.0 if x < 0.0 else (1.0 if x > 1.0 else x)


@njit(cache=True)
def _point_segment(
    px: float, py: float, pz: float, ax: float, ay: float, az: float, vx: float, vy: float, vz: float, vv: float
) -> tuple[float, float]:
    """(squared distance, parameter) from point p to the segment a + t v."""
    t = 0.0
    if vv > 0.0:
        t = _clamp01(((px - ax) * vx + (py - ay) * vy + (pz - az) * vz) / vv)
    dx = ax + t * vx - px
    dy = ay + t * vy - py
    dz = az + t * vz - pz
    return dx * dx + dy * dy + dz * dz, t


@njit(cache=True)
def segment_distance_scalar(
    a1: np.ndarray, b1: np.ndarray, a2: np.ndarray, b2: np.ndarray
) -> tuple[float, float, float]:
    """The distance of two segments and where it is reached, for one pair of 3-D segments:
    the compiled kernel of :func:`segment_distance`, callable from other kernels.

    Parameters
    ----------
    a1, b1, a2, b2 : ndarray, shape (3,)
        End points [m].

    Returns
    -------
    delta : float
        The distance [m].
    xi_i, xi_j : float
        The parameters in ``[0, 1]`` of a closest pair of points.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.5, Eq. 3.5.1.
       (docs/references.bib: lieskovsky2020)
    .. [2] C. Ericson, "Real-Time Collision Detection", Morgan Kaufmann, 2005, §5.1.9.
       (docs/references.bib: ericson2005)

    Examples
    --------
    >>> segment_distance_scalar(np.zeros(3), np.array([1.0, 0, 0]), np.array([0.0, 0, 2]), np.array([0.0, 1, 2]))
    (2.0, 0.0, 0.0)
    """
    v1x, v1y, v1z = b1[0] - a1[0], b1[1] - a1[1], b1[2] - a1[2]
    v2x, v2y, v2z = b2[0] - a2[0], b2[1] - a2[1], b2[2] - a2[2]
    rx, ry, rz = a1[0] - a2[0], a1[1] - a2[1], a1[2] - a2[2]
    a = v1x * v1x + v1y * v1y + v1z * v1z
    e = v2x * v2x + v2y * v2y + v2z * v2z
    b = v1x * v2x + v1y * v2y + v1z * v2z
    c = v1x * rx + v1y * ry + v1z * rz
    f = v2x * rx + v2y * ry + v2z * rz
    # 1. skew candidate (Ericson 5.1.9), with s = 0 when parallel or degenerate; s minimises
    #    |r' + s u'| for the parts r', u' of r, v1 orthogonal to v2: the same stationary point
    #    as (b f − c e) / (a e − b²), whose error grows as 1/sin²θ (the distance's as 1/sinθ,
    #    286 ulps at exact crossings), here as 1/sinθ (the distance's stays within a few ulps)
    s = 0.0
    denom = a * e - b * b
    if a > 0.0 and e > 0.0 and denom > PARALLEL_TOL * a * e:
        k, g = b / e, f / e
        ux, uy, uz = v1x - k * v2x, v1y - k * v2y, v1z - k * v2z
        s = _clamp01(-((rx - g * v2x) * ux + (ry - g * v2y) * uy + (rz - g * v2z) * uz) / (ux * ux + uy * uy + uz * uz))
    t = 0.0
    if e > 0.0:
        t = (b * s + f) / e
        if t < 0.0:
            t = 0.0
            s = _clamp01(-c / a) if a > 0.0 else 0.0
        elif t > 1.0:
            t = 1.0
            s = _clamp01((b - c) / a) if a > 0.0 else 0.0
    elif a > 0.0:
        s = _clamp01(-c / a)
    dx = a1[0] + s * v1x - a2[0] - t * v2x
    dy = a1[1] + s * v1y - a2[1] - t * v2y
    dz = a1[2] + s * v1z - a2[2] - t * v2z
    best = dx * dx + dy * dy + dz * dz
    bs, bt = s, t
    # 2. end-point candidates
    d2, u = _point_segment(a1[0], a1[1], a1[2], a2[0], a2[1], a2[2], v2x, v2y, v2z, e)
    if d2 < best:
        best, bs, bt = d2, 0.0, u
    d2, u = _point_segment(b1[0], b1[1], b1[2], a2[0], a2[1], a2[2], v2x, v2y, v2z, e)
    if d2 < best:
        best, bs, bt = d2, 1.0, u
    d2, u = _point_segment(a2[0], a2[1], a2[2], a1[0], a1[1], a1[2], v1x, v1y, v1z, a)
    if d2 < best:
        best, bs, bt = d2, u, 0.0
    d2, u = _point_segment(b2[0], b2[1], b2[2], a1[0], a1[1], a1[2], v1x, v1y, v1z, a)
    if d2 < best:
        best, bs, bt = d2, u, 1.0
    return np.sqrt(best), bs, bt


@njit(cache=True)
def _distance_kernel(
    a1: np.ndarray, b1: np.ndarray, a2: np.ndarray, b2: np.ndarray, dist: np.ndarray, xi: np.ndarray, xj: np.ndarray
) -> None:
    for k in range(a1.shape[0]):
        dist[k], xi[k], xj[k] = segment_distance_scalar(a1[k], b1[k], a2[k], b2[k])


def _as3(x: np.ndarray) -> np.ndarray:
    if x.shape[-1] == 3:
        return x
    if x.shape[-1] == 2:
        return np.concatenate([x, np.zeros(x.shape[:-1] + (1,))], axis=-1)
    raise ArgumentError(f"segment end points must be 2-D or 3-D, got {x.shape[-1]} coordinates")


@overload
def segment_distance(
    a1: npt.ArrayLike, b1: npt.ArrayLike, a2: npt.ArrayLike, b2: npt.ArrayLike, *, parameters: Literal[False] = ...
) -> np.ndarray: ...
@overload
def segment_distance(
    a1: npt.ArrayLike, b1: npt.ArrayLike, a2: npt.ArrayLike, b2: npt.ArrayLike, *, parameters: Literal[True]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]: ...
def segment_distance(
    a1: npt.ArrayLike, b1: npt.ArrayLike, a2: npt.ArrayLike, b2: npt.ArrayLike, *, parameters: bool = False
) -> np.ndarray | tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The minimal distance ``δ`` between the segments ``a1 b1`` and ``a2 b2`` (the proximity of
    Lieskovský 2020, §3.5), by a procedure that covers skew, parallel, collinear and
    zero-length segments (module docstring).

    Parameters
    ----------
    a1, b1, a2, b2 : array_like, shape (..., 2) or (..., 3)
        End points [m], broadcast together.
    parameters : bool, default False
        Also return where the closest points are.

    Returns
    -------
    delta : ndarray, shape (...)
        The distance [m].
    xi_i, xi_j : ndarray, shape (...)
        With ``parameters=True``: ``ξ_i, ξ_j ∈ [0, 1]`` of a closest pair of points
        ``a1 + ξ_i (b1 − a1)`` and ``a2 + ξ_j (b2 − a2)``.

    Raises
    ------
    TautError
        For points that are neither 2-D nor 3-D.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.5, Eq. 3.5.1.
       (docs/references.bib: lieskovsky2020)
    .. [2] C. Ericson, "Real-Time Collision Detection", Morgan Kaufmann, 2005, §5.1.9.
       (docs/references.bib: ericson2005)

    Examples
    --------
    Two parallel unit edges of a cube, across a face diagonal:

    >>> float(segment_distance([0, 0, 0], [1, 0, 0], [0, 1, 1], [1, 1, 1]))
    1.4142135623730951
    >>> [float(x) for x in segment_distance([0, 0], [2, 0], [1, 1], [1, 3], parameters=True)]
    [1.0, 0.5, 0.0]
    """
    try:
        arrs = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (a1, b1, a2, b2)))
    except (TypeError, ValueError):
        raise ArgumentError(
            "segment end points must be numbers in arrays (..., 2) or (..., 3) that broadcast"
        ) from None
    if arrs[0].ndim == 0:
        raise ArgumentError("segment end points must be arrays (..., 2) or (..., 3), got scalars")
    shape = arrs[0].shape[:-1]
    flat = [np.ascontiguousarray(_as3(x).reshape(-1, 3)) for x in arrs]
    M = flat[0].shape[0]
    dist, xi, xj = np.empty(M), np.empty(M), np.empty(M)
    _distance_kernel(flat[0], flat[1], flat[2], flat[3], dist, xi, xj)
    if parameters:
        return dist.reshape(shape), xi.reshape(shape), xj.reshape(shape)
    return dist.reshape(shape)
