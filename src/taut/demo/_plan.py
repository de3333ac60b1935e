"""The demo's section on wrench-feasible path planning: the Robocrane query q1 → q2 of
experiment 1 (Bohigas et al. 2013, §5, Figs. 5–6).

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5, Figs. 5–6. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

import time
from typing import TYPE_CHECKING, cast

import numpy as np

from taut.errors import TautError
from taut.model import example
from taut.planning import Atlas, PathResult, WrenchFeasibleManifold, plan_path, slice_map, verify_path
from taut.viz import plot_plan
from taut.viz.interactive import view_motion

if TYPE_CHECKING:
    from taut.viz import Report


def plan_section(report: Report, radius: float = 0.2) -> PathResult:
    """The Robocrane query q1 → q2 of experiment 1 (slice p = (0, 0, 2), σ = 35°): A* over
    the atlas, checked by the independent feasibility test, as Figs. 5–6.  Returns the
    :class:`~taut.planning.PathResult`."""
    robot = example("robocrane")
    if robot.reference is None:
        raise TautError(f"{robot.name} has no reference poses q1, q2 to plan between")
    q = {k: np.asarray(v, float) for k, v in robot.reference.poses.items()}
    fixed = dict(x=0.0, y=0.0, z=2.0, sigma=float(q["q1"][5]))
    M = WrenchFeasibleManifold.from_robot(robot, fixed=fixed)
    t0 = time.perf_counter()
    res = plan_path(M.implicit(), M.lift(q["q1"]), M.lift(q["q2"]), radius=radius, metric=M.pose_metric)
    elapsed = time.perf_counter() - t0
    check = verify_path(robot, M.pose(res.path), subdivide=5) if res.found else None
    centres = M.pose(cast(Atlas, res.atlas).centres)  # A* grows an atlas
    fig = plot_plan(M, res, slice_map(M, centres[0], span=centres))
    row = {
        "query": "q1 → q2",
        "found": res.found,
        "charts": res.charts,
        "closed": res.expanded,
        "path length [rad]": round(res.length, 3) if res.found else None,
        "time [s]": round(elapsed, 2),
        "paper [s]": 20.0,
        "independent check": None if check is None else check.all_feasible,
    }
    views = []
    if res.found:
        lo, hi = M.tension_range(res.path)
        poses = M.align(M.pose(res.path), q["q1"])
        shown = view_motion(
            robot,
            np.arange(len(poses), dtype=float),
            poses,
            tensions=(lo + hi) / 2,
            time_label="path step",
            tension_label="f₀ [N]",
            title=f"{robot.name}: the path q1 → q2, cables coloured by f₀ (the centre of their tension range)",
        )
        views.append((shown, "the planned path: slide along it or play it"))
    report.add_section(
        "Wrench-feasible path planning (Robocrane)",
        text=(
            "A path from q1 to q2 on the slice p = (0, 0, 2), σ = 35° of the Robocrane's "
            "wrench-feasible C-space (Bohigas et al. 2013, §5, Figs. 5–6): Henderson's "
            "atlas of Eqs. (1)–(8) expanded in A* order, every interpolated pose of the path "
            "then checked by the general wrench-feasibility test.\n\n"
            "The cable pairing is our reading of §5 (robocrane.yaml, reference.notes)."
        ),
        figures=[
            (
                fig,
                "plan-robocrane-q1-q2",
                "Left: the slice (green feasible, blue tension, red length out of range), the "
                "chart centres and the path. Right: extreme tensions f₀ ± v_ii along the path.",
            )
        ],
        table=[row],
        views=views,
    )
    return res
