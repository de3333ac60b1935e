"""The demo's section on under-constrained robots: every equilibrium of the suspended 3-cable
robot for the lengths of Table 4.3, then tracking forward kinematics from the stable one
(Berti 2015, §4.1.2, §4.2.1).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.2.2, §4.1.2, §4.2.1, Table 4.3. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.dgp import solve_dgp, track_path
from taut.errors import TautError
from taut.model import example
from taut.viz import plot_equilibria, plot_tracking
from taut.viz.interactive import view_equilibria

if TYPE_CHECKING:
    from taut.viz import Report


def dgp_section(report: Report) -> None:
    """All equilibria of the suspended 3-cable robot (Table 4.3), then tracking from the
    stable one while cable 1 is reeled in and cable 2 paid out until cable 2 goes slack."""
    robot = example("suspended-3cable")
    if robot.reference is None or robot.reference.lengths is None:
        raise TautError(f"{robot.name} has no reference cable lengths to solve for")
    lengths = np.array(robot.reference.lengths)
    res = solve_dgp(robot)
    rows: list[dict[str, object]] = []
    for k, s in enumerate(res.solutions):
        row = {"#": k + 1, "taut": ",".join(str(i + 1) for i in s.taut)}
        row.update(
            {n: round(float(v), 4) for n, v in zip(robot.pose_names, np.concatenate([s.position, s.orientation]))}
        )
        row.update({f"τ{i + 1}": round(float(t), 4) for i, t in enumerate(s.tensions)})
        row["stable"] = bool(s.stable)
        rows.append(row)
    stable = [s for s in res.solutions if s.stable]
    figures = [
        (plot_equilibria(robot, res.solutions), "dgp-equilibria.png", "every equilibrium for the lengths of Table 4.3")
    ]
    summary = {
        "robot": robot.name,
        "solutions": len(res.solutions),
        "stable": len(stable),
        "subproblems": res.subproblems,
        "undecided_boxes": res.undecided,
        "elapsed_s": round(res.elapsed_s, 2),
    }
    if stable:
        sequence = lengths + np.linspace(0.0, 3.0, 301)[1:, None] * np.array([-1.0, 1.0, 0.0])
        path = track_path(robot, stable[0], sequence)
        figures.append((plot_tracking(path), "dgp-tracking.png", "tracking: cable 1 in, cable 2 out by 3 m"))
        summary["tracking"] = {
            "updates": len(path),
            "taut_sets": sorted({",".join(str(i + 1) for i in s.taut) for s in path}),
        }
    report.add_section(
        "Under-constrained robots: every equilibrium, then tracking",
        text=(
            "All equilibria of the suspended 3-cable robot for the cable lengths of Table 4.3 "
            "(Berti 2015, §4.2.1): certified branch-and-prune over every set of taut cables, "
            "stability by the reduced Hessian (§3.2.2).  Then tracking forward kinematics (§4.1.2) from "
            "the stable equilibrium: one Newton step certified by the Krawczyk operator per update; "
            "when cable 2's tension reaches zero the robot hangs from cables 1 and 3."
        ),
        figures=figures,
        table=rows,
        json=summary,
        views=[(view_equilibria(robot, res.solutions), "every equilibrium, one at a time: choose it in the selector")],
    )
