"""A robot at one pose, in a 3-D view: :func:`view_robot`."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.errors import PoseError
from taut.viz._robot import _default_pose
from taut.viz.interactive._plotly import graph_objects
from taut.viz.interactive._scene import at_poses, bounds, check_rows, pose_traces, scene_traces, tension_range

if TYPE_CHECKING:
    from plotly.graph_objects import Figure

    from taut.model import Robot

__all__ = ["view_robot"]


def view_robot(
    robot: Robot,
    pose: npt.ArrayLike | None = None,
    *,
    tensions: npt.ArrayLike | None = None,
    slack: npt.ArrayLike | None = None,
    title: str | None = None,
) -> Figure:
    """A 3-D view of ``robot`` at ``pose``: frame, exit points, pulleys, obstacles, the
    platform with its bodies and capsules, and the cables — coloured by tension with a
    colour bar when ``tensions`` are given, slack cables dashed.

    Parameters
    ----------
    robot : Robot
    pose : array_like, shape (pose_size,), optional
        Default: the robot's ``home`` reference pose, else the centroid of its exit points.
    tensions : array_like, shape (n,), optional
        Cable tensions [N], e.g. from :func:`taut.statics.distribute_tensions`.
    slack : array_like of bool, shape (n,), optional
        Cables drawn dashed.
    title : str, optional
        Default: the robot's name and the pose.

    Returns
    -------
    plotly.graph_objects.Figure
        Its traces are the scene's, then :data:`~taut.viz.interactive.POSE_TRACES`.

    Raises
    ------
    PoseError
        Not one pose of the robot.
    ArgumentError
        Tensions or slack flags not one per cable.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.viz.interactive import view_robot
    >>> fig = view_robot(example("planar-4cable"), [0, 0, 0], tensions=[1, 2, 3, 4])
    >>> cables = next(t for t in fig.data if t.name == "cables")
    >>> cables.line.cmin, cables.line.cmax, cables.line.showscale
    (1.0, 4.0, True)
    """
    graph_objects()
    pose = _default_pose(robot) if pose is None else pose
    g = at_poses(robot, pose)
    if g.poses.shape[0] != 1:
        raise PoseError(f"view_robot draws one pose, got {g.poses.shape[0]}")
    n = robot.n_cables
    t = check_rows("tensions", None if tensions is None else np.reshape(tensions, (1, -1)), 1, n)
    s = check_rows("slack", None if slack is None else np.reshape(slack, (1, -1)), 1, n)
    go = graph_objects()
    fig = go.Figure(
        data=[
            *scene_traces(robot),
            *pose_traces(
                robot,
                g,
                0,
                tensions=None if t is None else t[0],
                slack=None if s is None else s[0].astype(bool),
                crange=tension_range(t),
            ),
        ]
    )
    head = ", ".join(f"{nm}={x:.4g}" for nm, x in zip(robot.pose_names, g.poses[0]))
    fig.update_layout(
        title=title or f"{robot.name}: {head}",
        scene=bounds(robot, [g]),
        height=700,
        margin=dict(l=0, r=0, t=50, b=0),
        legend=dict(x=0, y=1),
    )
    return fig
