"""AtlasRRT: rapidly exploring random trees grown on a manifold through an atlas of charts.

Jaillet & Porta (2013), Algs. 1–4, on an :class:`~taut.planning.ImplicitManifold`:

* the **atlas** (:class:`~taut.planning.Atlas`) starts with one chart at the
  start and one at the goal; a chart is a tangent space ``Ψ_c`` at a centre ``x_c`` with a
  ball of radius ``ρ`` and a polytope ``P_c`` cropped by its neighbours;
* **sampling**: a chart ``c`` is drawn uniformly, then a point ``u_r`` uniformly in its ball,
  rejected unless ``u_r ∈ P_c`` (so the atlas' covered area is sampled uniformly, and the
  samples of border charts lead the trees into unexplored regions); the random target is
  the ambient point ``x_r = x_c + Ψ_c u_r``;
* **extension** (Alg. 3) from the tree node ``x_n`` nearest ``x_r`` (in the ``metric``
  coordinates): steps of length ``δ`` in the tangent space of the node's chart toward the
  coordinates of ``x_r``, each mapped to the manifold by the chart's projection; a step
  whose projection fails or leaves the box blocks the branch (the boundary of the
  wrench-feasible set).  A step that leaves the chart's **validity area** — projection
  farther than ``ε`` from the tangent point, a step stretched by more than ``1/cos α`` by
  the projection, or ``‖u‖ > ρ`` — creates a new chart at the last node and continues in
  it; a step out of ``P_c`` continues in the neighbour chart that covers it;
* **bidirectional** (Alg. 4, the RRT-Connect scheme of Kuffner & LaValle): a tree grows
  from the start and one from the goal; each iteration extends one toward a random
  sample, then the other toward the node just reached, and the trees are joined when the
  second extension ends within ``δ`` of it; then the trees swap roles.  With
  ``bidirectional=False`` only the start tree grows, toward the goal with probability
  ``goal_bias``.

The path is the tree branch (points ``δ`` apart on the manifold), made continuous across the
manifold's :class:`~taut.planning.Symmetry`, and optionally **shortened**
(:func:`shorten_path`): random shortcuts between two path points, walked on the atlas
the same way, replace the stretch between them when shorter.  A random search cannot
prove that no path exists: when the budget runs out the answer is ``found=False,
no_path=False`` (:func:`taut.planning.plan_path` is the complete search).

References
----------
.. [1] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
   exploring manifolds", IEEE Transactions on Robotics 29(1), 2013, Algs. 1–4.
   (docs/references.bib: jaillet2013)
.. [2] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count, as_number, as_rng
from taut.errors import TautError
from taut.planning._continuation import MAX_CHARTS, Atlas, ImplicitManifold
from taut.planning._search import PathResult, continuous

__all__ = ["MAX_NODES", "MIN_STEP", "Tree", "atlas_rrt", "shorten_path"]

#: The tree-node budget of AtlasRRT when none is given: with the chart budget, it bounds
#: the time and memory of a search that finds no path (a random search never proves that
#: none exists); every step of a walk is a node, one point and one projection.
MAX_NODES = 20_000
#: Smallest step ``δ`` as a fraction of the chart radius: a walk across one chart takes up
#: to ``2 / MIN_STEP`` steps, each a projection on the manifold and a node of the tree.
MIN_STEP = 1e-3


class Tree:
    """Nodes on the manifold with their parent and chart (arrays grown by doubling)."""

    def __init__(self, root: np.ndarray, chart: int) -> None:
        self.points = np.empty((64, root.size))
        self.parent = np.empty(64, int)
        self.chart = np.empty(64, int)
        self.size = 0
        self.add(root, -1, chart)

    def add(self, x: np.ndarray, parent: int, chart: int) -> int:
        if self.size == len(self.parent):
            self.points = np.vstack([self.points, np.empty_like(self.points)])
            self.parent = np.concatenate([self.parent, np.empty_like(self.parent)])
            self.chart = np.concatenate([self.chart, np.empty_like(self.chart)])
        n = self.size
        self.points[n], self.parent[n], self.chart[n] = x, parent, chart
        self.size += 1
        return n

    def branch(self, n: int) -> list[int]:
        """Node indices from the root to node ``n``."""
        out = [n]
        while self.parent[out[-1]] >= 0:
            out.append(int(self.parent[out[-1]]))
        return out[::-1]


class _Walker:
    """Steps of length ``δ`` on the atlas (Alg. 3 of Jaillet & Porta 2013)."""

    def __init__(self, atlas: Atlas, step: float, max_charts: int) -> None:
        self.atlas = atlas
        self.step = step
        self.max_charts = max_charts
        self.cos_alpha = 1.0 - atlas.epsilon
        self.charts_full = False
        # a graph puts every node on the manifold exactly, whatever the tangential tolerance
        self.tol = 1e-4 if atlas.manifold.graph is not None else 1e-10

    def _chart_at(self, x: np.ndarray, chart: int) -> int | None:
        """A new chart centred at ``x``, a neighbour of ``chart``; ``None`` at the chart limit."""
        atlas = self.atlas
        if len(atlas.charts) >= self.max_charts:
            self.charts_full = True
            return None
        j = atlas.add_chart(x)
        if chart not in atlas.charts[j].neighbours:
            c = atlas.cost(x, atlas.charts[chart].centre)
            atlas.charts[j].neighbours[chart] = c
            atlas.charts[chart].neighbours[j] = c
        return j

    def _covering_neighbour(self, chart: int, x: np.ndarray) -> tuple[int, np.ndarray] | None:
        atlas = self.atlas
        for j in atlas.charts[chart].neighbours:
            u = atlas.coordinates(j, x)
            if np.linalg.norm(u) <= atlas.radius and atlas.charts[j].polytope.contains(u):
                return j, u
        return None

    def walk(
        self, x: np.ndarray, chart: int, target: np.ndarray, max_steps: int
    ) -> tuple[list[np.ndarray], list[int], bool]:
        """From the manifold point ``x`` (covered by ``chart``) toward the point ``target``:
        the points reached (``x`` excluded), their charts, and whether the walk ended within
        ``δ`` of ``target`` (in the tangent coordinates of the last chart)."""
        atlas, delta = self.atlas, self.step
        pts: list[np.ndarray] = []
        charts: list[int] = []
        c = chart
        u_n = atlas.coordinates(c, x)
        u_r = atlas.coordinates(c, target)
        for _ in range(max_steps):
            d = u_r - u_n
            dist = float(np.linalg.norm(d))
            if dist <= delta:
                return pts, charts, True
            u_j = u_n + (delta / dist) * d
            ch = atlas.charts[c]
            x_j = atlas.chart_map(c, u_j, newton_fallback=False, tol=self.tol)
            if x_j is None or not atlas.manifold.in_box(x_j):
                return pts, charts, False  # blocked: the boundary of the manifold's box
            u_j = ch.basis.T @ (x_j - ch.centre)
            x_n = atlas.local(c, x)
            step = float(np.linalg.norm(x_j - x_n))
            valid = (
                np.linalg.norm(u_j) <= ch.radius
                and np.linalg.norm(x_j - (ch.centre + ch.basis @ u_j)) <= atlas.epsilon
                and np.linalg.norm(u_j - u_n) >= self.cos_alpha * step
            )
            if not valid:
                if np.linalg.norm(u_n) < 1e-9 * (1.0 + ch.radius):
                    return pts, charts, False  # the chart at x itself cannot step: a singular spot
                new = self._chart_at(x, c)
                if new is None:
                    return pts, charts, False
                c = new
                u_n = atlas.coordinates(c, x)
                u_r = atlas.coordinates(c, target)
                continue
            if not ch.polytope.contains(u_j):
                other = self._covering_neighbour(c, x_j)
                if other is not None:
                    c, u_j = other
                    u_r = atlas.coordinates(c, target)
            pts.append(x_j)
            charts.append(c)
            x, u_n = x_j, u_j
        return pts, charts, False


def _nearest(atlas: Atlas, tree: Tree, x: np.ndarray) -> int:
    P = tree.points[: tree.size]
    near, _ = atlas.near(P, x)
    return int(np.argmin(np.linalg.norm((near - x)[:, atlas.metric], axis=1)))


def _sample(atlas: Atlas, rng: np.random.Generator) -> np.ndarray:
    """A random ambient point over the atlas: a random chart, a uniform point of its ball
    inside its polytope (a few rejections at most, else the last draw)."""
    k = atlas.manifold.dim
    for _ in range(20):
        c = atlas.charts[int(rng.integers(len(atlas.charts)))]
        v = rng.normal(size=k)
        u = v / np.linalg.norm(v) * c.radius * rng.uniform() ** (1.0 / k)
        if c.polytope.contains(u):
            break
    return c.centre + c.basis @ u


def _length(atlas: Atlas, path: np.ndarray) -> float:
    return float(np.sum(np.linalg.norm(np.diff(path[:, atlas.metric], axis=0), axis=1)))


def shorten_path(
    atlas: Atlas,
    path: np.ndarray,
    charts: list[int],
    *,
    step: float,
    seed: int | np.random.Generator = 0,
    attempts: int = 60,
) -> tuple[np.ndarray, list[int]]:
    """A path shortened by random shortcuts on the manifold: for two random points of the
    path, walk from one toward the other on the atlas; a walk that arrives and is shorter
    than the stretch it skips replaces it.

    Parameters
    ----------
    atlas : Atlas
        An atlas covering the path.
    path : array_like, shape (N, n)
        Manifold points, continuous across its symmetry.
    charts : list of int
        The chart of each point.
    step : float
        Step ``δ`` of the walks, in tangent coordinates.
    seed : int or numpy.random.Generator, optional
        The random shortcuts.
    attempts : int, optional
        Shortcuts tried.

    Returns
    -------
    path : ndarray, shape (M, n)
        The shortened path, with the same ends.
    charts : list of int
        The chart of each point.

    Raises
    ------
    TautError
        A path and charts that do not match, or bad options.

    References
    ----------
    .. [1] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
       exploring manifolds", IEEE Transactions on Robotics 29(1), 2013.
       (docs/references.bib: jaillet2013)

    Examples
    --------
    A detour near the north pole of the unit sphere, in one chart:

    >>> import numpy as np
    >>> from taut.planning import Atlas, ImplicitManifold, shorten_path
    >>> sphere = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
    >>> atlas = Atlas(sphere, [0, 0, 1.0], radius=0.5, vertices=False)
    >>> xy = np.array([[0, 0], [0.1, 0.15], [0.2, 0.2], [0.3, 0.15], [0.4, 0.0]])
    >>> path = np.column_stack([xy, np.sqrt(1 - (xy**2).sum(axis=1))])
    >>> short, charts = shorten_path(atlas, path, [0] * 5, step=0.05, seed=0)
    >>> def length(p):
    ...     return round(float(np.linalg.norm(np.diff(p, axis=0), axis=1).sum()), 3)
    >>> length(path), length(short), np.allclose(short[-1], path[-1])
    (0.591, 0.411, True)
    """
    rng = as_rng(seed)
    step = as_number(step, "step", positive=True)
    attempts = as_count(attempts, "attempts", minimum=0)
    path = as_array(path, "path", shape=(None, atlas.centres.shape[1]))
    if len(charts) != len(path) or any(not 0 <= c < len(atlas.charts) for c in charts):
        raise TautError(f"charts: expected one chart of the atlas (0..{len(atlas.charts) - 1}) per point of the path")
    pts = [np.asarray(p, float) for p in path]
    chs = list(charts)
    walker = _Walker(atlas, step, max_charts=len(atlas.charts) + 10 * attempts)
    for _ in range(attempts):
        if len(pts) < 3:
            break
        i, j = sorted(rng.choice(len(pts), 2, replace=False))
        if j - i < 2:
            continue
        old = _length(atlas, np.array(pts[i : j + 1]))
        direct = atlas.cost(pts[j], pts[i])
        new, new_ch, ok = walker.walk(pts[i], chs[i], pts[j], max_steps=int(np.ceil(1.5 * direct / step)) + 2)
        if not ok:
            continue
        seg = continuous(atlas, np.array([pts[i], *new, pts[j]]))
        if np.linalg.norm(seg[-1] - pts[j]) > 1e-9 * (1.0 + np.linalg.norm(pts[j])):
            continue  # the shortcut arrives at another image of pts[j]: not the same path class
        if _length(atlas, seg) < old - 1e-12:
            pts = pts[: i + 1] + list(seg[1:-1]) + pts[j:]
            chs = chs[: i + 1] + new_ch + chs[j:]
    return np.array(pts), chs


def atlas_rrt(
    manifold: ImplicitManifold,
    start: npt.ArrayLike,
    goal: npt.ArrayLike,
    *,
    radius: float,
    step: float | None = None,
    epsilon: float = 0.1,
    metric: np.ndarray | None = None,
    seed: int | np.random.Generator = 0,
    bidirectional: bool = True,
    goal_bias: float = 0.1,
    max_nodes: int = MAX_NODES,
    max_charts: int = MAX_CHARTS,
    time_limit: float | None = None,
    shorten: bool = False,
    progress: Callable[[int, int | None], None] | None = None,
) -> PathResult:
    """A path on ``manifold`` from ``start`` to ``goal`` (both on it) by AtlasRRT (module doc),
    deterministic for a ``seed``, within ``max_nodes`` tree nodes (every step of a walk is
    a node: the budget bounds the projections, hence the time and the memory),
    ``max_charts`` charts and ``time_limit`` seconds.  ``step`` is ``δ`` (default
    ``radius / 4``, at least :data:`MIN_STEP` times the radius).  The result's ``nodes``
    counts tree nodes; ``no_path`` is always ``False``.

    ``progress(nodes, None)`` is called every 50 iterations, ``progress(nodes, nodes)`` at the end.

    References
    ----------
    .. [1] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
       exploring manifolds", IEEE Transactions on Robotics 29(1), 2013, Algs. 1–4.
       (docs/references.bib: jaillet2013)
    """
    t0 = time.perf_counter()
    start, goal = np.asarray(start, float), np.asarray(goal, float)
    delta = radius / 4 if step is None else float(step)
    if not 0 < delta <= radius:
        raise TautError(f"AtlasRRT needs 0 < step <= radius, got step {delta:g}, radius {radius:g}")
    if delta < MIN_STEP * radius:
        raise TautError(
            f"AtlasRRT step {delta:g} is below {MIN_STEP:g} times the chart radius {radius:g}: "
            f"a walk across one chart would take more than {2 / MIN_STEP:.0f} steps; give a step of at least {MIN_STEP * radius:g}"
        )
    if max_nodes < 2 or max_charts < 2:
        raise TautError("AtlasRRT needs max_nodes >= 2 and max_charts >= 2")
    if np.linalg.norm(manifold.function(goal)) > 1e-6 * (1 + np.linalg.norm(goal)):
        raise TautError("the goal point is not on the manifold (|F(goal)| too large)")
    rng = as_rng(seed)
    atlas = Atlas(manifold, start, radius=radius, epsilon=epsilon, metric=metric, vertices=False)
    goal_chart = atlas.add_chart(goal)
    trees = [Tree(atlas.local(0, start), 0), Tree(atlas.local(goal_chart, goal), goal_chart)]
    walker = _Walker(atlas, delta, max_charts)
    reach = max(2, int(np.ceil(2 * radius / delta)))  # steps per extension toward a random sample
    joined: tuple[int, int, int] | None = None  # (index of tree a, node in a, node in b)
    it = 0

    def extend(t: int, target: np.ndarray, max_steps: int) -> int:
        tree = trees[t]
        n = _nearest(atlas, tree, target)
        # a walk adds one node per step: it stops where the node budget does
        left = max_nodes - trees[0].size - trees[1].size
        pts, chs, _ = walker.walk(tree.points[n], int(tree.chart[n]), target, min(max_steps, left))
        for x, c in zip(pts, chs):
            n = tree.add(x, n, c)
        return n

    while trees[0].size + trees[1].size < max_nodes and not walker.charts_full:
        if time_limit is not None and time.perf_counter() - t0 > time_limit:
            break
        it += 1
        if progress is not None and it % 50 == 0:
            progress(trees[0].size + trees[1].size, None)
        if bidirectional:
            a = (it - 1) % 2
            la = extend(a, _sample(atlas, rng), reach)
            xa = trees[a].points[la]
            lb = extend(1 - a, xa, max_nodes)
            if atlas.cost(trees[1 - a].points[lb], xa) <= delta * (1 + 1e-9):
                joined = (a, la, lb)
                break
        else:
            target = trees[1].points[0] if rng.uniform() < goal_bias else _sample(atlas, rng)
            la = extend(0, target, reach)
            if atlas.cost(trees[0].points[la], trees[1].points[0]) <= delta * (1 + 1e-9):
                joined = (0, la, 0)
                break
    nodes = trees[0].size + trees[1].size
    if progress is not None:
        progress(nodes, nodes)
    if joined is None:
        return PathResult(
            False,
            np.empty((0, start.size)),
            len(atlas.charts),
            0,
            False,
            float("nan"),
            time.perf_counter() - t0,
            atlas,
            "atlasrrt",
            nodes,
        )
    a, la, lb = joined
    ia, ib = trees[a].branch(la), trees[1 - a].branch(lb)[::-1]
    pts = [trees[a].points[i] for i in ia] + [trees[1 - a].points[i] for i in ib]
    chs = [int(trees[a].chart[i]) for i in ia] + [int(trees[1 - a].chart[i]) for i in ib]
    if a == 1:
        pts, chs = pts[::-1], chs[::-1]
    path = continuous(atlas, np.array(pts))
    if shorten:
        path, chs = shorten_path(atlas, path, chs, step=delta, seed=rng)
    return PathResult(
        True,
        path,
        len(atlas.charts),
        0,
        False,
        _length(atlas, path),
        time.perf_counter() - t0,
        atlas,
        "atlasrrt",
        nodes,
    )
