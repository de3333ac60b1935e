"""The demo's first sections: the table of built-in robots, and for a standard robot its
drawing, wrench-feasible workspace and tensions along a straight move (Rushton 2022, Ch. 2).

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.errors import TautError
from taut.model import example, example_names

if TYPE_CHECKING:
    from taut.model import Robot
    from taut.viz import Report


def robots_section(report: Report) -> None:
    """Table of the built-in examples."""
    rows = []
    for name in example_names():
        r = example(name)
        rows.append(
            {
                "name": name,
                "dimension": f"{r.dimension}-D",
                "platform": r.platform.kind + (f" + {r.n_joints} joint(s)" if r.n_joints else ""),
                "cables": r.n_cables,
                "obstacles": len(r.obstacles),
                "source": r.source or "taut",
            }
        )
    report.add_section(
        "Built-in robots", text="Every example is addressable by name wherever a robot is expected.", table=rows
    )


def _line_of_poses(robot: Robot, start: npt.ArrayLike, shift: npt.ArrayLike, n: int = 60) -> np.ndarray:
    poses = np.repeat(np.asarray(start, float)[None, :], n, axis=0)
    poses[:, : robot.dimension] += np.linspace(0.0, 1.0, n)[:, None] * np.asarray(shift, float)
    return poses


def standard_model_section(report: Report, name: str, shift: npt.ArrayLike, resolution: int) -> None:
    """Robot drawing, wrench-feasible workspace and tensions along a straight move."""
    from taut.statics import distribute_tensions
    from taut.viz import draw_robot, plot_tensions, plot_workspace
    from taut.workspace import evaluate_workspace

    robot = example(name)
    if robot.reference is None or "home" not in robot.reference.poses:
        raise TautError(f"{name}: the demo draws a robot at its reference pose 'home', and it has none")
    home = np.asarray(robot.reference.poses["home"], float)
    ax = draw_robot(robot, home)
    drawing = ax.figure
    orientation = home[robot.dimension :]
    ws = evaluate_workspace(robot, "wrench-feasible", resolution=resolution, orientation=orientation)
    wfig = plot_workspace(ws, robot).figure
    poses = _line_of_poses(robot, home, shift)
    res = distribute_tensions(robot, poses, method="lp")
    s = np.linspace(0.0, 1.0, len(poses)) * np.linalg.norm(shift)
    tmin, tmax = robot.tension_bounds
    tax = plot_tensions(s, res.tensions, tmin, tmax, res.feasible)
    tax.set_xlabel("distance travelled from home [m]")
    summary = ws.summary()
    text = (
        f"{robot.description} Wrench-feasible workspace (box wrench set around the weight) over a "
        f"{resolution}-point-per-axis grid at the home orientation: {summary['inside']} of "
        f"{summary['poses']} poses ({100 * ws.fraction:.1f} %), {ws.elapsed_s:.3f} s. "
        f"Minimum-sum tensions (LP, HiGHS) along a straight move of {np.linalg.norm(shift):.2f} m: "
        f"feasible at {int(np.count_nonzero(res.feasible))} of {len(poses)} poses."
    )
    report.add_section(
        f"{name}: kinematics, tensions, workspace",
        text=text,
        figures=[
            (drawing, f"{name}-robot.png", f"{name} at its home pose"),
            (wfig, f"{name}-workspace.png", "wrench-feasible workspace"),
            (tax.figure, f"{name}-tensions.png", "tensions along the move"),
        ],
        json=summary,
    )
