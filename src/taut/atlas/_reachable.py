"""Cable-reachable area (CRA) of one collidable cable in a given state (§5.1.2 of Rushton 2022).

The CRA of a cable in state ``s`` is the set of platform-end positions ``b`` reachable by
its active (last, straight) segment without changing the state or making a forbidden
collision: ``b`` is where :meth:`taut.wrapping.CableStateTree.is_taut` holds —
the tangent from the last object exists, the wrap angle about it is ``φ ∈ [0, 3π/2)``
(``φ < 0`` is a separation), the segment enters no collidable circle (that would be a
collision, i.e. a wrap), crosses no earlier static segment and enters no disallowed
polygon — and ``b`` lies in the installation space.

Like §5.1.2 this is an **angular sweep** of the scan line tangent to the last object
(radius ``r``, wrap direction ``d``) over the wrap angle: ``φ ∈ [0, 3π/2)`` about a
wrapped object, the full turn about the winch pulley.  Instead of maintaining the list
of active edges vertex by vertex, the sweep is split at every *critical angle* — the scan
line through a vertex (ends of the static segments, polygon corners, crossings of edges)
or tangent to a circle — and in each interval between two critical angles the nearest
blocking element is constant, so it is found once by casting the mid-interval ray.  The
boundary over an interval is then exact: the two bounding rays, intersected with the
line of the nearest edge.  Several vertices at one angle (the collinear case of §5.1.2)
need no special ordering: the boundary jumps along the scan line from the previous
interval's edge to the next one's.

Exact for straight edges; circular arcs (the far boundary on a circular obstacle, the
near boundary on the pulley itself) are polygonised with chords every ``arc_step``
radians (of the obstacle's angle for a far arc, of wrap angle for the near arc) — the
only approximation (chord error ``≈ r·arc_step²/8``).
The result is a shapely polygon (possibly a MultiPolygon once clipped by the
installation space).  The installation space bounds the end point; regions the cable
must not cross are the robot's disallowed regions, as in the CST (§4.2.1).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.1.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
import shapely
from shapely.geometry import MultiPolygon, Polygon

from taut._checks import as_array, as_index, as_number
from taut.errors import TautError
from taut.geometry import directed_tangent
from taut.wrapping import CableStateTree

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

#: Default angular step [rad] of the chords that polygonise circular arcs.
ARC_STEP = 0.01
#: Largest wrap angle about a wrapped object (beyond it the cable would cross itself).
WRAP_SPAN = 1.5 * math.pi
_EPS_T = 1e-12
#: Precision grid [m] of the polygon union of the sweep's pieces.
GRID = 1e-12
#: Width [m] of the round-off cracks closed between pieces (a morphological closing).
CRACK = 1e-9


def _sweep_frame(tree: CableStateTree, node: int) -> tuple[np.ndarray, float, int, float, float]:
    """``(centre, radius, d, α0, span)``: the scan line starts along direction angle ``α0``
    and turns by ``d·s``, ``s ∈ [0, span]``."""
    k = tree.obstacle(node)
    c, r = tree.circles[k, :2], float(tree.circles[k, 2])
    r = r if r > CRACK else 0.0  # a sub-nanometre pulley is a point
    d = tree.direction(node)
    if node == 0:
        return c, r, d, 0.0, 2 * math.pi
    _, leaving = tree.ray(node)
    return c, r, d, math.atan2(leaving[1], leaving[0]), WRAP_SPAN


def _rays(c: np.ndarray, r: float, d: int, a0: float, s: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Scan-line origins (tangent points) and directions at sweep parameters ``s``."""
    a = a0 + d * np.asarray(s, float)
    U = np.column_stack([np.cos(a), np.sin(a)])
    N = np.column_stack([-U[:, 1], U[:, 0]])
    return c - d * r * N, U


def _segment_hits(O: np.ndarray, U: np.ndarray, P: np.ndarray, Q: np.ndarray) -> np.ndarray:
    """``(A, E)`` ray parameter ``t`` where each ray meets each segment (inf if not)."""
    E = Q - P
    den = U[:, None, 0] * E[None, :, 1] - U[:, None, 1] * E[None, :, 0]
    W = P[None] - O[:, None]
    safe = np.where(np.abs(den) > 1e-300, den, 1.0)
    t = (W[..., 0] * E[None, :, 1] - W[..., 1] * E[None, :, 0]) / safe
    w = (W[..., 0] * U[:, None, 1] - W[..., 1] * U[:, None, 0]) / safe
    ok = (np.abs(den) > 1e-14) & (w >= 0) & (w <= 1) & (t > _EPS_T)
    return np.where(ok, t, np.inf)


def _circle_hits(O: np.ndarray, U: np.ndarray, C: np.ndarray, R: np.ndarray, strict: bool = True) -> np.ndarray:
    """``(A, K)`` ray parameter of the first entry into each disc (inf if none)."""
    D = C[None] - O[:, None]
    b = D[..., 0] * U[:, None, 0] + D[..., 1] * U[:, None, 1]
    disc = b * b - (D[..., 0] ** 2 + D[..., 1] ** 2 - R[None] ** 2)
    if strict:
        ok = disc > 1e-18
    else:
        ok = disc >= -1e-12
    t = b - np.sqrt(np.maximum(disc, 0.0))
    return np.where(ok & (t > -1e-12) & (b > 0), np.maximum(t, 0.0), np.inf)


class _Scene:
    """The blocking elements seen by one cable state: segments, circles, polygons."""

    def __init__(self, tree: CableStateTree, node: int, bbox: np.ndarray) -> None:
        k = tree.obstacle(node)
        segs = [tree.static_segments(node)[:-1]] if node != 0 else []
        self.polys = [np.asarray(p, float) for p in tree.disallowed]
        for p in self.polys:
            segs.append(np.stack([p, np.roll(p, -1, axis=0)], axis=1))
        x0, y0, x1, y1 = bbox
        box = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]])
        segs.append(np.stack([box, np.roll(box, -1, axis=0)], axis=1))
        S = np.concatenate([s.reshape(-1, 2, 2) for s in segs])
        self.P, self.Q = S[:, 0], S[:, 1]
        keep = (tree.circles[:, 2] > 0) & (np.arange(len(tree.circles)) != k)
        self.C, self.R = tree.circles[keep, :2], tree.circles[keep, 2]
        self.shapes = [Polygon(p) for p in self.polys]
        for s in self.shapes:
            shapely.prepare(s)

    def vertices(self) -> np.ndarray:
        """Segment end points and the crossings of pairs of segments."""
        P, Q = self.P, self.Q
        pts = [P, Q]
        E = Q - P
        den = E[:, None, 0] * E[None, :, 1] - E[:, None, 1] * E[None, :, 0]
        W = P[None] - P[:, None]
        safe = np.where(np.abs(den) > 1e-14, den, 1.0)
        s = (W[..., 0] * E[None, :, 1] - W[..., 1] * E[None, :, 0]) / safe
        u = (W[..., 0] * E[:, None, 1] - W[..., 1] * E[:, None, 0]) / safe
        ok = (np.abs(den) > 1e-14) & (s > 0) & (s < 1) & (u > 0) & (u < 1)
        i, _ = np.nonzero(ok)
        if len(i):
            pts.append(P[i] + s[ok][:, None] * E[i])
        return np.concatenate(pts)

    def nearest(self, O: np.ndarray, U: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(t, kind, index)`` of the first blocking element along each ray: kind 0 a
        segment, 1 a circle, 2 the origin itself (the ray starts into a polygon)."""
        ts = _segment_hits(O, U, self.P, self.Q)
        tc = _circle_hits(O, U, self.C, self.R) if len(self.R) else np.full((len(O), 0), np.inf)
        js, jc = np.argmin(ts, axis=1), (np.argmin(tc, axis=1) if tc.shape[1] else np.zeros(len(O), int))
        t_s = ts[np.arange(len(O)), js]
        t_c = tc[np.arange(len(O)), jc] if tc.shape[1] else np.full(len(O), np.inf)
        kind = np.where(t_c < t_s, 1, 0)
        idx = np.where(kind == 1, jc, js)
        t = np.minimum(t_s, t_c)
        probe = O + 1e-7 * U
        for shape in self.shapes:
            inside = shapely.contains_xy(shape, probe[:, 0], probe[:, 1])
            kind = np.where(inside, 2, kind)
            t = np.where(inside, 0.0, t)
        return t, kind, idx


def _circle_segment_angles(c: np.ndarray, r: float, P: np.ndarray, Q: np.ndarray) -> np.ndarray:
    """Angles about ``c`` of the points where the circle ``(c, r)`` crosses the segments."""
    E = Q - P
    F = P - c
    a = (E * E).sum(axis=1)
    b = 2 * (F * E).sum(axis=1)
    q = (F * F).sum(axis=1) - r * r
    disc = b * b - 4 * a * q
    ok = (disc >= 0) & (a > 0)
    root = np.sqrt(np.where(ok, disc, 0.0))
    out = []
    for sign in (-1.0, 1.0):
        w = (-b + sign * root) / np.where(a > 0, 2 * a, 1.0)
        m = ok & (w >= 0) & (w <= 1)
        X = P[m] + w[m, None] * E[m] - c
        out.append(np.arctan2(X[:, 1], X[:, 0]))
    return np.concatenate(out)


def _bbox(tree: CableStateTree, space: Polygon | None) -> np.ndarray:
    pts: list[np.ndarray] | np.ndarray
    pts = [tree.circles[:, :2] - tree.circles[:, 2:3], tree.circles[:, :2] + tree.circles[:, 2:3]]
    pts += [np.asarray(p, float) for p in tree.disallowed]
    if space is not None:
        pts.append(np.asarray(space.exterior.coords))
    pts = np.concatenate(pts)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    m = 0.5 * max(hi - lo) + 1.0
    return np.array([lo[0] - m, lo[1] - m, hi[0] + m, hi[1] + m])


def cable_reachable_area(
    tree: CableStateTree,
    node: int,
    *,
    installation_space: npt.ArrayLike | Polygon | None = None,
    arc_step: float = ARC_STEP,
) -> Polygon | MultiPolygon:
    """The cable-reachable area of a cable in one state (§5.1.2, module docstring): where its
    platform end can go without changing the state.

    Parameters
    ----------
    tree : CableStateTree
        The cable's state tree.
    node : int
        The state: a node of the tree.
    installation_space : array_like, shape (V, 2), or shapely.Polygon, optional
        Clips the area; without one it is bounded by a box around the objects.
    arc_step : float, optional
        Angular step [rad] of the chords that polygonise circular arcs.

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon

    Raises
    ------
    TautError
        A node not in the tree, a bad installation space or ``arc_step``.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.1.2. (docs/references.bib: rushton2022)

    Examples
    --------
    A straight cable from the origin, a disc at ``(0, 1)`` in the way, in a 4 m square:

    >>> import shapely
    >>> from taut.atlas import cable_reachable_area
    >>> from taut.wrapping import CableStateTree
    >>> tree = CableStateTree([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]])
    >>> square = [[-2, -2], [2, -2], [2, 2], [-2, 2]]
    >>> area = cable_reachable_area(tree, 0, installation_space=square)
    >>> area.contains(shapely.Point(1.0, 1.0)), area.contains(shapely.Point(0.0, 1.5))
    (True, False)
    """
    node = as_index(node, "node", tree.size)
    arc_step = as_number(arc_step, "arc_step", positive=True)
    space = None
    if isinstance(installation_space, Polygon):
        space = installation_space
    elif installation_space is not None:
        ring = as_array(installation_space, "installation_space", shape=(None, 2))
        if len(ring) < 3:
            raise TautError(f"installation_space: a polygon needs at least 3 vertices, got {len(ring)}")
        space = Polygon(ring)
    bbox = _bbox(tree, space)
    scene = _Scene(tree, node, bbox)
    c, r, d, a0, span = _sweep_frame(tree, node)
    # critical angles: scan line through a vertex, or tangent to a circle
    V = scene.vertices()
    crit = []
    _, _, u, _, ok = directed_tangent(c, r, d, V, 0.0, 1.0)
    crit.append(np.arctan2(u[ok, 1], u[ok, 0]))
    if len(scene.R):
        for dd in (1.0, -1.0):
            _, _, u, _, ok = directed_tangent(c, r, d, scene.C, scene.R, dd)
            crit.append(np.arctan2(u[ok, 1], u[ok, 0]))
    if r > 0:  # the tangent point itself crosses an edge
        th = _circle_segment_angles(c, r, scene.P, scene.Q)
        crit.append(th + d * 0.5 * math.pi)
    s = np.mod(d * (np.concatenate(crit) - a0), 2 * math.pi)
    s = np.unique(np.concatenate([[0.0, span], s[(s > 0) & (s < span)]]))
    s = s[np.concatenate([[True], np.diff(s) > 1e-13])]
    s[-1] = span
    mid = 0.5 * (s[:-1] + s[1:])
    O, U = _rays(c, r, d, a0, mid)
    _, kind, idx = scene.nearest(O, U)
    pieces = []
    for i in range(len(mid)):
        k = int(kind[i])
        n = 2 if (k == 0 and r == 0) else max(2, int(math.ceil((s[i + 1] - s[i]) / arc_step)) + 1)
        O, U = _rays(c, r, d, a0, np.linspace(s[i], s[i + 1], n))
        if k == 2:
            continue
        if k == 0:
            P, Q = scene.P[idx[i]], scene.Q[idx[i]]
            E = Q - P
            den = U[:, 0] * E[1] - U[:, 1] * E[0]
            W = P - O
            par = np.abs(den) <= 1e-14 * np.hypot(*E)
            t = (W[:, 0] * E[1] - W[:, 1] * E[0]) / np.where(par, 1.0, den)
            if par.any():  # scan line along the edge: it stops at the edge's nearer end
                near_end = np.minimum((W * U).sum(axis=1), ((Q - O) * U).sum(axis=1))
                t = np.where(par, np.maximum(near_end, 0.0), t)
        else:  # sample the far arc uniformly on the obstacle, aim the scan line at it
            O, U = O[[0, -1]], U[[0, -1]]
            cc, rr = scene.C[idx[i]], scene.R[idx[i]]
            t = _circle_hits(O, U, cc[None], rr[None], strict=False)[:, 0]
            D = cc - O
            t = np.where(np.isfinite(t), t, D[:, 0] * U[:, 0] + D[:, 1] * U[:, 1])  # grazing: tangent point
            X = O + t[:, None] * U - cc
            th0, th1 = np.arctan2(X[:, 1], X[:, 0])
            dth = (th1 - th0 + math.pi) % (2 * math.pi) - math.pi
            th = th0 + dth * np.linspace(0.0, 1.0, max(2, int(math.ceil(abs(dth) / arc_step)) + 1))
            X = cc + rr * np.column_stack([np.cos(th), np.sin(th)])
            O, _, U, t, _ = directed_tangent(c, r, d, X, 0.0, 1.0)
        far = O + np.maximum(t, 0.0)[:, None] * U
        ring = np.concatenate([O, far[::-1]]) if r > 0 else np.concatenate([O[:1], far[::-1]])
        pieces.append(shapely.make_valid(Polygon(ring)))
    region = close_cracks(shapely.union_all(pieces, grid_size=GRID))
    if space is not None:
        region = region.intersection(space)
    return _polygonal(region)


def close_cracks(geom: BaseGeometry, eps: float = CRACK) -> Polygon | MultiPolygon:
    """Morphological closing by ``eps``: joins pieces that round-off left a hairline apart
    (two boundary pieces along one scan line do not share vertices)."""
    return _polygonal(geom.buffer(eps, join_style="mitre").buffer(-eps, join_style="mitre"))


def _polygonal(geom: BaseGeometry) -> Polygon | MultiPolygon:
    """The polygonal part of a shapely geometry, as a Polygon or MultiPolygon."""
    parts = [g for g in getattr(geom, "geoms", [geom]) if isinstance(g, (Polygon, MultiPolygon)) and not g.is_empty]
    polys: list[Polygon] = []
    for g in parts:
        polys.extend(g.geoms if isinstance(g, MultiPolygon) else [g])
    if len(polys) == 1:
        return polys[0]
    return MultiPolygon(polys)
