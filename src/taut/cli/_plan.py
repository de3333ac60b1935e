"""``taut plan ROBOT --start POSE --goal POSE``: a wrench-feasible path between two
configurations of a cable-driven hexapod (Bohigas et al. 2013; :mod:`taut.planning`), by
A* over a growing atlas (complete), AtlasRRT (Jaillet & Porta 2013), or both in turn.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §4–5. (docs/references.bib: bohigas2013)
.. [2] L. Jaillet, J. M. Porta, "Path planning under kinematic constraints by rapidly
   exploring manifolds", IEEE Transactions on Robotics 29(1), 2013.
   (docs/references.bib: jaillet2013)
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure, written
from taut.errors import TautError

if TYPE_CHECKING:
    import numpy as np

    from taut.model import Robot
    from taut.planning import PathResult, WrenchFeasibleManifold

#: Smallest chart radius: the number of charts grows as radius^-k on a k-dimensional slice,
#: and below this even a 2-D slice needs more charts than a search can visit.
MIN_RADIUS = 1e-3

#: Chart radius of each planner when --radius is not given.
DEFAULT_RADIUS = {"astar": 0.2, "atlasrrt": 0.4}
#: AtlasRRT tree nodes when --max-nodes is not given: alone, and as the first stage of auto.
DEFAULT_NODES = {"atlasrrt": 5000, "auto": 500}
#: Most free coordinates A* searches without an explicit --max-charts: its atlas needs about
#: (extent / radius)^k charts (millions in six dimensions at the default radius, at 0.2 s a
#: chart), so that on more it would only run out of the default budget after an hour.
ASTAR_DIMENSIONS = 4

SUMMARY = "wrench-feasible path between two configurations (cable hexapods)"
ROBOT = True

DESCRIPTION = """Plan a path along which the cables balance every wrench of the ellipsoid
(w - w0)^T E (w - w0) <= 1 with tensions and lengths strictly inside their bounds.
Planners (--planner):
  astar     higher-dimensional continuation + A* (Bohigas et al. 2013, §4): complete, it
            proves that no path exists when it covers the start's component at the
            chart radius (--radius, default 0.2);
  atlasrrt  AtlasRRT (Jaillet & Porta 2013), bidirectional unless --unidirectional: random
            trees grown on an atlas of the same manifold (--radius, default 0.4; --step,
            default radius/4; --seed), fast, but it cannot prove that no path exists;
  auto      (default) AtlasRRT within --max-nodes (default 500), then A* (on more than 4
            free coordinates only with an explicit --max-charts: its atlas would need
            millions of charts).
--max-charts bounds the atlas of either planner (default 20000); A* then answers
"found": false, "no_path": false.
--shorten shortens an AtlasRRT path by random shortcuts on the manifold.
Angles are periodic: a path may cross phi = +-pi or theta = 0, so its last pose is the goal
or the same orientation written with other angles (phi +- 2pi, or phi + pi with -theta).
POSE is x,y,z,phi,theta,sigma (tilt-and-torsion; 35deg, pi/8 accepted) or the name of a
reference pose of the robot (e.g. q1).  The path is checked independently at --subdivide
interpolated points per step (taut.statics._feasibility).  No path is an answer (exit 0):
"found": false, with "no_path": true for a proof (A*), false when a budget ran out.
JSON: {"planner", "method", "found", "path": [[x,y,z,phi,theta,sigma], ...], "charts",
"nodes", "elapsed_s", "min_tension_margin", "expanded", "no_path", "complete", "length", "verified"}."""


def _pose(robot: Robot, text: str, what: str) -> np.ndarray:
    import numpy as np

    ref = robot.reference.poses if robot.reference is not None else {}
    if text in ref:
        return np.asarray(ref[text], float)
    values = A.vector(text, what)
    if values.size != robot.pose_size:
        # a pose of the robot's own size, so that a robot the planner does not handle is refused for that reason
        raise TautError(f"{what}: expected {','.join(robot.pose_names)} or a reference pose name, got {text!r}")
    return values


def _fixed(text: str | None, start: np.ndarray) -> dict[str, float]:
    from taut.planning import POSE_NAMES

    if text is None:
        return {}
    values = A.assignments(text, "--fix")
    if not values:
        raise TautError(f"--fix: expected name=value,... (e.g. x=0,y=0,sigma=35deg), got {text!r}")
    for name in values:
        if name not in POSE_NAMES:
            raise TautError(f"--fix: unknown coordinate {name!r}; expected {', '.join(POSE_NAMES)}")
    return {name: float(start[POSE_NAMES.index(name)]) if v is None else v for name, v in values.items()}


def _ellipsoid(text: str | None) -> np.ndarray:
    import numpy as np

    if text is None:
        return 1e4 * np.eye(6)
    v = A.vector(text, "--wrench-ellipsoid")
    if v.size == 1:
        E = v[0] * np.eye(6)
    elif v.size == 6:
        E = np.diag(v)
    elif v.size == 36:
        E = v.reshape(6, 6)
    else:
        raise TautError("--wrench-ellipsoid: give 1 (E = e·I), 6 (diagonal) or 36 (full E) numbers")
    if not np.allclose(E, E.T) or np.linalg.eigvalsh(E).min() <= 0:
        raise TautError("--wrench-ellipsoid: E must be symmetric positive definite")
    return E


def _run(ns: argparse.Namespace, M: WrenchFeasibleManifold, y0: np.ndarray, y1: np.ndarray) -> tuple[str, PathResult]:
    """The planner's answer: the method that gave it and its result."""
    from taut.cli._progress import progress_bar, wanted
    from taut.planning import plan_path

    charts = {} if ns.max_charts is None else {"max_charts": ns.max_charts}
    if ns.planner in ("atlasrrt", "auto"):
        radius = ns.radius or DEFAULT_RADIUS["atlasrrt"]
        with progress_bar("plan (AtlasRRT nodes)", wanted(ns.json)) as progress:
            res = plan_path(
                M.implicit(),
                y0,
                y1,
                method="atlasrrt",
                radius=radius,
                step=ns.step,
                metric=M.pose_metric,
                seed=ns.seed,
                bidirectional=not ns.unidirectional,
                max_nodes=ns.max_nodes or DEFAULT_NODES[ns.planner],
                shorten=ns.shorten,
                progress=progress,
                **charts,
            )
        # auto on more free coordinates than A* covers: the AtlasRRT answer (not a proof)
        if res.found or ns.planner == "atlasrrt" or (M.dim > ASTAR_DIMENSIONS and ns.max_charts is None):
            return "atlasrrt", res
    with progress_bar("plan (charts expanded)", wanted(ns.json)) as progress:
        res = plan_path(
            M.implicit(),
            y0,
            y1,
            method="astar",
            radius=ns.radius or DEFAULT_RADIUS["astar"],
            metric=M.pose_metric,
            progress=progress,
            **charts,
        )
    return "astar", res


def run(ns: argparse.Namespace) -> int:
    import time

    import numpy as np

    from taut.planning import MAX_PATH_POSES, POSE_NAMES, WrenchFeasibleManifold, verify_path

    out = A.output_file(ns.out, "--out")
    plot = A.plot_file(ns.plot)
    if ns.subdivide >= MAX_PATH_POSES:
        raise TautError(
            f"--subdivide {ns.subdivide} checks more than {MAX_PATH_POSES:,} poses on any path (of one step or more); "
            "give a smaller --subdivide"
        )
    if ns.step is not None:
        radius = ns.radius or DEFAULT_RADIUS["atlasrrt"]
        if ns.step > radius:
            raise TautError(f"--step {ns.step:g} exceeds the chart radius {radius:g}")
    if ns.planner == "astar" and (ns.shorten or ns.unidirectional or ns.step is not None or ns.max_nodes):
        raise TautError("--shorten, --unidirectional, --step and --max-nodes apply to --planner atlasrrt or auto")
    robot = A.load(ns.robot, ns.cable_set)
    start, goal = _pose(robot, ns.start, "--start"), _pose(robot, ns.goal, "--goal")
    fixed = _fixed(ns.fix, start)
    free = [n for n in POSE_NAMES if n not in fixed]
    if plot is not None and len(free) < 2:
        raise TautError("--plot draws a map of two free coordinates: fix at most four")
    M = WrenchFeasibleManifold.from_robot(robot, E=_ellipsoid(ns.wrench_ellipsoid), fixed=fixed)
    if ns.planner == "astar" and M.dim > ASTAR_DIMENSIONS and ns.max_charts is None:
        raise TautError(
            f"A* on {M.dim} free coordinates needs about (extent/radius)^{M.dim} charts, far beyond its default "
            f"budget: fix some with --fix (at most {ASTAR_DIMENSIONS} free), use --planner atlasrrt, "
            "or give --max-charts to search within a budget"
        )
    y0, y1 = M.lift(start), M.lift(goal)
    t0 = time.perf_counter()
    method, res = _run(ns, M, y0, y1)
    elapsed = time.perf_counter() - t0
    # the path as poses (not the manifold's points), the count of the planner that ran (None
    # for the other's), and the time of both planners of auto
    data = (
        {"robot": robot.name, "planner": ns.planner}
        | res.as_dict()
        | {
            "path": [],
            "nodes": res.nodes if method == "atlasrrt" else None,
            "expanded": res.expanded if method == "astar" else None,
            "elapsed_s": elapsed,
            "min_tension_margin": None,
            "verified": None,
            "fixed": fixed,
        }
    )
    table = None  # the path's poses and extreme tensions, one row per pose
    if res.found:
        poses = M.align(M.pose(res.path), start)  # begins at --start as written
        lo, hi = M.tension_range(res.path)
        margin = np.minimum(lo - M.f_min, M.f_max - hi).min()
        check = verify_path(robot, poses, E=M.E, subdivide=ns.subdivide)
        data.update(path=poses.tolist(), min_tension_margin=float(margin), verified=check.all_feasible)
        table = np.hstack([poses, lo, hi])

    def human(d: dict) -> None:
        con = console()
        if d["found"]:
            con.print(
                f"[bold]{markup(robot.name)}[/]: path of {len(d['path'])} poses, length {d['length']:.4g} "
                f"(pose coordinates), {d['method']}, {d['charts']} charts, {d['elapsed_s']:.3g} s"
            )
            con.print(
                f"min tension margin {d['min_tension_margin']:.4g}; independent check: "
                f"{'feasible' if d['verified'] else 'NOT feasible'} at every interpolated pose"
            )
        else:
            if d["no_path"]:
                why = "proved: the start's component, covered at the chart radius, does not reach the goal"
            elif d["method"] == "atlasrrt":
                why = f"not a proof: AtlasRRT's budget of {d['nodes']} nodes ran out"
            else:
                why = "not a proof: the chart limit was reached"
            con.print(
                f"[bold]{markup(robot.name)}[/]: no path ({why}; {d['charts']} charts explored, {d['elapsed_s']:.3g} s)"
            )

    if out is not None and table is not None:
        head = ",".join(
            [*robot.pose_names, *(f"f_min_{i + 1}" for i in range(6)), *(f"f_max_{i + 1}" for i in range(6))]
        )
        with written(out, "--out") as tmp:
            np.savetxt(tmp, table, delimiter=",", header=head, comments="")
        data["out"] = str(out)
    if plot is not None:
        from taut.planning import slice_map
        from taut.viz import plot_plan

        centres = M.pose(res.atlas.centres)
        grid = slice_map(M, centres[0], axes=(free[0], free[1]), span=centres)
        save_figure(plot_plan(M, res, grid), plot, data)
    emit(data, ns.json, human)
    return 0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--start", required=True, help="start pose x,y,z,phi,theta,sigma or reference pose name")
    parser.add_argument("--goal", required=True, help="goal pose, same syntax")
    parser.add_argument(
        "--fix", help="slice: fixed pose coordinates, e.g. x=0,y=0,sigma=35deg (a name alone takes the start's value)"
    )
    parser.add_argument(
        "--wrench-ellipsoid", help="E of (w-w0)^T E (w-w0) <= 1: e (E = e*I), 6 diagonal or 36 entries (default 1e4)"
    )
    parser.add_argument(
        "--planner",
        choices=("auto", "atlasrrt", "astar"),
        default="auto",
        help="auto (default): AtlasRRT, then A* if it found nothing; atlasrrt; astar (complete)",
    )
    parser.add_argument(
        "--radius",
        type=A.real(least=MIN_RADIUS),
        help="chart radius; for astar the resolution of a 'no path' answer (default 0.2 astar, 0.4 atlasrrt); "
        f"at least {MIN_RADIUS:g}, below which the search could not cover the space",
    )
    parser.add_argument("--step", type=A.real(above=0), help="AtlasRRT step in the tangent spaces (default radius/4)")
    parser.add_argument("--seed", type=A.seed, default=0, help=f"AtlasRRT random seed, 0 to {A.MAX_SEED} (default 0)")
    parser.add_argument("--max-nodes", type=A.count(2), help="AtlasRRT tree nodes (default 5000 atlasrrt, 500 auto)")
    parser.add_argument("--unidirectional", action="store_true", help="AtlasRRT: one tree from the start")
    parser.add_argument("--shorten", action="store_true", help="AtlasRRT: shorten the path on the manifold")
    parser.add_argument(
        "--max-charts",
        type=A.count(2),
        help=f"stop the search after this many charts (default 20000; A* needs it on more than {ASTAR_DIMENSIONS} free coordinates)",
    )
    parser.add_argument(
        "--subdivide",
        type=A.count(),
        default=10,
        help="interpolated poses per path step for the independent check",
    )
    parser.add_argument("--out", metavar="FILE.csv", help="path poses and extreme tensions")
    parser.add_argument("--plot", metavar="FILE.png", help="extreme tensions along the path (Fig. 6)")
