"""Platform-reachable area of a rigid planar VSCR at a fixed orientation (§5.2.1, Eqs. 5.8–5.14 of Rushton 2022).

``M^θ`` is the platform outline (``platform.shape.polygon``, body frame) rotated by
``θ`` about the reference point placed at the origin.  The platform at reference point
``p`` occupies ``p + M^θ``, so it meets a fixed set ``P`` iff ``p ∈ P ⊕ (−M^θ)``
(Eqs. 5.8, 5.9).  The reference points that are *not* platform-reachable are

* ``H_obj`` (Eq. 5.10): the union of ``P_k ⊕ (−M^θ)`` over the fixed rigid objects —
  circle and polygon obstacles, the winch pulleys and the robot's disallowed regions;
* ``H_border`` (Eq. 5.11): the union of ``I_j ⊕ (−M^θ)`` over the edges of the
  installation space;
* ``H_static`` (Eq. 5.12): the union of ``s_ij ⊕ (−M^θ)`` over the static segments of
  every cable of the structure;
* ``H_active`` (Eq. 5.13): per cable, the reference points where the active segment runs
  into the platform: at the anchor ``b_i`` the segment leaves along ``u_i`` (towards the
  last object); it enters the platform iff ``u_i`` points into the interior cone of the
  outline at ``b_i`` (the cone between the two outline edges adjacent to the anchor).  The
  anchor points with such a ``u_i`` are swept by the tangents to the last object between
  the two extreme wrap angles (the scan lines tangent to those edges, Fig. 5.6); shifted
  by the anchor offset ``−R(θ) r_i`` they give ``H_active^{s_i}``.  Exact for a convex
  outline (a non-convex one can also be hit away from the anchor).

and ``PRA^{S,θ} = I ∖ (H_obj ∪ H_border ∪ H_static ∪ H_active)`` (Eq. 5.14).  Minkowski
sums of convex pieces are the convex hulls of the pairwise vertex sums; non-convex
polygons are split into triangles (constrained Delaunay) first, and a circle of radius
``ρ`` is ``−M^θ`` translated to its centre and buffered by ``ρ``.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.2.1, Eqs. 5.8–5.14. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
import shapely
import shapely.affinity
from shapely.geometry import MultiPoint, Polygon

from taut._checks import as_number
from taut.atlas._reachable import ARC_STEP
from taut.errors import PoseError, TautError
from taut.wrapping import CableStateTree

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

    from taut.model import Robot

#: Largest distance [m] of an anchor from the platform outline.
ON_OUTLINE = 1e-9


def rotation(theta: float) -> np.ndarray:
    c, s = math.cos(theta), math.sin(theta)
    return np.array([[c, -s], [s, c]])


def platform_outline(robot: Robot, theta: float) -> Polygon | None:
    """``M^θ``: the platform's outline rotated by ``θ`` about its reference point (§5.2.1).

    Parameters
    ----------
    robot : Robot
    theta : float
        Orientation [rad].

    Returns
    -------
    shapely.Polygon or None
        Counter-clockwise; ``None`` for a point mass or a platform without
        ``shape.polygon``.

    Raises
    ------
    TautError
        A polygon that is not simple or has no area.
    PoseError
        An orientation that is not a finite number.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.2.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.atlas import build_atlas, platform_outline, platform_reachable_area
    >>> from taut.model import example
    >>> robot = example("vscr-rigid-t-shaped")
    >>> round(platform_outline(robot, 0.0).area, 6)
    0.0032
    """
    shape = robot.platform.shape
    if robot.is_point_mass or shape is None or not shape.polygon:
        return None
    theta = as_number(theta, "theta", error=PoseError)
    V = np.asarray(shape.polygon, float) @ rotation(theta).T
    M = Polygon(V)
    if not M.is_valid or M.area <= 0:
        raise TautError(f"{robot.name}: the platform polygon is not a simple polygon of positive area")
    return shapely.orient_polygons(M)


def _convex_pieces(poly: Polygon) -> list[np.ndarray]:
    """Vertex arrays of convex pieces whose union is ``poly``."""
    if abs(poly.convex_hull.area - poly.area) <= 1e-12 * max(poly.area, 1e-30):
        return [np.asarray(poly.exterior.coords)[:-1]]
    tri = shapely.constrained_delaunay_triangles(poly)
    return [np.asarray(t.exterior.coords)[:-1] for t in tri.geoms]


def minkowski_sum(a: np.ndarray, b: np.ndarray) -> Polygon:
    """``A ⊕ B`` of two convex point sets given by their vertices (Eq. 5.9)."""
    S = (np.asarray(a, float)[:, None, :] + np.asarray(b, float)[None, :, :]).reshape(-1, 2)
    return MultiPoint(S).convex_hull


def swept_region(M: Polygon, shapes: Iterable[tuple[str, np.ndarray]]) -> BaseGeometry:
    """``∪_k P_k ⊕ (−M)`` for ``shapes``: ``("polygon", V)``, ``("segment", (2, 2))`` or
    ``("circle", (cx, cy, ρ))``."""
    neg = [-v for v in _convex_pieces(M)]
    negM = Polygon(-np.asarray(M.exterior.coords))
    out = []
    for kind, g in shapes:
        if kind == "circle":
            cx, cy, rho = g
            out.append(
                shapely.buffer(shapely.affinity.translate(negM, cx, cy), rho)
                if rho > 0
                else shapely.affinity.translate(negM, cx, cy)
            )
            continue
        pieces = [np.asarray(g, float)] if kind == "segment" else _convex_pieces(Polygon(g))
        out.extend(minkowski_sum(p, n) for p in pieces for n in neg)
    return shapely.union_all(out) if out else Polygon()


def interior_cone(M: Polygon, anchor: npt.ArrayLike) -> tuple[float, float]:
    """``(α, span)``: the directions ``v`` with ``anchor + εv`` inside ``M`` are the angles
    ``α + (0, span)``.  Raises :class:`TautError` if the anchor is not on the outline."""
    b = np.asarray(anchor, float)
    if M.exterior.distance(shapely.Point(b)) > ON_OUTLINE:
        raise TautError(f"the platform anchor {b.round(6).tolist()} is not on the platform outline")
    V = np.asarray(M.exterior.coords)[:-1]  # counter-clockwise
    d = np.hypot(*(V - b).T)
    k = int(np.argmin(d))
    if d[k] <= ON_OUTLINE:
        prev, nxt = V[k - 1], V[(k + 1) % len(V)]
    else:  # on an edge: its two ends
        E = np.roll(V, -1, axis=0) - V
        w = np.clip(((b - V) * E).sum(axis=1) / (E * E).sum(axis=1), 0, 1)
        j = int(np.argmin(np.hypot(*(V + w[:, None] * E - b).T)))
        prev, nxt = V[j], V[(j + 1) % len(V)]
    a0 = math.atan2(*(nxt - b)[::-1])
    a1 = math.atan2(*(prev - b)[::-1])
    return a0, (a1 - a0) % (2 * math.pi)


def active_collision_region(
    tree: CableStateTree, node: int, cone: tuple[float, float], reach: float, arc_step: float
) -> Polygon:
    """Anchor positions (not yet shifted) where the active segment of ``tree`` in state
    ``node`` leaves the anchor in a direction of ``cone``: the tangents to the last object
    whose scan direction (object → anchor) is opposite to the cone."""
    a0, span = cone
    k = tree.obstacle(node)
    c, r = tree.circles[k, :2], float(tree.circles[k, 2])
    d = tree.direction(node)
    m = max(2, int(math.ceil(span / arc_step)) + 1)
    al = a0 + math.pi + np.linspace(0.0, span, m)
    U = np.column_stack([np.cos(al), np.sin(al)])
    N = np.column_stack([-U[:, 1], U[:, 0]])
    O = c - d * r * N
    far = O + reach * U
    ring = np.concatenate([O, far[::-1]]) if r > 0 else np.concatenate([O[:1], far[::-1]])
    return shapely.make_valid(Polygon(ring))


def platform_reachable_area(
    robot: Robot,
    theta: float,
    space: Polygon,
    trees: Sequence[CableStateTree],
    nodes: Sequence[int],
    offsets: np.ndarray,
    *,
    arc_step: float = ARC_STEP,
    reach: float,
) -> BaseGeometry | None:
    """The platform-reachable area ``PRA^{S,θ}`` (Eq. 5.14) of a structure: the reference
    points where the platform's outline meets no object, no border and no cable.

    Parameters
    ----------
    robot : Robot
    theta : float
        Orientation [rad] of the page.
    space : shapely.Polygon
        The installation space.
    trees : sequence of CableStateTree
        Each cable's state tree.
    nodes : sequence of int
        The structure: a node of each tree.
    offsets : ndarray, shape (n, 2)
        Anchor offsets ``R(θ) r_i`` [m].
    arc_step : float, optional
        Angular step [rad] of the chords of circular arcs.
    reach : float
        Length [m] beyond which the active segments are cut (longer than any cable).

    Returns
    -------
    shapely geometry or None
        ``None`` when the platform has no outline (only its anchors, which the
        cable-reachable areas already keep in the installation space).

    Raises
    ------
    TautError
        Bad ``arc_step`` or ``reach``, or an anchor off the platform's outline.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.2.1, Eq. 5.14. (docs/references.bib: rushton2022)

    Examples
    --------
    The first chart of the rigid T-shaped robot's page at its initial orientation:

    >>> from taut.atlas import build_atlas, platform_outline, platform_reachable_area
    >>> from taut.model import example
    >>> robot = example("vscr-rigid-t-shaped")
    >>> x, y, theta = robot.reference.poses["initial"]
    >>> page = build_atlas(robot, [x, y], theta=theta)
    >>> args = (page.theta, page.space, page.trees, page.charts[0].nodes, page.offsets)
    >>> round(platform_reachable_area(robot, *args, reach=20.0).area, 4)
    0.7509
    """
    arc_step = as_number(arc_step, "arc_step", positive=True)
    reach = as_number(reach, "reach", positive=True)
    M = platform_outline(robot, theta)
    if M is None:
        return None
    return space.difference(
        shapely.union_all(
            [
                fixed_collision_region(robot, M, space, trees),
                structure_collision_region(M, trees, nodes, offsets, arc_step, reach),
            ]
        )
    )


def fixed_collision_region(robot: Robot, M: Polygon, space: Polygon, trees: Sequence[CableStateTree]) -> BaseGeometry:
    """``H_obj ∪ H_border`` (Eqs. 5.10, 5.11)."""
    shapes = []
    C = trees[0].circles[:-1]  # the obstacles (zero-radius ones are polygon corners)
    shapes += [("circle", c) for c in C if c[2] > 0]
    shapes += [("circle", t.circles[-1]) for t in trees]  # the winch pulleys
    shapes += [("polygon", p) for p in trees[0].disallowed]  # polygon obstacles and disallowed regions
    ring = np.asarray(space.exterior.coords)
    shapes += [("segment", ring[j : j + 2]) for j in range(len(ring) - 1)]
    return swept_region(M, shapes)


def structure_collision_region(
    M: Polygon,
    trees: Sequence[CableStateTree],
    nodes: Sequence[int],
    offsets: np.ndarray,
    arc_step: float,
    reach: float,
) -> BaseGeometry:
    """``H_static ∪ H_active`` (Eqs. 5.12, 5.13) of structure ``nodes``."""
    out = []
    for i, (tree, node) in enumerate(zip(trees, nodes)):
        segs = tree.static_segments(node)
        if len(segs):
            out.append(swept_region(M, [("segment", s) for s in segs]))
        cone = interior_cone(M, offsets[i])
        H = active_collision_region(tree, node, cone, reach, arc_step)
        out.append(shapely.affinity.translate(H, -offsets[i][0], -offsets[i][1]))
    return shapely.union_all(out) if out else Polygon()
