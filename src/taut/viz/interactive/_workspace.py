"""A workspace as a layer over the robot: :func:`view_workspace` — the poses of a grid
workspace found inside (:func:`taut.workspace.evaluate_workspace`), or the boxes of a certified
one (:func:`taut.workspace.certified`, Gouttefarde, Daney & Merlet 2011): proven inside,
undecided and proven outside.  Buttons and the legend show and hide the layer.

References
----------
.. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011. (docs/references.bib: gouttefarde2011)
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, cast

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError
from taut.viz.interactive._plotly import graph_objects
from taut.viz.interactive._robot import view_robot
from taut.viz.interactive._scene import lift, mesh

if TYPE_CHECKING:
    from plotly.graph_objects import Figure

    from taut.model import Robot
    from taut.workspace import CertifiedWorkspace, WorkspaceResult

__all__ = ["MAX_POINTS", "view_workspace"]

#: Most workspace points drawn: beyond, every k-th point inside is (the file and the
#: browser's memory grow with them).
MAX_POINTS = 50_000

_COLOURS = {"inner": "#4c9f70", "undecided": "#f0ad4e", "outer": "#bbbbbb"}


def _boxes(boxes: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Vertices and triangles of boxes ``(K, d, 2)``: rectangles in the plane, cuboids in space."""
    K, d, _ = boxes.shape
    if K == 0:
        return np.empty((0, 3)), np.empty((0, 3), int)
    corners = np.array(np.meshgrid(*([0, 1],) * d, indexing="ij")).reshape(d, -1).T  # (2^d, d)
    verts = np.take_along_axis(boxes[:, None, :, :], corners[None, :, :, None], axis=3)[..., 0]  # (K, 2^d, d)
    if d == 2:
        quad = np.array([[0, 1, 3], [0, 3, 2]])
    else:
        # the 12 triangles of a cube's faces, corners numbered by their (x, y, z) bits
        quad = np.array(
            [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1]]
            + [[2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
        )
    tris = quad[None] + (len(corners) * np.arange(K))[:, None, None]
    return lift(verts.reshape(-1, d)), tris.reshape(-1, 3)


def view_workspace(
    robot: Robot,
    result: WorkspaceResult | CertifiedWorkspace,
    pose: npt.ArrayLike | None = None,
    *,
    tensions: npt.ArrayLike | None = None,
    max_points: int = MAX_POINTS,
) -> Figure:
    """:func:`view_robot` with a workspace as a layer that buttons (and the legend) show and hide.

    Parameters
    ----------
    robot : Robot
        The robot of ``result``.
    result : WorkspaceResult or CertifiedWorkspace
        A grid workspace (its poses inside drawn as points at their positions) or a certified
        one (boxes proven inside green, undecided orange, proven outside grey and hidden at
        first).
    pose : array_like, optional
        The robot's pose (default as :func:`view_robot`).
    tensions : array_like, shape (n,), optional
    max_points : int, default :data:`MAX_POINTS`
        Most points of a grid workspace drawn.

    Returns
    -------
    plotly.graph_objects.Figure

    Raises
    ------
    ArgumentError
        A result of another robot, or ``max_points < 1``.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.viz.interactive import view_workspace
    >>> from taut.workspace import certified
    >>> robot = example("planar-4cable")
    >>> fig = view_workspace(robot, certified(robot, "static", eps=0.05), [0, 0, 0])
    >>> [t.name for t in fig.data if t.legendgroup == "workspace"]
    ['proven inside', 'undecided', 'proven outside']
    >>> [b.label for b in fig.layout.updatemenus[0].buttons]
    ['show workspace', 'hide workspace']
    """
    if result.robot_name != robot.name:
        raise ArgumentError(f"the workspace is of {result.robot_name!r}, not of {robot.name!r}")
    if max_points < 1:
        raise ArgumentError(f"max_points must be at least 1, got {max_points}")
    go = graph_objects()
    fig = view_robot(robot, pose, tensions=tensions)
    layers: list[Any] = []
    d = robot.dimension
    # the result classes are not imported at run time (viz only draws): told apart by their fields
    if hasattr(result, "inner"):
        names = {"inner": "proven inside", "undecided": "undecided", "outer": "proven outside"}
        for key, name in names.items():
            v, t = _boxes(np.asarray(getattr(result, key), float))
            layers.append(
                mesh(
                    go,
                    v,
                    t,
                    name,
                    color=_COLOURS[key],
                    opacity=0.35 if d == 3 else 0.6,
                    legendgroup="workspace",
                    showlegend=True,
                    hoverinfo="name",
                    visible="legendonly" if key == "outer" else True,
                )
            )
        what = f"{result.condition} workspace certified to {cast('CertifiedWorkspace', result).eps:g} m"
    else:
        inside = np.flatnonzero(np.asarray(result.inside))
        every = max(1, -(-len(inside) // max_points))
        pts = lift(result.poses_at(inside[::every])[:, :d]) if len(inside) else np.empty((0, 3))
        note = f" (every {every}th)" if every > 1 else ""
        layers.append(
            go.Scatter3d(
                x=pts[:, 0],
                y=pts[:, 1],
                z=pts[:, 2],
                mode="markers",
                marker=dict(size=2 if d == 3 else 3, color=_COLOURS["inner"], opacity=0.5),
                name=f"{len(inside)} poses inside{note}",
                legendgroup="workspace",
                hoverinfo="skip",
            )
        )
        what = f"{result.condition} workspace, {len(inside)} of {result.size} poses inside"
    first = len(fig.data)
    fig.add_traces(layers)
    index = list(range(first, len(fig.data)))
    shown = [tr.visible for tr in layers]
    fig.update_layout(
        title=f"{robot.name}: {what}",
        updatemenus=[
            dict(
                type="buttons",
                direction="left",
                x=0.0,
                y=1.06,
                xanchor="left",
                buttons=[
                    dict(label="show workspace", method="restyle", args=[{"visible": shown}, index]),
                    dict(label="hide workspace", method="restyle", args=[{"visible": False}, index]),
                ],
            )
        ],
    )
    return fig
