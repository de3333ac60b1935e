"""The demo's section on self-collision and singularities: simulation c of
``adjustable-8cable`` (Lieskovský 2020, §4.2.2).

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.2.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.collision import check_poses, trajectory_poses
from taut.model import example
from taut.viz import plot_check
from taut.viz.interactive import view_motion

if TYPE_CHECKING:
    from taut.viz import Report


def check_section(report: Report) -> None:
    """Demo section: simulation c of ``adjustable-8cable`` (rotation about x at s23 = 2)."""
    robot = example("adjustable-8cable")
    poses = trajectory_poses(robot, "sim-c")
    res = check_poses(robot, poses)
    first = res.first(res.collides)
    pairs = ", ".join(f"{i + 1} & {j + 1}" for i, j in res.proximity.collisions(first)) if first is not None else "none"
    text = (
        "Simulation c of Lieskovský 2020, §4.2.2: the adjustable platform (two bodies joined by a "
        "prismatic joint, 8 cables) rotates about x from 0 to π/8 in 100 steps with the joint retracted "
        f"(s23 = 2). Capsule model: cables of radius 0.1, the two rectangles and the joint column. First "
        f"self-collision at step {None if first is None else first + 1} between cables {pairs} (the source reports step 71, cables 1 & 5 and "
        f"4 & 8). Force-closure singular steps: {int(res.force_closure_singular.sum())}; Jacobian singular: "
        f"{int(res.jacobian_singular.sum())}."
    )
    fig = plot_check(robot, res)
    report.add_section(
        "adjustable-8cable: self-collision and singularities (simulation c)",
        text=text,
        figures=[(fig, "adjustable-8cable-check.png", "clearance over the steps; robot at the first collision")],
        json={"first_collision": first, "collisions": res.proximity.collisions(first - 1) if first else []},
        views=[
            (
                view_motion(
                    robot,
                    np.arange(1, len(poses) + 1, dtype=float),
                    poses,
                    time_label="step",
                    title=f"{robot.name}: simulation c, {len(poses)} steps",
                ),
                "simulation c step by step: the two bodies, their capsules and the cables",
            )
        ],
    )
