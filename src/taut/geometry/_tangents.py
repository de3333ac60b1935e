"""Common tangents of points and circles with cable wrap directions.

Appendix A.3 (point–circle) and A.4 (circle–circle) of Rushton (2022).
A point is a circle of radius 0, so one formula serves all cases: a cable leaving circle
``(c1, r1)`` with wrap direction ``d1`` and arriving on circle ``(c2, r2)`` with wrap
direction ``d2`` (``+1`` counter-clockwise: the centre lies on the left of the direction
of travel; ``−1`` clockwise; the sign convention of ``dir`` in A.3/A.4) runs along the
unique directed line ``x1 → x2`` with unit direction ``u`` and left normal ``n``:

    ``x1 = c1 − d1 r1 n``,  ``x2 = c2 − d2 r2 n``,  ``c2 − c1 = L u + s n``,  ``s = d2 r2 − d1 r1``

so that ``L = sqrt(|c2 − c1|² − s²)`` and ``angle(u) = atan2(c2 − c1) − atan2(s, L)``.
The tangent exists iff ``|c2 − c1| ≥ |s|`` (one circle inside the other has none); at
tangency (``|c2 − c1| = |s|``) it degenerates to a single point (``L = 0``).  External
tangents of A.4 are ``d1 = d2``, internal ones ``d1 = −d2``; the two tangents from a point
(A.3) are ``d2 = ±1``.  Zero radii make the wrap direction irrelevant to the line, as they
should.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Appendix A.3–A.4. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt


def directed_tangent(
    c1: npt.ArrayLike, r1: npt.ArrayLike, d1: npt.ArrayLike, c2: npt.ArrayLike, r2: npt.ArrayLike, d2: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The tangent from circle 1, left with wrap direction ``d1``, to circle 2, reached with wrap
    direction ``d2`` (module docstring; a point is a circle of radius 0).

    Parameters
    ----------
    c1, c2 : array_like, shape (..., 2)
        Centres [m].
    r1, r2 : array_like, shape (...)
        Radii [m].
    d1, d2 : array_like, shape (...)
        Wrap directions: ``+1`` counter-clockwise (the centre on the left of the travel),
        ``−1`` clockwise.

    Returns
    -------
    x1, x2 : ndarray, shape (..., 2)
        The tangent points on circles 1 and 2.
    u : ndarray, shape (..., 2)
        The unit direction ``x1 → x2`` (defined at tangency too).
    length : ndarray, shape (...)
        ``‖x2 − x1‖``.
    exists : ndarray of bool, shape (...)
        False for nested or coincident circles, where the other outputs are NaN.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Appendix A.3–A.4. (docs/references.bib: rushton2022)

    Examples
    --------
    Two unit circles 4 m apart, both wrapped counter-clockwise: the external tangent below them.

    >>> x1, x2, u, length, exists = directed_tangent([0.0, 0.0], 1.0, 1.0, [4.0, 0.0], 1.0, 1.0)
    >>> x1, x2, float(length)
    (array([ 0., -1.]), array([ 4., -1.]), 4.0)
    """
    c1 = np.asarray(c1, float)
    c2 = np.asarray(c2, float)
    D = c2 - c1
    dist2 = D[..., 0] ** 2 + D[..., 1] ** 2
    s = np.asarray(d2, float) * np.asarray(r2, float) - np.asarray(d1, float) * np.asarray(r1, float)
    L2 = dist2 - s * s
    # tangency within round-off: a single contact point (L = 0)
    tol = 8 * np.finfo(float).eps * np.maximum(dist2, s * s)
    exists = (L2 >= -tol) & (dist2 > 0)
    L = np.sqrt(np.where(exists, np.maximum(L2, 0.0), np.nan))
    phi = np.arctan2(D[..., 1], D[..., 0]) - np.arctan2(s, L)
    u = np.stack([np.cos(phi), np.sin(phi)], axis=-1)
    n = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    x1 = c1 - (np.asarray(d1, float) * np.asarray(r1, float))[..., None] * n
    x2 = c2 - (np.asarray(d2, float) * np.asarray(r2, float))[..., None] * n
    return x1, x2, u, L, exists


def point_circle_tangents(a: npt.ArrayLike, c: npt.ArrayLike, r: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Both tangents from point ``a`` to circle ``(c, r)`` (A.3).

    Returns ``(b, dirs)``: tangent points ``(..., 2, 2)`` for the wrap directions
    ``dirs = [+1, −1]`` (counter-clockwise, clockwise) of a cable running from ``a`` onto
    the circle.  NaN where ``a`` is inside the circle.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Appendix A.3. (docs/references.bib: rushton2022)
    """
    dirs = np.array([1.0, -1.0])
    a = np.asarray(a, float)[..., None, :]
    c = np.asarray(c, float)[..., None, :]
    r = np.asarray(r, float)[..., None]
    _, b, _, _, _ = directed_tangent(a, 0.0, 1.0, c, r, dirs)
    return b, dirs


def circle_circle_tangents(
    c1: npt.ArrayLike, r1: npt.ArrayLike, c2: npt.ArrayLike, r2: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The four common tangents of two circles (A.4): two external, two internal.

    Returns ``(a, b, dir1, dir2)`` with tangent points ``a`` on circle 1 and ``b`` on
    circle 2, shape ``(..., 4, 2)``, for the wrap directions ``dir1 = [+1, −1, +1, −1]``
    and ``dir2 = [+1, −1, −1, +1]`` (external: ``dir2 = dir1``; internal:
    ``dir2 = −dir1``) of a cable running from circle 1 to circle 2.  NaN where a tangent
    does not exist (overlapping circles have no internal tangents, nested ones none).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Appendix A.4. (docs/references.bib: rushton2022)
    """
    dir1 = np.array([1.0, -1.0, 1.0, -1.0])
    dir2 = np.array([1.0, -1.0, -1.0, 1.0])
    c1 = np.asarray(c1, float)[..., None, :]
    c2 = np.asarray(c2, float)[..., None, :]
    a, b, _, _, _ = directed_tangent(
        c1, np.asarray(r1, float)[..., None], dir1, c2, np.asarray(r2, float)[..., None], dir2
    )
    return a, b, dir1, dir2


def wrap_direction(c: npt.ArrayLike, x: npt.ArrayLike, y: npt.ArrayLike) -> np.ndarray:
    """Wrap direction about the circle centred at ``c`` of a cable that runs along
    ``x → y`` touching the circle at ``x`` (or at ``y``): ``sign((y − x) × (c − x))``,
    ``+1`` (ccw) when the centre is on the left of the travel.  This is ``dir`` of A.3
    (``sign((b − c) × (b − a))`` for a cable ``a → b``); A.4 prints
    ``sign((c₁ − a) × (b − a))``, the opposite sign, i.e. the direction of a cable
    running ``b → a`` — taut uses the A.3 convention throughout."""
    c, x, y = (np.asarray(v, float) for v in (c, x, y))
    p, q = y - x, c - x
    return np.sign(p[..., 0] * q[..., 1] - p[..., 1] * q[..., 0])
