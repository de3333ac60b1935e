"""Figures of the geometrico-static problems of under-constrained robots
(Berti 2015, Ch. 2–4).

:func:`plot_equilibria` draws every equilibrium of a DGP solve, one panel each (the
drawings of Fig. 4.7); :func:`plot_tracking` shows a run of tracking forward kinematics
(§4.1.2) — platform position and cable tensions per update, taut-set changes marked;
:func:`dgp_section` adds both, on the robot of Table 4.3, to the ``taut demo`` report.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, Chs. 2–4, Table 4.3, Fig. 4.7, §4.1.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from taut.model import Robot
from taut.viz._style import cable_color, empty_figure
from taut.viz.robot import draw_robot

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.dgp import DGPSolution
    from taut.viz.report import Report

__all__ = ["dgp_section", "plot_equilibria", "plot_tracking"]


def plot_equilibria(
    robot: Robot, solutions: Sequence[DGPSolution], columns: int = 3, fig: Figure | None = None
) -> Figure:
    """One 3-D panel per solution of the spatial ``robot``, ``columns`` panels a row, titled
    with its taut cables and stability; a single note when there is none.  Laid out on the
    empty figure ``fig`` (``None``: a new one; a figure that already has axes raises
    ``ValueError``), which is returned."""
    if columns < 1:
        raise ValueError(f"columns must be at least 1, got {columns}")
    if not solutions:
        fig = empty_figure(fig, "a set of equilibria", (4.0, 2.0))
        ax = fig.add_subplot()
        ax.text(0.5, 0.5, f"{robot.name}: no equilibrium for these lengths", ha="center", va="center")
        ax.axis("off")
        return fig
    cols = min(columns, len(solutions))
    rows = math.ceil(len(solutions) / cols)
    fig = empty_figure(fig, "a set of equilibria", (4.2 * cols, 4.0 * rows))
    for k, s in enumerate(solutions):
        ax = fig.add_subplot(rows, cols, k + 1, projection="3d")
        draw_robot(robot, np.concatenate([s.position, s.orientation]), ax=ax)
        taut = ",".join(str(i + 1) for i in s.taut)
        ax.set_title(f"#{k + 1}: cables {taut} taut, {'stable' if s.stable else 'unstable'}", fontsize=9)
    fig.tight_layout()
    return fig


def plot_tracking(path: Sequence[DGPSolution], fig: Figure | None = None) -> Figure:
    """Position (left) and tensions (right) along a :func:`taut.dgp.track_path` result; a
    dotted line where the set of taut cables changes.  Laid out on the empty figure ``fig``
    (``None``: a new one; a figure that already has axes raises ``ValueError``), which is
    returned."""
    if not path:
        raise ValueError("plot_tracking needs at least one tracked solution, got none")
    k = np.arange(1, len(path) + 1)
    P = np.array([s.position for s in path])
    T = np.array([s.tensions for s in path])
    fig = empty_figure(fig, "a tracking run", (10.0, 3.6))
    ax_p, ax_t = fig.subplots(1, 2)
    for c, name in enumerate("xyz"):
        ax_p.plot(k, P[:, c], label=name)
    for i in range(T.shape[1]):
        ax_t.plot(k, T[:, i], color=cable_color(i), label=f"τ{i + 1}")
    for j in range(1, len(path)):
        if path[j].taut != path[j - 1].taut:
            for ax in (ax_p, ax_t):
                ax.axvline(k[j], color="0.4", ls=":", lw=1)
            ax_t.annotate(
                f"taut {','.join(str(i + 1) for i in path[j].taut)}",
                (k[j], ax_t.get_ylim()[1]),
                fontsize=8,
                va="top",
                ha="left",
            )
    ax_p.set(xlabel="update", ylabel="platform position [m]")
    ax_t.set(xlabel="update", ylabel="tension")
    ax_p.legend(fontsize=8)
    ax_t.legend(fontsize=8)
    fig.tight_layout()
    return fig


def dgp_section(report: Report) -> None:
    """All equilibria of the suspended 3-cable robot (Table 4.3), then tracking from the
    stable one while cable 1 is reeled in and cable 2 paid out until cable 2 goes slack."""
    from taut.dgp import solve_dgp, track_path
    from taut.errors import TautError
    from taut.model import example

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
    )
