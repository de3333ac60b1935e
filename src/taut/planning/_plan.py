"""One entry point for wrench-feasible path planning: the complete A* search over a growing
atlas (:mod:`taut.planning._search`, Bohigas et al. 2013, §4) or AtlasRRT
(:mod:`taut.planning._atlasrrt`, Jaillet & Porta 2013), chosen by ``method``.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
.. [2] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
   exploring manifolds", IEEE Transactions on Robotics 29(1), 2013, Algs. 1–4.
   (docs/references.bib: jaillet2013)
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count, as_number, as_rng
from taut.errors import TautError
from taut.planning._atlasrrt import MAX_NODES, atlas_rrt
from taut.planning._continuation import MAX_CHARTS, ImplicitManifold
from taut.planning._search import PathResult, astar

__all__ = ["METHODS", "RADIUS", "plan_path"]

#: The planners of :func:`plan_path`.
METHODS = ("astar", "atlasrrt")

#: Chart radius of each planner when none is given: A* needs charts small enough to resolve
#: the narrow passages it must prove closed; AtlasRRT walks steps of a quarter radius.
RADIUS = {"astar": 0.2, "atlasrrt": 0.4}


def plan_path(
    manifold: ImplicitManifold,
    start: npt.ArrayLike,
    goal: npt.ArrayLike,
    *,
    method: str = "astar",
    radius: float | None = None,
    epsilon: float = 0.1,
    metric: np.ndarray | None = None,
    max_charts: int = MAX_CHARTS,
    max_nodes: int = MAX_NODES,
    spacing: float | None = None,
    step: float | None = None,
    seed: int | np.random.Generator = 0,
    bidirectional: bool = True,
    goal_bias: float = 0.1,
    time_limit: float | None = None,
    shorten: bool = False,
    progress: Callable[[int, int | None], None] | None = None,
) -> PathResult:
    """A path on a manifold between two of its points, by A* over a growing atlas or by
    AtlasRRT.

    Parameters
    ----------
    manifold : ImplicitManifold
        E.g. :meth:`WrenchFeasibleManifold.implicit`.
    start, goal : array_like, shape (n,)
        Points of the manifold (:meth:`WrenchFeasibleManifold.lift` of two poses).
    method : {"astar", "atlasrrt"}, optional
        ``"astar"`` (:data:`METHODS`): A* over the charts of a growing atlas, complete —
        when every chart of the start's component is closed without reaching the goal, no path exists
        at the resolution ``radius`` (``no_path``).  ``"atlasrrt"``: rapidly exploring
        trees grown on an atlas, randomised, deterministic for a ``seed``; it cannot prove
        that no path exists.
    radius : float, optional
        Chart radius (default :data:`RADIUS` of the method).
    epsilon : float, optional
        Validity of a chart: distance between a tangent point and its projection, and
        tangent-space change (:class:`Atlas`).
    metric : array_like of int, optional
        The coordinates in which lengths are measured (e.g.
        :attr:`WrenchFeasibleManifold.pose_metric`; default all).
    max_charts : int, optional
        Chart budget (default :data:`MAX_CHARTS`).
    max_nodes : int, optional
        AtlasRRT's tree-node budget (default :data:`MAX_NODES`).
    spacing : float, optional
        A*: the largest step of the refined path (default ``radius / 4``).
    step : float, optional
        AtlasRRT: the step ``δ`` of the trees (default ``radius / 4``).
    seed : int or numpy.random.Generator, optional
        AtlasRRT: the random samples.
    bidirectional : bool, optional
        AtlasRRT: grow a tree from the goal too (RRT-Connect).
    goal_bias : float, optional
        AtlasRRT, one tree: the probability of extending toward the goal.
    time_limit : float, optional
        AtlasRRT: seconds before giving up.
    shorten : bool, optional
        AtlasRRT: shorten the path by random shortcuts (:func:`shorten_path`).
    progress : callable, optional
        ``progress(done, None)`` as the search goes (charts expanded by A*, tree nodes of
        AtlasRRT), ``progress(done, done)`` at the end.

    Returns
    -------
    PathResult

    Raises
    ------
    TautError
        An unknown method, start or goal off the manifold, or a bad option.

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
    A quarter of a great circle of the unit sphere (length π/2 ≈ 1.571):

    >>> import numpy as np
    >>> from taut.planning import ImplicitManifold, plan_path
    >>> sphere = ImplicitManifold(lambda x: np.array([x @ x - 1]), lambda x: 2 * x[None, :], 2)
    >>> a, b = [1.0, 0, 0], [0, 1.0, 0]
    >>> [round(plan_path(sphere, a, b, method=m, radius=0.3).length, 3) for m in ("astar", "atlasrrt")]
    [1.859, 1.571]
    """
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown planning method {method!r}; expected one of {', '.join(METHODS)}")
    r = RADIUS[method] if radius is None else as_number(radius, "radius", positive=True)
    start = as_array(start, "the start point", shape=(None,))
    goal = as_array(goal, "the goal point", shape=start.shape)
    max_charts = as_count(max_charts, "max_charts", minimum=2)
    max_nodes = as_count(max_nodes, "max_nodes", minimum=2)
    if spacing is not None:
        spacing = as_number(spacing, "spacing", positive=True)
    if step is not None:
        step = as_number(step, "step", positive=True)
    if time_limit is not None:
        time_limit = as_number(time_limit, "time_limit", positive=True)
    goal_bias = as_number(goal_bias, "goal_bias")
    if not 0.0 <= goal_bias <= 1.0:
        raise TautError(f"goal_bias: expected a probability in [0, 1], got {goal_bias}")
    if method == "astar":
        return astar(
            manifold,
            start,
            goal,
            radius=r,
            epsilon=epsilon,
            metric=metric,
            max_charts=max_charts,
            spacing=spacing,
            progress=progress,
        )
    return atlas_rrt(
        manifold,
        start,
        goal,
        radius=r,
        step=step,
        epsilon=epsilon,
        metric=metric,
        seed=as_rng(seed),
        bidirectional=bidirectional,
        goal_bias=goal_bias,
        max_nodes=max_nodes,
        max_charts=max_charts,
        time_limit=time_limit,
        shorten=shorten,
        progress=progress,
    )
