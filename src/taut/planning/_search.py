"""A* over the charts of a growing atlas, and the path refined on the manifold.

§4 of Bohigas et al. (2013): the atlas of :mod:`taut.planning._continuation` is
expanded in A* order (Russell & Norvig, ref. [25]) from the chart at the start point:
the open chart of least ``g + h`` is closed next, where ``g`` is the length of the
chart-centre path found so far and ``h`` the straight-line distance to the goal in the
same coordinates (admissible: no path on the manifold is shorter).  The search stops as
soon as a chart's map reaches the goal point; when no open chart is left the connected
component of the start has been covered without reaching the goal — *no path exists at
the resolution of the chart radius*.

The returned path is refined on the manifold: between consecutive chart centres ``x_a``
and ``x_b`` it follows chart ``a`` up to the middle of the tangent segment and chart ``b``
from there, each half mapped by Newton projection at a spacing of at most ``spacing``.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

import heapq
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_number
from taut._results import Result, jsonable
from taut.errors import TautError
from taut.planning._continuation import MAX_CHARTS, Atlas, ImplicitManifold

__all__ = ["PathResult", "astar", "continuous", "refine_path"]


@dataclass(frozen=True)
class PathResult(Result):
    """A path on a manifold, or why there is none (:func:`taut.planning.plan_path`).

    Attributes
    ----------
    found : bool
        A path from the start to the goal was found.
    path : ndarray, shape (N, n)
        Points on the manifold, start to goal, continuous across its symmetry (empty if
        not found); poses for the pose-space planners, from the start to the goal as given.
    charts : int
        Charts in the atlas when the search stopped (0 in pose space).
    expanded : int
        Charts closed by A*, lattice points closed by the grid (0 for AtlasRRT and
        RRT-Connect).
    no_path : bool
        A* closed every chart of the start's component (the grid every lattice point of the
        start's component) without reaching the goal: a proof
        that no path exists at the resolution of the chart radius.
    length : float
        Length of ``path`` in the atlas metric (NaN when not found).
    elapsed_s : float
        Wall-clock time [s].
    atlas : Atlas or None
        The atlas the search grew (``None`` for the pose-space planners).
    method : str
        ``"astar"``, ``"atlasrrt"``, ``"rrtconnect"`` or ``"grid"``.
    nodes : int
        Tree nodes grown by AtlasRRT or RRT-Connect (0 for A* and the grid).
    complete : bool
        The question is settled: ``found`` or ``no_path`` (a property).

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
    .. [2] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
       exploring manifolds", IEEE Transactions on Robotics 29(1), 2013, Algs. 1–4.
       (docs/references.bib: jaillet2013)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.planning import ImplicitManifold, plan_path
    >>> sphere = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
    >>> res = plan_path(sphere, [1.0, 0, 0], [0, 1.0, 0], radius=0.3)
    >>> res.found, res.complete, res.method, round(res.length, 3)
    (True, True, 'astar', 1.859)
    """

    found: bool
    path: np.ndarray  #: ``(N, n)`` points on the manifold, start to goal (empty if not found)
    charts: int  #: charts in the atlas when the search stopped
    expanded: int  #: charts closed by A* (0 for AtlasRRT)
    no_path: bool  #: every chart closed without reaching the goal: no path at this resolution (a proof)
    length: float  #: length of ``path`` in the atlas metric (NaN if not found)
    elapsed_s: float
    atlas: Atlas | None  #: the atlas the search grew (``None`` in pose space)
    method: str  #: the planner: ``"astar"``, ``"atlasrrt"``, ``"rrtconnect"`` or ``"grid"``
    nodes: int  #: tree nodes grown by AtlasRRT or RRT-Connect (0 for A* and the grid)

    @property
    def complete(self) -> bool:
        """The question is settled: a path was found, or none exists at this resolution."""
        return self.found or self.no_path

    def as_dict(self) -> dict:
        """The result in plain JSON types (``length`` ``None`` without a path), without the
        atlas: ``method``, ``found``, ``no_path``, ``complete``, ``path``, ``charts``,
        ``expanded``, ``nodes``, ``length``, ``elapsed_s``."""
        return {
            "method": self.method,
            "found": self.found,
            "no_path": self.no_path,
            "complete": self.complete,
            "path": jsonable(self.path),
            "charts": self.charts,
            "expanded": self.expanded,
            "nodes": self.nodes,
            "length": jsonable(self.length),
            "elapsed_s": self.elapsed_s,
        }


def _segment(atlas: Atlas, i: int, u0: np.ndarray, u1: np.ndarray, spacing: float) -> list[np.ndarray]:
    n = max(1, int(np.ceil(np.linalg.norm(u1 - u0) / spacing)))
    pts = []
    for t in np.linspace(0.0, 1.0, n + 1)[1:]:
        y = atlas.chart_map(i, u0 + t * (u1 - u0))
        if y is None:
            raise TautError(f"path refinement: the map of chart {i} failed")
        pts.append(y)
    return pts


def refine_path(atlas: Atlas, charts: list[int], goal: np.ndarray, *, spacing: float) -> np.ndarray:
    """Manifold points along a sequence of charts, ending at a goal reached through the
    last one (module docstring).

    Parameters
    ----------
    atlas : Atlas
    charts : list of int
        Chart indices, each adjacent to the next; the path starts at the first one's
        centre.
    goal : array_like, shape (n,)
        A manifold point covered by the last chart.
    spacing : float
        Largest step between points, in tangent coordinates.

    Returns
    -------
    ndarray, shape (N, n)
        Continuous across the manifold's symmetry, ending at ``goal``.

    Raises
    ------
    TautError
        Charts that are not the atlas's, a bad ``spacing``, or a chart map that fails.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.planning import Atlas, ImplicitManifold, refine_path
    >>> sphere = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
    >>> atlas = Atlas(sphere, [0, 0, 1.0], radius=0.5)
    >>> np.round(refine_path(atlas, [0], [0.3, 0, np.sqrt(0.91)], spacing=0.1), 3)
    array([[0.   , 0.   , 1.   ],
           [0.1  , 0.   , 0.995],
           [0.2  , 0.   , 0.98 ],
           [0.3  , 0.   , 0.954]])
    """
    spacing = as_number(spacing, "spacing", positive=True)
    goal = as_array(goal, "the goal point", shape=(atlas.centres.shape[1],))
    if not charts or any(not 0 <= c < len(atlas.charts) for c in charts):
        raise TautError(
            f"charts: expected a sequence of charts of the atlas (0..{len(atlas.charts) - 1}), got {charts}"
        )
    pts = [atlas.charts[charts[0]].centre]
    for a, b in zip(charts[:-1], charts[1:]):
        ub = atlas.coordinates(a, atlas.charts[b].centre)
        pts += _segment(atlas, a, np.zeros_like(ub), 0.5 * ub, spacing)
        pts += _segment(atlas, b, atlas.coordinates(b, pts[-1]), np.zeros_like(ub), spacing)
    k = atlas.manifold.dim
    pts += _segment(atlas, charts[-1], np.zeros(k), atlas.coordinates(charts[-1], goal), spacing)
    pts[-1] = np.asarray(goal, float)
    return continuous(atlas, np.array(pts))


def continuous(atlas: Atlas, pts: np.ndarray) -> np.ndarray:
    """The images of the points ``pts`` ``(N, n)`` (a path on the manifold modulo its
    symmetry) that make it continuous: each point is the image nearest its predecessor."""
    out = np.array(pts, float)
    for m in range(1, len(out)):
        out[m] = atlas.near(out[m], out[m - 1])[0][0]
    return out


def astar(
    manifold: ImplicitManifold,
    start: npt.ArrayLike,
    goal: npt.ArrayLike,
    *,
    radius: float,
    epsilon: float = 0.1,
    metric: np.ndarray | None = None,
    max_charts: int = MAX_CHARTS,
    spacing: float | None = None,
    progress: Callable[[int, int | None], None] | None = None,
) -> PathResult:
    """A path on ``manifold`` from ``start`` to ``goal`` (both on it), or proof that the
    connected component of ``start`` does not reach ``goal`` at resolution ``radius``.

    ``max_charts`` bounds the atlas (no chart is created beyond it, also in the middle of
    an expansion), hence the time and the memory: when it runs out the answer is
    ``found=False, no_path=False``.  ``progress(expanded, None)`` is called as charts are
    expanded (how many the search needs is not known in advance) and
    ``progress(expanded, expanded)`` when it stops.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
    """
    t0 = time.perf_counter()
    start, goal = np.asarray(start, float), np.asarray(goal, float)
    if np.linalg.norm(manifold.function(goal)) > 1e-6 * (1 + np.linalg.norm(goal)):
        raise TautError("the goal point is not on the manifold (|F(goal)| too large)")
    atlas = Atlas(manifold, start, radius=radius, epsilon=epsilon, metric=metric)
    h = lambda i: atlas.cost(atlas.charts[i].centre, goal)  # noqa: E731
    g = {0: 0.0}
    parent = {0: -1}
    heap = [(h(0), 0)]
    done: set[int] = set()
    found_at = None
    expanded = 0
    if isinstance(max_charts, bool) or not isinstance(max_charts, (int, np.integer)) or max_charts < 2:
        raise TautError(f"max_charts must be an integer >= 2, got {max_charts!r}")
    stopped = False  # the chart budget ran out
    while heap:
        f, i = heapq.heappop(heap)
        if i in done:
            continue
        if atlas.reaches(i, goal):
            found_at = i
            break
        if len(atlas.charts) >= max_charts:
            stopped = True
            break
        atlas.grow(i, max_charts)
        if not atlas.charts[i].expanded:
            stopped = True
            break
        done.add(i)
        expanded += 1
        if progress is not None:
            progress(expanded, None)
        for j, c in atlas.charts[i].neighbours.items():
            if j in done:
                continue
            gj = g[i] + c
            if gj < g.get(j, np.inf):
                g[j], parent[j] = gj, i
                heapq.heappush(heap, (gj + h(j), j))
    no_path = found_at is None and not stopped and not heap
    if progress is not None:
        progress(expanded, expanded)
    if found_at is None:
        return PathResult(
            False,
            np.empty((0, start.size)),
            len(atlas.charts),
            expanded,
            no_path,
            float("nan"),
            time.perf_counter() - t0,
            atlas,
            "astar",
            0,
        )
    seq = [found_at]
    while parent[seq[-1]] >= 0:
        seq.append(parent[seq[-1]])
    seq.reverse()
    path = refine_path(atlas, seq, goal, spacing=spacing or radius / 4)
    length = float(np.sum(np.linalg.norm(np.diff(path[:, atlas.metric], axis=0), axis=1)))
    return PathResult(
        True, path, len(atlas.charts), expanded, False, length, time.perf_counter() - t0, atlas, "astar", 0
    )
