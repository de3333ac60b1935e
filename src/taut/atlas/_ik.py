"""Structure-atlas inverse kinematics of a planar VSCR (§5.3.2, Algs. 5.3 and 5.4 of Rushton 2022).

*Direct* (Alg. 5.3): the active chart of a point is the first chart whose domain ``Q``
contains it (a point-in-polygon test, here shapely's prepared ``contains_xy`` over all
query points of a chart at once); the lengths follow from the chart's elements by
Eq. (4.9), ``l_i = l_{0,i} + ν_i(b_i) + ‖a_i(b_i) − b_i‖`` with the anchor
``b_i = p + R(θ) r_i`` of the atlas page (``b_i = p`` for a point mass;
:func:`taut.atlas.chart_lengths`).
Several charts may contain a point (Fig. 5.1); Alg. 5.3 takes the first, and so does
:func:`direct_ik` unless ``charts`` restricts the search (e.g. to the workspace).

*Iterative* (Alg. 5.4): from the active chart and a move ``p_1 → p_2``, crossing a
traversable edge of the active chart's domain switches to the adjacent chart; leaving
the domain anywhere else is an invalid move; otherwise the chart stays.  Steps must be
small against the charts (one switch per step, the earliest crossing along the move).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.3.2, Algs. 5.3 and 5.4; Eq. 4.9. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
import shapely

from taut._checks import as_array, as_index
from taut._results import Result, jsonable
from taut.atlas._atlas import StructureAtlas
from taut.atlas._chart import chart_lengths
from taut.errors import PoseError, TautError
from taut.geometry import segments_intersect


@dataclass(frozen=True)
class AtlasIK(Result):
    """Inverse kinematics at ``N`` points (:func:`direct_ik`, :func:`iterative_ik`).

    Attributes
    ----------
    charts : ndarray of int, shape (N,)
        The active chart (−1 where no chart contains the point).
    lengths : ndarray, shape (N, n)
        Cable lengths [m] (NaN where no chart).
    exit_points : ndarray, shape (N, n, 2)
        Where each active segment leaves its last object (NaN where no chart).
    found : ndarray of bool, shape (N,)
        A chart contains the point (a property).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.2, Algs. 5.3–5.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas, direct_ik, iterative_ik, iterative_step, locate
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> ik = direct_ik(atlas, [start, [100.0, 100.0]])
    >>> ik.charts.tolist(), ik.found.tolist(), np.round(ik.lengths[0, :2], 4)
    ([0, -1], [True, False], array([0.8374, 0.8374]))
    """

    charts: np.ndarray  #: ``(N,)`` active chart (``-1`` where no chart contains the point)
    lengths: np.ndarray  #: ``(N, n)`` cable lengths (NaN where no chart)
    exit_points: np.ndarray  #: ``(N, n, 2)`` where each active segment leaves its last object

    @property
    def found(self) -> np.ndarray:
        """``(N,)``: a chart contains the point."""
        return self.charts >= 0

    def as_dict(self) -> dict:
        """``charts``, ``found``, ``lengths`` and ``exit_points`` in plain JSON types
        (``None`` where no chart contains the point)."""
        return {
            "charts": jsonable(self.charts),
            "found": jsonable(self.found),
            "lengths": jsonable(self.lengths),
            "exit_points": jsonable(self.exit_points),
        }


def _points(points: npt.ArrayLike) -> np.ndarray:
    """Reference points ``(N, 2)`` (one point ``(2,)`` is one row)."""
    return as_array(
        np.atleast_2d(as_array(points, "points", error=PoseError)), "points", shape=(None, 2), error=PoseError
    )


def _charts(atlas: StructureAtlas, charts: Iterable[int]) -> list[int]:
    try:
        return [as_index(c, "charts", len(atlas.charts)) for c in charts]
    except TypeError:
        raise TautError(f"charts: expected chart indices 0..{len(atlas.charts) - 1}, got {charts!r}") from None


def locate(atlas: StructureAtlas, points: npt.ArrayLike, *, charts: Iterable[int] | None = None) -> np.ndarray:
    """The first chart containing each point (the point location of Alg. 5.3).

    Parameters
    ----------
    atlas : StructureAtlas
    points : array_like, shape (N, 2)
        Reference points [m].
    charts : iterable of int, optional
        The charts searched, in order (default all).

    Returns
    -------
    ndarray of int, shape (N,)
        Chart indices, −1 where none contains the point.

    Raises
    ------
    PoseError
        Points that are not rows of two finite numbers.
    TautError
        Charts that are not the atlas's.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.2, Alg. 5.3. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas, direct_ik, iterative_ik, iterative_step, locate
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> locate(atlas, [start, [0.9, -0.45]]).tolist()
    [0, 15]
    """
    P = _points(points)
    charts = None if charts is None else _charts(atlas, charts)
    out = np.full(len(P), -1, dtype=np.int64)
    todo = np.arange(len(P))
    for c in range(len(atlas.charts)) if charts is None else charts:
        if not len(todo):
            break
        dom = atlas.charts[c].domain
        shapely.prepare(dom)
        x0, y0, x1, y1 = dom.bounds
        q = P[todo]
        box = (q[:, 0] >= x0) & (q[:, 0] <= x1) & (q[:, 1] >= y0) & (q[:, 1] <= y1)
        if not box.any():
            continue
        sel = todo[box]
        hit = shapely.contains_xy(dom, P[sel, 0], P[sel, 1])
        out[sel[hit]] = c
        todo = np.setdiff1d(todo, sel[hit], assume_unique=True)
    return out


def _evaluate(atlas: StructureAtlas, P: np.ndarray, ch: np.ndarray) -> AtlasIK:
    n = len(atlas.trees)
    lengths = np.full((len(P), n), np.nan)
    exits = np.full((len(P), n, 2), np.nan)
    for c in np.unique(ch[ch >= 0]):
        sel = ch == c
        L, _, A = chart_lengths(atlas.trees, atlas.charts[c].nodes, P[sel], offsets=atlas.offsets)
        lengths[sel], exits[sel] = L, A
    return AtlasIK(ch, lengths, exits)


def direct_ik(atlas: StructureAtlas, points: npt.ArrayLike, *, charts: Iterable[int] | None = None) -> AtlasIK:
    """Inverse kinematics by the atlas at every point (Alg. 5.3): the first chart containing
    it, and the lengths of that chart's structure.

    Parameters
    ----------
    atlas : StructureAtlas
    points : array_like, shape (N, 2)
        Reference points [m].
    charts : iterable of int, optional
        The charts searched, in order (default all; e.g. the workspace's).

    Returns
    -------
    AtlasIK

    Raises
    ------
    PoseError
        Points that are not rows of two finite numbers.
    TautError
        Charts that are not the atlas's.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.2, Alg. 5.3. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas, direct_ik, iterative_ik, iterative_step, locate
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> ik = direct_ik(atlas, [[0.9, -0.45]])
    >>> ik.charts.tolist(), atlas.charts[15].states[2]
    ([15], ((0, -1),))
    """
    P = _points(points)
    return _evaluate(atlas, P, locate(atlas, P, charts=charts))


def _crossings(atlas: StructureAtlas, chart: int, p1: np.ndarray, d: np.ndarray) -> Iterator[tuple[float, int]]:
    """``(t, neighbour)`` of the traversable edges of ``chart`` that ``p1 + t d`` crosses
    towards the neighbour."""
    for nb, idx in atlas.charts[chart].neighbours.items():
        for k in idx:
            a, b = atlas.edges[k].segment
            if d @ atlas.edges[k].normal > 0 and segments_intersect(p1, p1 + d, a, b):
                e = b - a
                den = d[0] * e[1] - d[1] * e[0]
                w = a - p1
                yield ((w[0] * e[1] - w[1] * e[0]) / den if den != 0 else 0.0), nb


def iterative_step(atlas: StructureAtlas, chart: int, p1: npt.ArrayLike, p2: npt.ArrayLike) -> int:
    """One step of Alg. 5.4: the active chart after a straight move.

    The earliest traversable edge crossed switches the chart; the rest of the move
    continues from the new chart (several transitions at one point — e.g. two cables
    wrapping at a corner of the domain — are taken one after the other).

    Parameters
    ----------
    atlas : StructureAtlas
    chart : int
        The active chart at ``p1``.
    p1, p2 : array_like, shape (2,)
        The move [m].

    Returns
    -------
    int
        The active chart at ``p2``.

    Raises
    ------
    PoseError
        The move leaves a chart through an edge that is not traversable, or bad points.
    TautError
        A chart that is not the atlas's.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.2, Alg. 5.4. (docs/references.bib: rushton2022)

    Examples
    --------
    Moving down across a transition edge, cable 3 wraps object 1 clockwise:

    >>> import numpy as np
    >>> from taut.atlas import build_atlas, direct_ik, iterative_ik, iterative_step, locate
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> iterative_step(atlas, 0, [0.9, -0.3], [0.9, -0.45])
    15
    """
    chart = as_index(chart, "chart", len(atlas.charts))
    p1 = as_array(p1, "p1", shape=(2,), error=PoseError)
    p2 = as_array(p2, "p2", shape=(2,), error=PoseError)
    d = p2 - p1
    t0, prev = 0.0, -1
    for _ in range(4 * len(atlas.trees) + 4):
        best, target = np.inf, chart
        for t, nb in _crossings(atlas, chart, p1, d):
            if t >= t0 - 1e-12 and t < best and not (nb == prev and t <= t0 + 1e-12):
                best, target = t, nb
        if target == chart:
            rest = shapely.LineString([p1 + t0 * d, p2]) if t0 < 1 else shapely.Point(p2)
            if not shapely.covers(atlas.charts[chart].domain.buffer(1e-9), rest):
                raise PoseError(
                    f"the move {p1.tolist()} → {p2.tolist()} leaves chart {chart} through an edge that is not traversable"
                )
            return chart
        prev, chart, t0 = chart, target, max(t0, best)
    raise PoseError(f"the move {p1.tolist()} → {p2.tolist()} does not settle in a chart")


def iterative_ik(atlas: StructureAtlas, points: npt.ArrayLike, *, chart: int = 0) -> AtlasIK:
    """Inverse kinematics by the atlas along a polyline (Alg. 5.4): the active chart is
    carried from point to point across the traversable edges.

    Parameters
    ----------
    atlas : StructureAtlas
    points : array_like, shape (T, 2)
        The polyline [m]; steps small against the charts.
    chart : int, optional
        The active chart at ``points[0]``.

    Returns
    -------
    AtlasIK

    Raises
    ------
    PoseError
        A step that leaves a chart through an edge that is not traversable, or bad points.
    TautError
        A chart that is not the atlas's.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.2, Alg. 5.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas, direct_ik, iterative_ik, iterative_step, locate
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> iterative_ik(atlas, [start, [0.9, -0.3], [0.9, -0.45]]).charts.tolist()
    [0, 0, 15]
    """
    P = _points(points)
    ch = np.empty(len(P), dtype=np.int64)
    ch[0] = as_index(chart, "chart", len(atlas.charts))
    for j in range(1, len(P)):
        ch[j] = iterative_step(atlas, int(ch[j - 1]), P[j - 1], P[j])
    return _evaluate(atlas, P, ch)
