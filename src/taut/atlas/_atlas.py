"""Structure atlas of a point-mass planar VSCR (§5.1.3, Alg. 5.1 of Rushton 2022).

From an initial point ``p_0`` (and the cables' initial states — by default the shortest
taut routing, as in :func:`taut.wrapping.wrapped_inverse_kinematics`) Alg. 5.1 builds
the first chart, then repeatedly visits the edges of each chart's domain ``Q`` that are
*traversable* — crossing them changes one cable's state — and builds the chart of the
structure on the other side from the edge's midpoint.

A cable in CST node ``x`` changes state only on two kinds of rays (§4.2.2, Alg. 4.4):
it wraps onto the object of a child ``c`` when the platform end crosses the forward
extension of ``c``'s segment, and unwraps from ``x``'s object (back to the parent) when
it crosses the forward extension of ``x``'s own segment.  These are exactly the
traversable edges of the CRA sweep (§5.1.2: "if the PNE is collidable and no longer
active or if the new NAE is collidable and just added, the newly created edge induces a
cable state transition"), so here they are found from the tree rather than labelled
during the sweep: the pieces of each transition ray along the boundary of ``Q`` are the
traversable edges; a point just across the midpoint of each piece seeds the adjacent
chart (a structure that differs in that one cable's state), if it lies in that
structure's SRA.  Charts of one structure are told apart by their SRA component, so a
structure whose SRA has two components reachable from the start gives two charts.

A robot without an installation space is bounded by the box around its exits, objects
and start point, grown by half its size.

*Rigid platforms* (§5.2.2): the atlas is one *page* — a slice of constant orientation
``θ``.  Charts live in the plane of the reference point ``p``; cable ``i`` is attached at
``p + R(θ) r_i``, so its cable-reachable area and its transition rays are shifted by
``−R(θ) r_i``, and the structure-reachable area is cut down to the platform-reachable
area (Eq. 5.15, :mod:`taut.atlas._platform`).  A point-mass platform is the page ``θ = 0``
with zero offsets.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.1.3, Alg. 5.1; §5.1.2; §4.2.2, Alg. 4.4.
   (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
import shapely
from shapely.geometry import LineString, MultiPolygon, Polygon

from taut._checks import as_array, as_count, as_number
from taut._results import Result, jsonable
from taut.atlas._chart import StructureChart, chart_lengths, component_containing, structure_reachable_area
from taut.atlas._platform import fixed_collision_region, platform_outline, rotation, structure_collision_region
from taut.atlas._reachable import ARC_STEP, cable_reachable_area
from taut.errors import PoseError, TautError
from taut.kinematics import refuse_swivels
from taut.model import Robot
from taut.wrapping import CableStateTree, wrapped_inverse_kinematics

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry

#: Distance [m] across a traversable edge at which the adjacent chart is seeded.
PROBE = 1e-6
#: Shortest traversable edge [m] considered.
MIN_EDGE = 1e-6
#: The chart budget of :func:`build_atlas` when none is given: every chart holds the
#: polygons of its structure, so the budget bounds memory as well as time.
MAX_STRUCTURE_CHARTS = 5000


@dataclass(frozen=True)
class Edge(Result):
    """An adjacency of two charts: crossing its segment changes one cable's state (§5.1.3).

    Attributes
    ----------
    charts : (int, int)
        The chart whose domain the segment bounds, and the chart across it.
    cable : int
        The cable whose state changes (0-based).
    kind : str
        ``"wrap"`` or ``"unwrap"``.
    obj : int
        The object wrapped or unwrapped (0-based; the winch is the last one).
    segment : ndarray, shape (2, 2)
        End points [m] of the traversable edge.
    normal : ndarray, shape (2,)
        Unit normal of the edge pointing into ``charts[1]``.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.1.2–5.1.3. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> e = atlas.edges[0]
    >>> e.charts, e.cable, e.kind, e.obj
    ((0, 1), 2, 'wrap', 0)
    """

    charts: tuple[int, int]
    cable: int
    kind: str
    obj: int
    segment: np.ndarray  #: (2, 2) end points of the shared edge
    normal: np.ndarray  #: (2,) unit normal of the edge pointing into ``charts[1]``

    def as_dict(self) -> dict:
        """The edge as ``taut atlas --out`` writes it, 0-based: ``charts``, ``cable``,
        ``kind``, ``object`` and ``segment``."""
        return {
            "charts": list(self.charts),
            "cable": self.cable,
            "kind": self.kind,
            "object": self.obj,
            "segment": jsonable(self.segment),
        }


@dataclass(frozen=True)
class StructureAtlas(Result):
    """The structure atlas of a planar VSCR — for a rigid platform one page, at orientation
    ``theta`` (§5.2.2): charts and their adjacency (:func:`build_atlas`).

    Attributes
    ----------
    robot : Robot
    trees : tuple of CableStateTree
        Each cable's state tree (the charts' ``nodes`` index them).
    space : shapely.Polygon
        The installation space (or a box around the robot).
    charts : tuple of StructureChart
    edges : tuple of Edge
    start : ndarray, shape (2,)
        The start point [m].
    theta : float
        Platform orientation [rad] of the page (0 for a point mass).
    offsets : ndarray, shape (n, 2)
        Anchor offsets ``R(θ) r_i`` [m].
    complete : bool
        Every chart reachable from the start is built (the chart budget did not run out).
    elapsed_s : float
        Wall-clock time [s].

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.1.3, Alg. 5.1; §5.2.2. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> len(atlas.charts), atlas.n_edges, atlas.complete, round(atlas.reachable_area().area, 4)
    (31, 44, True, 0.9012)
    """

    robot: Robot
    trees: tuple[CableStateTree, ...] = field(repr=False)
    space: Polygon = field(repr=False)  #: the installation space (or a box around the robot)
    charts: tuple[StructureChart, ...]
    edges: tuple[Edge, ...]
    start: np.ndarray
    theta: float  #: platform orientation of the page (0 for a point mass)
    offsets: np.ndarray = field(repr=False)  #: ``(n, 2)`` anchor offsets ``R(θ) r_i``
    #: every chart reachable from the start is built (the chart budget did not run out)
    complete: bool
    elapsed_s: float

    def poses(self, points: npt.ArrayLike) -> np.ndarray:
        """Robot poses at reference points ``(N, 2)``: ``(x, y)``, or ``(x, y, θ)`` for a
        rigid platform."""
        P = np.atleast_2d(np.asarray(points, float))
        if self.robot.is_point_mass:
            return P
        return np.column_stack([P, np.full(len(P), self.theta)])

    @property
    def n_edges(self) -> int:
        """Number of adjacent chart pairs."""
        return len({tuple(sorted(e.charts)) for e in self.edges})

    def reachable_area(self) -> BaseGeometry:
        """Union of the chart domains (the reachable part of the C-space, projected)."""
        return shapely.union_all([c.domain for c in self.charts])

    def lengths(self, chart: int, points: npt.ArrayLike) -> np.ndarray:
        """Cable lengths ``(N, n)`` at ``points`` in chart ``chart`` (Eq. 4.9)."""
        return chart_lengths(self.trees, self.charts[chart].nodes, points, offsets=self.offsets)[0]

    def as_dict(self) -> dict:
        """The atlas as ``taut atlas --json --out`` prints it, with 0-based charts, cables
        and objects: ``start``, ``theta``, ``complete``, ``elapsed_s``, ``charts`` and
        ``edges`` (their numbers), ``reachable_area``, ``chart_list``
        (:meth:`StructureChart.as_dict`) and ``edge_list`` (:meth:`Edge.as_dict`)."""
        return {
            "start": jsonable(self.start),
            "theta": float(self.theta),
            "complete": self.complete,
            "elapsed_s": self.elapsed_s,
            "charts": len(self.charts),
            "edges": self.n_edges,
            "reachable_area": float(self.reachable_area().area),
            "chart_list": [c.as_dict() for c in self.charts],
            "edge_list": [e.as_dict() for e in self.edges],
        }


class _Builder:
    def __init__(
        self,
        robot: Robot,
        trees: Sequence[CableStateTree],
        space: Polygon,
        arc_step: float,
        theta: float,
        offsets: np.ndarray,
    ) -> None:
        self.robot, self.trees, self.space, self.arc_step = robot, trees, space, arc_step
        self.offsets = offsets
        self.full = False  #: the chart budget ran out
        self.cra: dict[tuple[int, int], Polygon | MultiPolygon] = {}
        self.sra: dict[tuple[int, ...], Polygon | MultiPolygon] = {}
        x0, y0, x1, y1 = space.bounds
        self.reach = 4.0 * float(np.hypot(x1 - x0, y1 - y0) + np.abs(offsets).max()) + 1.0
        self.outline = platform_outline(robot, theta)
        self.fixed = fixed_collision_region(robot, self.outline, space, trees) if self.outline is not None else None

    def cable_area(self, i: int, node: int) -> Polygon | MultiPolygon:
        key = (i, node)
        if key not in self.cra:
            self.cra[key] = cable_reachable_area(
                self.trees[i], node, installation_space=self.space, arc_step=self.arc_step
            )
        return self.cra[key]

    def area(self, nodes: tuple[int, ...]) -> Polygon | MultiPolygon:
        if nodes not in self.sra:
            pra = None
            if self.outline is not None:  # Eq. (5.14)
                H = structure_collision_region(self.outline, self.trees, nodes, self.offsets, self.arc_step, self.reach)
                pra = self.space.difference(shapely.union_all([self.fixed, H]))
            self.sra[nodes] = structure_reachable_area(
                [self.cable_area(i, n) for i, n in enumerate(nodes)], offsets=self.offsets, pra=pra
            )
        return self.sra[nodes]

    def transitions(self, nodes: tuple[int, ...]) -> Iterator[tuple[int, int, int, float, str, int]]:
        """``(cable, new node, ray node, side, kind, object)`` for every neighbouring state:
        the ray is the forward extension of ``ray node``'s segment, the new state lies on
        the ``side`` (±1, along the left normal) of it."""
        for i, (tree, x) in enumerate(zip(self.trees, nodes)):
            if x != 0:
                yield i, tree.parent(x), x, -tree.direction(x), "unwrap", tree.obstacle(x)
            for c in tree.children(x):
                c = int(c)
                yield i, c, c, tree.direction(c), "wrap", tree.obstacle(c)


def _objects_bounds(trees: Sequence[CableStateTree]) -> tuple[float, float, float, float]:
    C = np.concatenate([t.circles for t in trees])
    lo, hi = (C[:, :2] - C[:, 2:]).min(axis=0), (C[:, :2] + C[:, 2:]).max(axis=0)
    return float(lo[0]), float(lo[1]), float(hi[0]), float(hi[1])


def _edge_pieces(domain: Polygon, e: np.ndarray, u: np.ndarray, reach: float) -> Iterator[np.ndarray]:
    """Pieces ``(2, 2)`` of the ray ``e + t u`` that run along the domain's boundary."""
    ray = LineString([e, e + reach * u])
    hit = ray.intersection(domain.buffer(2 * PROBE))
    for g in getattr(hit, "geoms", [hit]):
        if isinstance(g, LineString) and g.length > MIN_EDGE:
            xy = np.asarray(g.coords)
            yield np.array([xy[0], xy[-1]])


def build_atlas(
    robot: Robot,
    start: npt.ArrayLike,
    *,
    theta: float = 0.0,
    initial: Mapping[int, Sequence[tuple[int, int]]] | None = None,
    arc_step: float = ARC_STEP,
    max_charts: int = MAX_STRUCTURE_CHARTS,
    progress: Callable[[int, int | None], None] | None = None,
) -> StructureAtlas:
    """The structure atlas of a planar variable-structure robot (Alg. 5.1): the charts
    reachable from a start point — for a rigid platform, the page of one orientation
    (§5.2.2).

    Parameters
    ----------
    robot : Robot
        A planar robot without joints.
    start : array_like, shape (2,)
        The start point [m] (the platform reference point of a rigid platform).
    theta : float, optional
        Orientation [rad] of the page of a rigid platform (0 for a point mass).
    initial : mapping of int to sequence of (int, int), optional
        0-based cable index → its starting state (see
        :func:`taut.wrapping.wrapped_inverse_kinematics`).
    arc_step : float, optional
        Angular step [rad] of the chords of circular arcs in the reachable areas.
    max_charts : int, optional
        Chart budget (default :data:`MAX_STRUCTURE_CHARTS`): when it runs out the atlas is returned
        with ``complete`` false.
    progress : callable, optional
        ``progress(expanded, None)`` as charts are expanded (how many there are is not
        known in advance) and ``progress(expanded, expanded)`` at the end.

    Returns
    -------
    StructureAtlas

    Raises
    ------
    PoseError
        A start point or orientation that is not finite, outside the installation space or
        not in the reachable area of its structure.
    TautError
        A spatial or jointed robot, or bad options.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.1.3, Alg. 5.1; §5.2.2. (docs/references.bib: rushton2022)

    Examples
    --------
    The T-shaped robot of §6.3 from its initial point; a budget of 3 charts stops early.

    >>> import numpy as np
    >>> from taut.atlas import build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> len(atlas.charts), atlas.complete
    (31, True)
    >>> build_atlas(robot, start, max_charts=3).complete
    False
    """
    t0 = time.perf_counter()
    theta = as_number(theta, f"{robot.name}: the orientation theta", error=PoseError)
    max_charts = as_count(max_charts, "max_charts")
    arc_step = as_number(arc_step, "arc_step", positive=True)
    if robot.is_point_mass and theta != 0.0:
        raise PoseError(f"{robot.name}: a point-mass platform has no orientation (theta must be 0)")
    refuse_swivels(robot, "the structure atlas")
    if robot.dimension != 2 or robot.n_joints:
        raise TautError(f"{robot.name}: the structure atlas is implemented for planar platforms without joints")
    p0 = as_array(start, f"{robot.name}: the start point", finite=False, error=PoseError).reshape(-1)
    if p0.shape != (2,) or not np.isfinite(p0).all():
        raise PoseError(f"{robot.name}: the start point must be 2 finite coordinates, got {list(np.ravel(start))}")
    offsets = (
        np.zeros((robot.n_cables, 2))
        if robot.is_point_mass
        else np.asarray(robot.anchors, float)[:, :2] @ rotation(theta).T
    )
    space = Polygon(np.asarray(robot.installation_space, float)) if robot.installation_space else None
    if space is not None and not space.covers(shapely.Point(p0)):
        raise PoseError(f"{robot.name}: the start point {p0.tolist()} is outside the installation space")
    pose0 = p0[None] if robot.is_point_mass else np.array([[p0[0], p0[1], theta]])
    ik = wrapped_inverse_kinematics(robot, pose0, initial=initial)
    if space is None:  # the box of the exits, the objects and the start, grown by half its size
        x0, y0, x1, y1 = _objects_bounds(ik.trees)
        x0, y0, x1, y1 = min(x0, p0[0]), min(y0, p0[1]), max(x1, p0[0]), max(y1, p0[1])
        g = 0.5 * max(x1 - x0, y1 - y0) + float(np.abs(offsets).max())
        space = shapely.box(x0 - g, y0 - g, x1 + g, y1 + g)
    b = _Builder(robot, ik.trees, space, arc_step, theta, offsets)
    nodes0 = tuple(int(x) for x in ik.nodes[0])
    q0 = component_containing(b.area(nodes0), p0, tol=1e-7)
    if q0 is None:
        raise PoseError(
            f"{robot.name}: the start point {p0.tolist()} is not in the reachable area of its structure "
            "(on an object, a cable is blocked there, or the platform hits something)"
        )
    charts = [StructureChart(0, nodes0, q0, p0, _states(ik.trees, nodes0))]
    edges: list[Edge] = []
    links: dict[int, dict[int, list[int]]] = {}  #: chart → adjacent chart → its edges
    stack = [0]
    expanded = 0
    while stack:
        ci = stack.pop()
        C = charts[ci]
        expanded += 1
        if progress is not None:
            progress(expanded, None)
        for i, new, ray_node, side, kind, obj in b.transitions(C.nodes):
            tree = b.trees[i]
            e, u = tree.ray(ray_node)
            e = e - b.offsets[i]
            nrm = side * np.array([-u[1], u[0]])
            nodes = C.nodes[:i] + (new,) + C.nodes[i + 1 :]
            for seg in _edge_pieces(C.domain, e, u, b.reach):
                target = None
                for f in (0.5, 0.25, 0.75):
                    m = seg[0] + f * (seg[1] - seg[0])
                    here, there = m - PROBE * nrm, m + PROBE * nrm
                    if not shapely.contains_xy(C.domain, *here):
                        continue
                    target = _find_or_build(b, charts, nodes, there, stack, max_charts)
                    if target is not None:
                        break
                if target is not None and target != ci:
                    edges.append(Edge((ci, target), i, kind, obj, seg, nrm))
                    links.setdefault(ci, {}).setdefault(target, []).append(len(edges) - 1)
    if progress is not None:
        progress(expanded, expanded)
    built = tuple(replace(C, neighbours={k: tuple(v) for k, v in links.get(C.index, {}).items()}) for C in charts)
    return StructureAtlas(
        robot, tuple(b.trees), space, built, tuple(edges), p0, theta, offsets, not b.full, time.perf_counter() - t0
    )


def _states(trees: Sequence[CableStateTree], nodes: Sequence[int]) -> tuple[tuple[tuple[int, int], ...], ...]:
    return tuple(t.contacts(n) for t, n in zip(trees, nodes))


def _find_or_build(
    b: _Builder,
    charts: list[StructureChart],
    nodes: tuple[int, ...],
    point: np.ndarray,
    stack: list[int],
    max_charts: int,
) -> int | None:
    for C in charts:
        if C.nodes == nodes and shapely.contains_xy(C.domain, *point):
            return C.index
    q = component_containing(b.area(nodes), point, tol=0.0)
    if q is None or not shapely.contains_xy(q, *point):
        return None
    if len(charts) >= max_charts:
        b.full = True
        return None
    charts.append(StructureChart(len(charts), nodes, q, np.asarray(point, float), _states(b.trees, nodes)))
    stack.append(len(charts) - 1)
    return len(charts) - 1
