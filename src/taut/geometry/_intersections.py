"""Planar intersection tests: segment–segment, segment–circle, segment–polygon, circle–circle.

Appendix A.1 (line segment–line segment intercept) and A.2 (line segment–circle
intercept) of Rushton (2022), vectorised over leading axes.  The tests are
*strict* where the cable model needs it: a cable that only touches a circle tangentially
(the contact points of every taut path, and the tie of Fig. 4.5) does not meet it; a
tolerance ``tol`` [m] absorbs round-off.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Appendix A.1–A.2, Fig. 4.5. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

#: Default tolerance [m] of the strict tests (round-off of tangent constructions).
TOL = 1e-9


def _cross(p: np.ndarray, q: np.ndarray) -> np.ndarray:
    return p[..., 0] * q[..., 1] - p[..., 1] * q[..., 0]


def segments_intersect(
    a1: npt.ArrayLike,
    b1: npt.ArrayLike,
    a2: npt.ArrayLike,
    b2: npt.ArrayLike,
    *,
    tol: float = 0.0,
    collinear: bool = True,
) -> np.ndarray:
    """Whether segments ``a1 b1`` and ``a2 b2`` share a point (Rushton 2022, A.1).

    With ``s = ((a2 − a1) × (b2 − a2)) / ((b1 − a1) × (b2 − a2))`` and ``u = ((a2 − a1) ×
    (b1 − a1)) / ((b1 − a1) × (b2 − a2))`` they intercept iff ``0 ≤ s, u ≤ 1``; parallel
    segments intercept iff collinear and overlapping.

    Parameters
    ----------
    a1, b1, a2, b2 : array_like, shape (..., 2)
        End points [m], broadcast together.
    tol : float, default 0.0
        Shrinks both segments by ``tol`` [m] at each end: with ``tol > 0`` only a proper
        crossing counts, not end points touching.
    collinear : bool, default True
        Whether collinear overlaps (a segment running along another) count.

    Returns
    -------
    ndarray of bool, shape (...)

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Appendix A.1. (docs/references.bib: rushton2022)

    Examples
    --------
    The diagonals of a square cross; segments end to end touch, which counts unless ``tol > 0``:

    >>> segments_intersect([[0, 0], [0, 0]], [[1, 1], [1, 0]], [[0, 1], [1, 0]], [[1, 0], [2, 0]])
    array([ True,  True])
    >>> segments_intersect([0, 0], [1, 0], [1, 0], [2, 0], tol=1e-9)
    array(False)
    """
    a1, b1, a2, b2 = (np.asarray(v, float) for v in (a1, b1, a2, b2))
    r, q, w = b1 - a1, b2 - a2, a2 - a1
    den = _cross(r, q)
    len1 = np.hypot(r[..., 0], r[..., 1])
    len2 = np.hypot(q[..., 0], q[..., 1])
    scale = np.maximum(len1 * len2, np.finfo(float).tiny)
    parallel = np.abs(den) <= 1e-12 * scale
    safe = np.where(parallel, 1.0, den)
    s = _cross(w, q) / safe
    u = _cross(w, r) / safe
    e1 = tol / np.maximum(len1, np.finfo(float).tiny)
    e2 = tol / np.maximum(len2, np.finfo(float).tiny)
    crossing = (s >= e1) & (s <= 1 - e1) & (u >= e2) & (u <= 1 - e2)
    # collinear: positions of a2, b2 along r (in units of |r|)
    on_line = parallel & (np.abs(_cross(w, r)) <= 1e-12 * np.maximum(len1 * len1, np.finfo(float).tiny) + tol * len1)
    rr = np.maximum(len1 * len1, np.finfo(float).tiny)
    sa = (w[..., 0] * r[..., 0] + w[..., 1] * r[..., 1]) / rr
    sb = ((b2 - a1)[..., 0] * r[..., 0] + (b2 - a1)[..., 1] * r[..., 1]) / rr
    overlap = (np.minimum(sa, sb) <= 1 - e1) & (np.maximum(sa, sb) >= e1)
    return np.where(parallel, on_line & overlap & collinear, crossing)


def closest_point_on_segment(a: npt.ArrayLike, b: npt.ArrayLike, c: npt.ArrayLike) -> np.ndarray:
    """The point ``q`` of segment ``ab`` closest to ``c`` (A.2)."""
    a, b, c = (np.asarray(v, float) for v in (a, b, c))
    ab = b - a
    den = ab[..., 0] ** 2 + ab[..., 1] ** 2
    s = ((c - a)[..., 0] * ab[..., 0] + (c - a)[..., 1] * ab[..., 1]) / np.where(den > 0, den, 1.0)
    s = np.clip(np.where(den > 0, s, 0.0), 0.0, 1.0)
    return a + s[..., None] * ab


def segment_circle_distance(a: npt.ArrayLike, b: npt.ArrayLike, c: npt.ArrayLike) -> np.ndarray:
    """Distance from the centre ``c`` to segment ``ab`` (A.2: ``‖q − c‖``)."""
    q = closest_point_on_segment(a, b, c)
    d = q - np.asarray(c, float)
    return np.hypot(d[..., 0], d[..., 1])


def segment_meets_circle(
    a: npt.ArrayLike, b: npt.ArrayLike, c: npt.ArrayLike, r: npt.ArrayLike, *, tol: float = TOL
) -> np.ndarray:
    """Whether segment ``ab`` enters the open disc ``(c, r)``: ``‖q − c‖ < r − tol`` with ``q`` the
    point of the segment nearest the centre.

    Rushton (2022), A.2, states ``≤ r``; the strict form lets a cable touch an object
    tangentially (a zero-radius object is therefore never met).

    Parameters
    ----------
    a, b : array_like, shape (..., 2)
        End points [m].
    c : array_like, shape (..., 2)
        Centres [m].
    r : array_like, shape (...)
        Radii [m].
    tol : float, default :data:`TOL`
        Round-off allowance [m].

    Returns
    -------
    ndarray of bool, shape (...)

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Appendix A.2. (docs/references.bib: rushton2022)

    Examples
    --------
    A horizontal cable through a unit circle centred 0.5 m above it, and one tangent to it:

    >>> segment_meets_circle([-2, 0], [2, 0], [0, 0.5], 1.0), segment_meets_circle([-2, 0], [2, 0], [0, 1.0], 1.0)
    (np.True_, np.False_)
    """
    return segment_circle_distance(a, b, c) < np.asarray(r, float) - tol


def point_in_polygon(p: npt.ArrayLike, vertices: npt.ArrayLike) -> np.ndarray:
    """Whether points lie strictly inside a polygon (even–odd rule).

    Parameters
    ----------
    p : array_like, shape (..., 2)
        Points [m].
    vertices : array_like, shape (k, 2)
        The polygon's vertices, in order.

    Returns
    -------
    ndarray of bool, shape (...)

    Examples
    --------
    >>> point_in_polygon([[0.5, 0.5], [2.0, 2.0]], [[0, 0], [1, 0], [1, 1], [0, 1]])
    array([ True, False])
    """
    p = np.asarray(p, float)
    v = np.asarray(vertices, float)
    x, y = p[..., 0][..., None], p[..., 1][..., None]
    x1, y1 = v[:, 0], v[:, 1]
    x2, y2 = np.roll(x1, -1), np.roll(y1, -1)
    cond = (y1 > y) != (y2 > y)
    xs = x1 + (y - y1) * (x2 - x1) / np.where(y2 != y1, y2 - y1, 1.0)
    return (np.count_nonzero(cond & (x < xs), axis=-1) % 2) == 1


def segment_enters_polygon(
    a: npt.ArrayLike, b: npt.ArrayLike, vertices: npt.ArrayLike, *, tol: float = TOL
) -> np.ndarray:
    """Whether segment ``ab`` enters the interior of a polygon (a disallowed region, Rushton
    2022, §4.2.1).

    §4.2.1 checks the segment against each edge of the bounding polygon (A.1); a segment
    wholly inside crosses no edge, so its midpoint is tested too.  Touching an edge or a vertex
    (within ``tol``) is not entering, and neither is running along an edge (a cable wrapped
    round one corner of a polygon obstacle onto the next).

    Parameters
    ----------
    a, b : array_like, shape (..., 2)
        End points [m].
    vertices : array_like, shape (k, 2)
        The polygon's vertices, in order.
    tol : float, default :data:`TOL`
        Round-off allowance [m].

    Returns
    -------
    ndarray of bool, shape (...)

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Appendix A.1, §4.2.1. (docs/references.bib: rushton2022)

    Examples
    --------
    Through the unit square, and along its top edge:

    >>> square = [[0, 0], [1, 0], [1, 1], [0, 1]]
    >>> segment_enters_polygon([-1, 0.5], [2, 0.5], square), segment_enters_polygon([-1, 1], [2, 1], square)
    (np.True_, np.False_)
    """
    a = np.asarray(a, float)
    b = np.asarray(b, float)
    v = np.asarray(vertices, float)
    w = np.roll(v, -1, axis=0)
    hit = segments_intersect(a[..., None, :], b[..., None, :], v, w, tol=tol, collinear=False).any(axis=-1)
    mid = 0.5 * (a + b)
    on_boundary = (segment_circle_distance(v, w, mid[..., None, :]) <= max(tol, 0.0)).any(axis=-1)
    return hit | (point_in_polygon(mid, v) & ~on_boundary)


def circles_overlap(
    c1: npt.ArrayLike, r1: npt.ArrayLike, c2: npt.ArrayLike, r2: npt.ArrayLike, *, tol: float = TOL
) -> np.ndarray:
    """Whether two closed discs share interior points (``‖c1 − c2‖ < r1 + r2 − tol``), or
    coincide (two points at the same place).

    Parameters
    ----------
    c1, c2 : array_like, shape (..., 2)
        Centres [m].
    r1, r2 : array_like, shape (...)
        Radii [m].
    tol : float, default :data:`TOL`
        Round-off allowance [m]: discs that only touch do not overlap.

    Returns
    -------
    ndarray of bool, shape (...)

    Examples
    --------
    >>> circles_overlap([0, 0], 1.0, [1.5, 0], 1.0), circles_overlap([0, 0], 1.0, [2.0, 0], 1.0)
    (np.True_, np.False_)
    """
    d = np.asarray(c2, float) - np.asarray(c1, float)
    dist = np.hypot(d[..., 0], d[..., 1])
    return (dist < np.asarray(r1, float) + np.asarray(r2, float) - tol) | (dist <= tol)
