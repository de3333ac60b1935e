"""The demo's section on variable-structure robots: one trajectory of each VSCR example,
its cable-state transitions and tensions (Rushton 2022, §4.2–4.3, §6.1–6.2).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.2–4.3, §6.1.2, §6.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut.model import example
from taut.viz import plot_trajectory
from taut.viz.interactive import view_trajectory
from taut.wrapping import builtin_trajectory, run_trajectory

if TYPE_CHECKING:
    from taut.viz import Report


def trajectory_section(report: Report) -> None:
    """One trajectory of each VSCR example: lengths, transitions, snapshots, tensions."""
    rows, figures, views = [], [], []
    for name in ["vscr-single-cable", "vscr-four-cable", "vscr-agriculture", "vscr-rehabilitation", "vscr-t-shaped"]:
        robot = example(name)
        traj = next(iter(robot.trajectories))
        t, P = builtin_trajectory(robot, traj, dt=0.02)
        res = run_trajectory(robot, t, P)
        rows.append(
            {
                "robot": name,
                "trajectory": traj,
                "samples": len(t),
                "duration [s]": round(float(t[-1]), 2),
                "wraps": sum(e["kind"] == "wrap" for e in res.transitions),
                "unwraps": sum(e["kind"] == "unwrap" for e in res.transitions),
                "tension feasible": bool(res.feasible.all()),
            }
        )
        figures.append((plot_trajectory(robot, res), f"{name}-trajectory.png", f"{name}: {traj}"))
        if name == "vscr-t-shaped":
            views.append((view_trajectory(robot, res), f"{name}: {traj}, the cables along their wrapped paths"))
    report.add_section(
        "Variable-structure robots: wrapping cables along trajectories",
        text=(
            "Cable states tracked with the cable-state tree and the exact-event form of Alg. 4.4 "
            "(Rushton 2022, §4.2–4.3); waypoint moves with 1 s dwells (§6.2), "
            "Eqs. (4.12)/(4.13) as parametric paths; minimum-sum LP tensions per sample (§6.1.2)."
        ),
        figures=figures,
        table=rows,
        views=views,
    )
