"""One entry point for wrench-feasible path planning, chosen by ``method``: on a manifold,
the complete A* search over a growing atlas (:mod:`taut.planning._search`, Bohigas et al.
2013, §4) or AtlasRRT (:mod:`taut.planning._atlasrrt`, Jaillet & Porta 2013); in a robot's
own pose space, RRT-Connect or A* over a lattice (:mod:`taut.planning._posespace`).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §4. (docs/references.bib: bohigas2013)
.. [2] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
   exploring manifolds", IEEE Transactions on Robotics 29(1), 2013, Algs. 1–4.
   (docs/references.bib: jaillet2013)
.. [3] J. J. Kuffner, S. M. LaValle, "RRT-Connect: an efficient approach to single-query path
   planning", IEEE International Conference on Robotics and Automation, 2000.
   (docs/references.bib: kuffner2000)
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count, as_number, as_rng
from taut.errors import PoseError, TautError
from taut.model import Robot
from taut.planning._atlasrrt import MAX_NODES, atlas_rrt
from taut.planning._continuation import MAX_CHARTS, ImplicitManifold
from taut.planning._posespace import POSE_METHODS, grid_search, pose_space, rrt_connect
from taut.planning._search import PathResult, astar

__all__ = ["METHODS", "RADIUS", "plan_path"]

#: The planners of :func:`plan_path`: on a manifold (``astar``, ``atlasrrt``), in a robot's
#: pose space (``rrtconnect``, ``grid``).
METHODS = ("astar", "atlasrrt", *POSE_METHODS)

#: Chart radius of each planner when none is given: A* needs charts small enough to resolve
#: the narrow passages it must prove closed; AtlasRRT walks steps of a quarter radius.
RADIUS = {"astar": 0.2, "atlasrrt": 0.4}


def plan_path(
    space: ImplicitManifold | Robot,
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
    shorten: bool | None = None,
    progress: Callable[[int, int | None], None] | None = None,
    resolution: float | None = None,
    bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    E: npt.ArrayLike | None = None,
    interference: bool = False,
    obstacles: bool = False,
    lengths: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> PathResult:
    """A path between two points of a manifold, by A* over a growing atlas or by AtlasRRT,
    or between two poses of a robot in its pose space, by RRT-Connect or A* over a lattice.

    Parameters
    ----------
    space : ImplicitManifold or Robot
        For ``astar`` and ``atlasrrt`` a manifold, e.g. :meth:`WrenchFeasibleManifold.implicit`;
        for ``rrtconnect`` and ``grid`` a robot whose valid poses fill an open set of its
        pose space (at least as many cables as wrench components, no jointed bodies): a
        redundant or fully constrained robot, a point mass, a planar platform, in any
        orientation convention.
    start, goal : array_like, shape (n,)
        Points of the manifold (:meth:`WrenchFeasibleManifold.lift` of two poses), or poses
        of the robot, valid (``verify_path`` of one pose).
    method : {"astar", "atlasrrt", "rrtconnect", "grid"}, optional
        ``"astar"`` (:data:`METHODS`): A* over the charts of a growing atlas, complete —
        when every chart of the start's component is closed without reaching the goal, no path exists
        at the resolution ``radius`` (``no_path``).  ``"atlasrrt"``: rapidly exploring
        trees grown on an atlas, randomised, deterministic for a ``seed``; it cannot prove
        that no path exists.  ``"rrtconnect"``: RRT-Connect in the pose space with the
        validity test of :func:`verify_path` made stricter by a margin, the shortest of a few
        paths after shortening as OMPL's path simplifier does, with partial shortcuts
        (without the margin when it leaves no path: ``max_nodes`` each); randomised, deterministic for a ``seed``, it cannot prove that no path exists.  ``"grid"``: A*
        over a lattice of the pose space at ``spacing``; ``no_path`` proves that no chain of
        valid lattice neighbours joins the start to the goal (:mod:`taut.planning._posespace`
        states exactly what), for pose spaces of two or three coordinates (point masses,
        planar platforms), where a lattice fits in a budget.
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
        Tree-node budget of AtlasRRT and RRT-Connect, lattice-point budget of the grid
        (default :data:`MAX_NODES`).
    spacing : float, optional
        A*: the largest step of the refined path (default ``radius / 4``).  Grid: the lattice
        spacing in pose coordinates (default: the finest within ``max_nodes``).
    step : float, optional
        AtlasRRT: the step ``δ`` of the trees (default ``radius / 4``).  RRT-Connect: the
        longest extension (default a twentieth of the box's diagonal).
    seed : int or numpy.random.Generator, optional
        AtlasRRT, RRT-Connect, shortcuts: the random samples.
    bidirectional : bool, optional
        AtlasRRT: grow a tree from the goal too (RRT-Connect).
    goal_bias : float, optional
        AtlasRRT, one tree: the probability of extending toward the goal.
    time_limit : float, optional
        AtlasRRT, RRT-Connect, grid: seconds before giving up (an answer that is then
        ``found=False`` proves nothing).
    shorten : bool, optional
        Shorten the path by random shortcuts (AtlasRRT: on the manifold, :func:`shorten_path`;
        default False); in pose space straight, by segments that pass the validity test
        (default True).
    progress : callable, optional
        ``progress(done, None)`` as the search goes (charts expanded by A*, tree nodes of
        AtlasRRT and RRT-Connect, lattice points checked and closed by the grid),
        ``progress(done, done)`` at the end.
    resolution : float, optional
        Pose space: the largest gap between the checked poses of a segment, in pose
        coordinates (default an eighth of ``step`` or of the lattice spacing, at most 0.01).
    bounds : (lower, upper), optional
        Pose space: the box of the position coordinates, each ``(d,)`` [m] (default: the
        bounding box of the exits, start and goal, widened to a cube about its centre);
        angles range over the full circle.
    E : array_like, shape (m, m), optional
        Pose space: the wrench ellipsoid of the validity test (default ``10⁴ I``,
        :func:`verify_path`).
    interference, obstacles : bool, optional
        Pose space: also no interference of the capsule model (cable–cable, cable–platform),
        no cable in a disallowed region (planar robots); the robot's obstacles are always
        checked (:func:`pose_validity`).
    lengths : (lmin, lmax), optional
        Pose space: also cable lengths strictly inside these bounds [m].

    Returns
    -------
    PathResult

    Raises
    ------
    TautError
        An unknown method, a method for the other kind of ``space``, a robot the pose-space
        planners do not take, start or goal off the manifold or not valid, or a bad option.

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

    In the pose space of the planar 4-cable robot: from its centre to a pose turned by 0.3 rad,
    by RRT-Connect; and to the platform turned upside down, which the lattice proves
    unreachable at its resolution (no valid orientation between 1.2 and 2 rad):

    >>> from taut.model import example
    >>> from taut.planning import verify_path
    >>> robot = example("planar-4cable")
    >>> res = plan_path(robot, [0, 0, 0], [0.2, 0.1, 0.3], method="rrtconnect")
    >>> res.found, res.path[-1].tolist(), verify_path(robot, res.path, subdivide=20).all_feasible
    (True, [0.2, 0.1, 0.3], True)
    >>> res = plan_path(robot, [0, 0, 0], [0, 0, 3.0], method="grid", max_nodes=4000)
    >>> res.found, res.no_path
    (False, True)
    """
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown planning method {method!r}; expected one of {', '.join(METHODS)}")
    if method in POSE_METHODS:
        if not isinstance(space, Robot):
            raise TautError(
                f"method {method!r} plans in a robot's pose space: give a Robot, not {type(space).__name__}"
            )
    elif isinstance(space, Robot):
        raise TautError(
            f"method {method!r} plans on a manifold: give WrenchFeasibleManifold.from_robot(robot).implicit() "
            "(a rigid 6-cable tilt-and-torsion robot), or use method 'rrtconnect' or 'grid' on the robot"
        )
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
    if isinstance(space, Robot):
        k = space.pose_size
        start = as_array(start, "the start pose", shape=(k,), error=PoseError)
        goal = as_array(goal, "the goal pose", shape=(k,), error=PoseError)
        if resolution is not None:
            resolution = as_number(resolution, "resolution", positive=True)
        ps = pose_space(
            space, start, goal, bounds=bounds, E=E, interference=interference, obstacles=obstacles, lengths=lengths
        )
        if method == "rrtconnect":
            return rrt_connect(
                ps,
                start,
                goal,
                step=step,
                resolution=resolution,
                rng=as_rng(seed),
                max_nodes=max_nodes,
                time_limit=time_limit,
                shorten=True if shorten is None else bool(shorten),
                progress=progress,
            )
        return grid_search(
            ps,
            start,
            goal,
            spacing=spacing,
            resolution=resolution,
            max_nodes=max_nodes,
            shorten=True if shorten is None else bool(shorten),
            rng=as_rng(seed),
            time_limit=time_limit,
            progress=progress,
        )
    r = RADIUS[method] if radius is None else as_number(radius, "radius", positive=True)
    start = as_array(start, "the start point", shape=(None,))
    goal = as_array(goal, "the goal point", shape=start.shape)
    if method == "astar":
        return astar(
            space,
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
        space,
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
        shorten=bool(shorten),
        progress=progress,
    )
