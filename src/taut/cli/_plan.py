"""``taut plan ROBOT --start POSE --goal POSE``: a wrench-feasible path between two
configurations of a cable-driven hexapod (Bohigas et al. 2013; :mod:`taut.planning`), by
A* over a growing atlas (complete), AtlasRRT (Jaillet & Porta 2013), or both in turn; of any
other robot whose valid poses fill an open set of its pose space (redundant robots, point
masses, planar platforms, any orientation convention) by RRT-Connect or A* over a lattice.

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
from typing import TYPE_CHECKING, cast

from taut.cli import _args as A
from taut.cli._output import console, emit, markup, save_figure, written
from taut.errors import TautError

if TYPE_CHECKING:
    from pathlib import Path

    import numpy as np

    from taut.model import Robot
    from taut.planning import Atlas, PathResult, WrenchFeasibleManifold

#: Smallest chart radius: the number of charts grows as radius^-k on a k-dimensional slice,
#: and below this even a 2-D slice needs more charts than a search can visit.
MIN_RADIUS = 1e-3

#: Chart radius of each planner when --radius is not given.
DEFAULT_RADIUS = {"astar": 0.2, "atlasrrt": 0.4}
#: AtlasRRT tree nodes when --max-nodes is not given: alone, and as the first stage of auto.
DEFAULT_NODES = {"atlasrrt": 5000, "auto": 500}
#: The planners on the wrench-feasible manifold of a hexapod, and in a robot's pose space.
MANIFOLD_PLANNERS = ("auto", "atlasrrt", "astar")
POSE_PLANNERS = ("rrtconnect", "grid")
#: Most pose coordinates the grid takes (point masses, planar platforms).
GRID_DIMENSIONS = 3
#: Most free coordinates A* searches without an explicit --max-charts: its atlas needs about
#: (extent / radius)^k charts (millions in six dimensions at the default radius, at 0.2 s a
#: chart), so that on more it would only run out of the default budget after an hour.
ASTAR_DIMENSIONS = 4

SUMMARY = "wrench-feasible path between two configurations"
ROBOT = True

DESCRIPTION = """Plan a path along which the cables balance every wrench of the ellipsoid
(w - w0)^T E (w - w0) <= 1 with tensions and lengths strictly inside their bounds.
Which planner applies to what (auto picks it from the robot):
  a rigid 6-cable spatial robot in tilt-torsion angles with a constant platform wrench:
    auto = atlasrrt, then astar (on its wrench-feasible manifold); rrtconnect applies too;
  any other robot with at least as many cables as wrench components and no joints
    (redundant robots such as 8-cable ones, any orientation convention):
    auto = rrtconnect; grid too when the pose has at most 3 coordinates;
  point masses (x,y or x,y,z) and planar platforms (x,y,theta): auto = grid;
  fewer cables than wrench components (under-constrained) or a jointed platform: refused.
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
  rrtconnect  RRT-Connect in the robot's own pose coordinates (Kuffner & LaValle 2000),
            then random and partial shortcuts on the best of a few paths; --step (default
            1/20 of the box diagonal), --seed, --max-nodes (default 20000), --time-limit; no
            path within a budget proves nothing;
  grid      A* over a lattice of the pose space at --spacing (default: the finest of at most
            --max-nodes points); "no_path": true proves that no chain of valid neighbouring
            lattice points (segments checked every --resolution) joins start and goal: a proof
            at that resolution, not of the continuous space.
Pose-space planners (rrtconnect, grid) check segments every --resolution (default 0.01, in
m and rad), angles the short way; --bounds sets the box of the positions; on request
--interference (no cable-cable or cable-platform interference), --obstacles (no cable in a
disallowed region, planar robots), --lengths LMIN,LMAX (cable lengths inside these bounds);
a robot's obstacles are always checked (its cables are straight only clear of them).  Their path
starts at --start and ends at --goal exactly as written.
--shorten shortens an AtlasRRT path by random shortcuts on the manifold.
Angles are periodic: a path may cross phi = +-pi or theta = 0, so its last pose is the goal
or the same orientation written with other angles (phi +- 2pi, or phi + pi with -theta).
POSE is the robot's pose coordinates (x,y,z,phi,theta,sigma for tilt-and-torsion; 35deg,
pi/8 accepted) or the name of a reference pose of the robot (e.g. q1).  The path is checked independently at --subdivide
interpolated points per step (taut.statics._feasibility).  No path is an answer (exit 0):
"found": false, with "no_path": true for a proof (A*, grid), false when a budget ran out.
JSON: {"planner", "method", "found", "path": [[x,y,z,phi,theta,sigma], ...], "charts",
"nodes", "elapsed_s", "min_tension_margin", "expanded", "no_path", "complete", "length", "verified"}."""


def _pose(robot: Robot, text: str, what: str) -> np.ndarray:
    import numpy as np

    ref = robot.reference.poses if robot.reference is not None else {}
    if text in ref:
        return np.asarray(ref[text], float)
    values = A.vector(text, what)
    if values.size != robot.pose_size:
        names = ",".join(robot.pose_names) if robot.orientation != "tilt-torsion" else "x,y,z,phi,theta,sigma"
        raise TautError(f"{what}: expected {names} or a reference pose name, got {text!r}")
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


def _ellipsoid(text: str | None, m: int = 6) -> np.ndarray:
    import numpy as np

    if text is None:
        return 1e4 * np.eye(m)
    v = A.vector(text, "--wrench-ellipsoid")
    if v.size == 1:
        E = v[0] * np.eye(m)
    elif v.size == m:
        E = np.diag(v)
    elif v.size == m * m:
        E = v.reshape(m, m)
    else:
        raise TautError(f"--wrench-ellipsoid: give 1 (E = e·I), {m} (diagonal) or {m * m} (full E) numbers")
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


def _on_manifold(robot: Robot) -> bool:
    """Whether the manifold planners take ``robot`` (a rigid 6-cable tilt-and-torsion robot
    with a constant platform wrench)."""
    from taut.planning import WrenchFeasibleManifold

    try:
        WrenchFeasibleManifold.from_robot(robot)
    except TautError:
        return False
    return True


def _pair(text: str | None, what: str, size: int | None = None) -> tuple[np.ndarray, np.ndarray] | None:
    """``LO,HI`` (or ``size`` lows then ``size`` highs) as two arrays."""
    if text is None:
        return None
    v = A.vector(text, what)
    n = 1 if size is None else size
    if v.size != 2 * n:
        raise TautError(f"{what}: expected {2 * n} numbers (lower then upper), got {v.size}")
    return v[:n], v[n:]


def _run_pose_space(
    ns: argparse.Namespace, robot: Robot, planner: str, start: np.ndarray, goal: np.ndarray, out: Path | None
) -> int:
    """``--planner rrtconnect`` or ``grid``: in the robot's own pose space."""
    import time

    import numpy as np

    from taut.cli._progress import progress_bar, wanted
    from taut.planning import plan_path, verify_path

    bad = [o for o in ("fix", "radius", "max_charts", "plot") if getattr(ns, o) is not None]
    bad += [o for o in ("unidirectional", "shorten") if getattr(ns, o)]
    if bad:
        raise TautError(f"--{bad[0].replace('_', '-')} applies to the manifold planners (auto, atlasrrt, astar)")
    if planner == "rrtconnect" and ns.spacing is not None:
        raise TautError("--spacing applies to --planner grid")
    if planner == "grid" and ns.step is not None:
        raise TautError("--step applies to --planner rrtconnect or atlasrrt")
    E = _ellipsoid(ns.wrench_ellipsoid, robot.wrench_dim)
    checks = {
        "E": E,
        "interference": ns.interference,
        "obstacles": ns.obstacles,
        "lengths": _pair(ns.lengths, "--lengths"),
    }
    t0 = time.perf_counter()
    with progress_bar(f"plan ({planner})", wanted(ns.json)) as progress:
        res = plan_path(
            robot,
            start,
            goal,
            method=planner,
            step=ns.step,
            spacing=ns.spacing,
            resolution=ns.resolution,
            seed=ns.seed,
            bounds=_pair(ns.bounds, "--bounds", robot.dimension),
            time_limit=ns.time_limit,
            progress=progress,
            **({} if ns.max_nodes is None else {"max_nodes": ns.max_nodes}),
            **checks,
        )
    elapsed = time.perf_counter() - t0
    data = (
        {"robot": robot.name, "planner": ns.planner}
        | res.as_dict()
        | {
            "nodes": res.nodes if planner == "rrtconnect" else None,
            "expanded": res.expanded if planner == "grid" else None,
            "elapsed_s": elapsed,
            "min_tension_margin": None,
            "verified": None,
            "fixed": {},
        }
    )
    if res.found:
        check = verify_path(robot, res.path, subdivide=ns.subdivide, **checks)
        data["verified"] = check.all_feasible
        if out is not None:
            head = ",".join([*robot.pose_names, *(f"length_{i + 1}" for i in range(robot.n_cables))])
            ends = verify_path(robot, res.path, subdivide=1, **checks)
            with written(out, "--out") as tmp:
                np.savetxt(tmp, np.hstack([res.path, ends.lengths]), delimiter=",", header=head, comments="")
            data["out"] = str(out)

    def human(d: dict) -> None:
        con = console()
        if d["found"]:
            con.print(
                f"[bold]{markup(robot.name)}[/]: path of {len(d['path'])} poses, length {d['length']:.4g} "
                f"(pose coordinates), {d['method']}, {d['elapsed_s']:.3g} s"
            )
            con.print(
                f"independent check: {'feasible' if d['verified'] else 'NOT feasible'} at every interpolated pose"
            )
        elif d["no_path"]:
            con.print(
                f"[bold]{markup(robot.name)}[/]: no path (proved at the lattice's resolution: no chain of valid "
                f"neighbouring lattice points joins start and goal; {d['expanded']} points closed, {d['elapsed_s']:.3g} s)"
            )
        else:
            con.print(
                f"[bold]{markup(robot.name)}[/]: no path found (not a proof: the budget ran out; "
                f"{d['nodes'] or d['expanded']} {'nodes' if d['nodes'] else 'points'}, {d['elapsed_s']:.3g} s)"
            )

    emit(data, ns.json, human)
    return 0


def run(ns: argparse.Namespace) -> int:
    import time

    import numpy as np

    from taut.planning import MAX_PATH_POSES, POSE_NAMES, WrenchFeasibleManifold, verify_path

    out = A.output_file(ns.out, "--out")
    plot = A.plot_file(ns.plot) if ns.planner not in POSE_PLANNERS else None
    if ns.subdivide >= MAX_PATH_POSES:
        raise TautError(
            f"--subdivide {ns.subdivide} checks more than {MAX_PATH_POSES:,} poses on any path (of one step or more); "
            "give a smaller --subdivide"
        )
    robot = A.load(ns.robot, ns.cable_set)
    A.straight_cables(robot, "the planner")
    planner = ns.planner
    if planner == "auto" and not _on_manifold(robot):
        planner = "grid" if robot.pose_size <= GRID_DIMENSIONS else "rrtconnect"
    if planner == "grid" and robot.pose_size > GRID_DIMENSIONS:
        raise TautError(
            f"{robot.name}: --planner grid takes pose spaces of at most {GRID_DIMENSIONS} coordinates "
            f"(point masses, planar platforms), this robot's has {robot.pose_size}: use --planner rrtconnect"
        )
    if planner in POSE_PLANNERS:
        start, goal = _pose(robot, ns.start, "--start"), _pose(robot, ns.goal, "--goal")
        return _run_pose_space(ns, robot, planner, start, goal, out)
    if ns.step is not None:
        radius = ns.radius or DEFAULT_RADIUS["atlasrrt"]
        if ns.step > radius:
            raise TautError(f"--step {ns.step:g} exceeds the chart radius {radius:g}")
    if ns.planner == "astar" and (ns.shorten or ns.unidirectional or ns.step is not None or ns.max_nodes):
        raise TautError("--shorten, --unidirectional, --step and --max-nodes apply to --planner atlasrrt or auto")
    start, goal = _pose(robot, ns.start, "--start"), _pose(robot, ns.goal, "--goal")
    used = [o for o in ("spacing", "resolution", "bounds", "lengths", "time_limit") if getattr(ns, o) is not None]
    used += [o for o in ("interference", "obstacles") if getattr(ns, o)]
    if used:
        raise TautError(
            f"--{used[0].replace('_', '-')} applies to --planner rrtconnect or grid (the pose-space planners)"
        )
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

        centres = M.pose(cast("Atlas", res.atlas).centres)  # the manifold planners grow an atlas
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
        choices=(*MANIFOLD_PLANNERS, *POSE_PLANNERS),
        default="auto",
        help="auto (default): from the robot (hexapod: AtlasRRT, then A*; point mass or planar: grid; "
        "else rrtconnect); atlasrrt; astar (complete); rrtconnect; grid (proves no path at its resolution)",
    )
    parser.add_argument(
        "--radius",
        type=A.real(least=MIN_RADIUS),
        help="chart radius; for astar the resolution of a 'no path' answer (default 0.2 astar, 0.4 atlasrrt); "
        f"at least {MIN_RADIUS:g}, below which the search could not cover the space",
    )
    parser.add_argument("--step", type=A.real(above=0), help="AtlasRRT step in the tangent spaces (default radius/4)")
    parser.add_argument(
        "--seed", type=A.seed, default=0, help=f"AtlasRRT / RRT-Connect random seed, 0 to {A.MAX_SEED} (default 0)"
    )
    parser.add_argument(
        "--max-nodes",
        type=A.count(2),
        help="tree nodes of AtlasRRT (default 5000 atlasrrt, 500 auto) and RRT-Connect (default 20000), "
        "lattice points of the grid (default 20000)",
    )
    parser.add_argument("--spacing", type=A.real(above=0), help="grid: lattice spacing (m and rad)")
    parser.add_argument(
        "--resolution", type=A.real(above=0), help="rrtconnect, grid: gap between checked poses (default 0.01)"
    )
    parser.add_argument("--time-limit", type=A.real(above=0), help="rrtconnect, grid: seconds before giving up")
    parser.add_argument("--bounds", help="rrtconnect, grid: box of the positions, lower then upper (e.g. -1,-1,1,1)")
    parser.add_argument("--interference", action="store_true", help="rrtconnect, grid: no cable interference")
    parser.add_argument(
        "--obstacles",
        action="store_true",
        help="rrtconnect, grid: no cable in a disallowed region (obstacles are always checked)",
    )
    parser.add_argument("--lengths", metavar="LMIN,LMAX", help="rrtconnect, grid: cable lengths inside these bounds")
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
