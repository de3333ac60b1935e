"""The equilibria of an under-constrained robot, one at a time: :func:`view_equilibria`
(the solutions of the direct geometrico-static problem, Berti 2015, Ch. 2–3).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, Chs. 2–3. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import numpy as np

from taut.errors import ArgumentError
from taut.viz.interactive._plotly import graph_objects
from taut.viz.interactive._scene import POSE_TRACES, at_poses, bounds, pose_traces, scene_traces, tension_range

if TYPE_CHECKING:
    from plotly.graph_objects import Figure

    from taut.dgp import DGPSolution
    from taut.model import Robot

__all__ = ["view_equilibria"]


def _describe(k: int, s: DGPSolution) -> str:
    taut = ",".join(str(i + 1) for i in s.taut)
    return f"#{k + 1}: cables {taut} taut, {'stable' if s.stable else 'unstable'}"


def view_equilibria(robot: Robot, solutions: Sequence[DGPSolution], *, title: str | None = None) -> Figure:
    """A 3-D view of ``robot`` in each of its equilibria, one shown at a time, chosen in a
    selector; the hover of a cable gives the solution's taut set, its tension and stability;
    slack cables are dashed.

    Parameters
    ----------
    robot : Robot
    solutions : sequence of DGPSolution
        From :func:`taut.dgp.solve_dgp` (``.solutions``) or :func:`taut.dgp.track_path`.
    title : str, optional

    Returns
    -------
    plotly.graph_objects.Figure
        The scene's traces, then :data:`~taut.viz.interactive.POSE_TRACES` per solution (the
        first visible), and one dropdown whose entries show one solution each.

    Raises
    ------
    ArgumentError
        A solution of another robot (poses or tensions of other sizes).

    Examples
    --------
    >>> from taut.dgp import solve_dgp
    >>> from taut.model import example
    >>> from taut.viz.interactive import view_equilibria
    >>> robot = example("planar-2cable")
    >>> fig = view_equilibria(robot, solve_dgp(robot).solutions)
    >>> [b.label for b in fig.layout.updatemenus[0].buttons]
    ['#1: cables 1,2 taut, unstable', '#2: cables 1,2 taut, stable']
    """
    go = graph_objects()
    n = robot.n_cables
    poses = []
    for k, s in enumerate(solutions):
        pose = np.concatenate([np.asarray(s.position, float), np.asarray(s.orientation, float)])
        if pose.size != robot.pose_size or np.asarray(s.tensions).size != n:
            raise ArgumentError(
                f"solution {k + 1} has {pose.size} pose coordinates and {np.asarray(s.tensions).size} tensions; "
                f"{robot.name} has {robot.pose_size} and {n} cables"
            )
        poses.append(pose)
    fig = go.Figure(data=scene_traces(robot))
    fixed = len(fig.data)
    if not solutions:
        fig.update_layout(title=title or f"{robot.name}: no equilibrium for these lengths", height=700)
        return fig
    g = at_poses(robot, np.array(poses))
    tensions = np.array([np.asarray(s.tensions, float) for s in solutions])
    crange = tension_range(tensions)
    for k, s in enumerate(solutions):
        slack = np.ones(n, bool)
        slack[list(s.taut)] = False
        label = f"{_describe(k, s)}<br>τ = {', '.join(f'{t:.4g}' for t in s.tensions)}"
        fig.add_traces(
            pose_traces(robot, g, k, tensions=tensions[k], slack=slack, crange=crange, label=label, visible=k == 0)
        )
    m = len(POSE_TRACES)
    buttons = []
    for k, s in enumerate(solutions):
        visible = [True] * fixed + [j // m == k for j in range(m * len(solutions))]
        buttons.append(
            dict(label=_describe(k, s), method="update", args=[{"visible": visible}, {"title.text": _describe(k, s)}])
        )
    fig.update_layout(
        title=title or _describe(0, solutions[0]),
        scene=bounds(robot, [g]),
        height=750,
        margin=dict(l=0, r=0, t=60, b=0),
        legend=dict(x=0, y=0.9),
        updatemenus=[dict(type="dropdown", buttons=buttons, active=0, x=0.0, y=1.06, xanchor="left", yanchor="top")],
    )
    return fig
