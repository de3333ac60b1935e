"""Poses over time, animated: :func:`view_motion` (any sequence of poses: a timed trajectory,
a planned path) and :func:`view_trajectory` (a wrapping trajectory of a variable-structure
robot, its cables drawn along their wrapped paths, Rushton 2022, §4.3).

A time slider and a play button move the robot through at most :data:`MAX_FRAMES` frames
evenly spread over the samples; below the 3-D view every cable's length (and tension) over
the whole motion, with markers at the slider's time (the traces ``"lengths now"`` and
``"tensions now"``), so that the 2-D plot and the 3-D view stay linked.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.3. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError
from taut.viz._style import CABLE_COLORS
from taut.viz.interactive._plotly import graph_objects
from taut.viz.interactive._scene import (
    DRAWN,
    Poses,
    at_poses,
    bounds,
    check_rows,
    pose_traces,
    scene_traces,
    tension_range,
)

if TYPE_CHECKING:
    from plotly.graph_objects import Figure

    from taut.model import Robot
    from taut.wrapping import TrajectoryResult

__all__ = ["MAX_FRAMES", "view_motion", "view_trajectory", "frame_samples", "slider"]

#: Most animation frames of a view: each holds the robot's traces, so the file grows with
#: them, while the 2-D plots keep every sample.
MAX_FRAMES = 200


def frame_samples(count: int, frames: int) -> np.ndarray:
    """The samples shown as frames: ``frames`` (at most) evenly spread, the first and last included."""
    if frames < 1:
        raise ArgumentError(f"frames must be at least 1, got {frames}")
    return np.unique(np.linspace(0, count - 1, min(count, frames)).round().astype(int))


def slider(values: Sequence[float], prefix: str, *, y: float = 0.0) -> tuple[dict[str, Any], dict[str, Any]]:
    """The slider (one step per frame, named by its index) and the play/pause buttons."""
    now = dict(mode="immediate", frame=dict(duration=0, redraw=True), transition=dict(duration=0))
    steps = [dict(method="animate", label=f"{v:.4g}", args=[[str(k)], now]) for k, v in enumerate(values)]
    bar = dict(
        active=0,
        steps=steps,
        currentvalue=dict(prefix=prefix),
        x=0.08,
        len=0.9,
        y=y,
        pad=dict(t=30),
    )
    play = dict(frame=dict(duration=60, redraw=True), fromcurrent=True, transition=dict(duration=0))
    buttons = dict(
        type="buttons",
        direction="left",
        x=0.0,
        y=y,
        xanchor="left",
        yanchor="top",
        pad=dict(t=40),
        showactive=False,
        buttons=[
            dict(label="▶ play", method="animate", args=[None, play]),
            dict(label="❚❚", method="animate", args=[[None], dict(mode="immediate", frame=dict(duration=0))]),
        ],
    )
    return bar, buttons


def _animate(
    robot: Robot,
    times: np.ndarray,
    g: Poses,
    lengths: np.ndarray,
    tensions: np.ndarray | None,
    slack: np.ndarray | None,
    paths: Mapping[int, Sequence[np.ndarray]] | None,
    picks: np.ndarray,
    *,
    time_label: str,
    tension_label: str,
    title: str,
) -> Figure:
    from plotly.subplots import make_subplots

    go = graph_objects()
    n = robot.n_cables
    rows = 3 if tensions is not None else 2
    fig = make_subplots(
        rows=rows,
        cols=1,
        specs=[[{"type": "scene"}], *([{"type": "xy"}] for _ in range(rows - 1))],
        row_heights=[0.62, 0.19, 0.19][:rows] if rows == 3 else [0.7, 0.3],
        vertical_spacing=0.05,
        shared_xaxes=True,
    )
    crange = tension_range(tensions)

    def robot_at(k: int) -> list[Any]:
        s = int(picks[k])
        return pose_traces(
            robot,
            g,
            k,
            tensions=None if tensions is None else tensions[s],
            slack=None if slack is None else slack[s],
            paths=None if paths is None else paths[s],
            lengths=lengths[s],
            crange=crange,
            label=f"{time_label.split(' [')[0]} {times[s]:.4g}",
        )

    def now(k: int) -> list[Any]:
        s = int(picks[k])
        colours = [CABLE_COLORS[i % len(CABLE_COLORS)] for i in range(n)]

        def markers(values: np.ndarray, name: str, unit: str) -> Any:
            return go.Scatter(
                x=np.full(n, times[s]),
                y=values,
                mode="markers",
                name=name,
                marker=dict(color=colours, size=9, line=dict(color="black", width=1)),
                hovertext=[f"cable {i + 1}: {values[i]:.6g}{unit}" for i in range(n)],
                hoverinfo="text",
                showlegend=False,
            )

        out = [markers(lengths[s], "lengths now", " m")]
        if tensions is not None:
            out.append(markers(tensions[s], "tensions now", ""))
        return out

    for tr in scene_traces(robot):
        fig.add_trace(tr, row=1, col=1)
    first = len(fig.data)
    for tr in robot_at(0):
        fig.add_trace(tr, row=1, col=1)
    x = times.astype(DRAWN)
    for i in range(n):
        style = dict(color=CABLE_COLORS[i % len(CABLE_COLORS)], width=1.5)
        fig.add_trace(
            go.Scatter(x=x, y=lengths[:, i].astype(DRAWN), mode="lines", name=f"cable {i + 1}", line=style),
            row=2,
            col=1,
        )
        if tensions is not None:
            fig.add_trace(
                go.Scatter(
                    x=x, y=tensions[:, i].astype(DRAWN), mode="lines", name=f"τ{i + 1}", line=style, showlegend=False
                ),
                row=3,
                col=1,
            )
    marks = len(fig.data)
    for r, tr in enumerate(now(0), start=2):
        fig.add_trace(tr, row=r, col=1)
    moving = [*range(first, marks), *range(marks, len(fig.data))]
    fig.frames = [go.Frame(data=[*robot_at(k), *now(k)], traces=moving, name=str(k)) for k in range(len(picks))]
    bar, buttons = slider(times[picks], f"{time_label.split(' [')[0]} = ")
    fig.update_layout(
        title=title,
        scene=bounds(robot, [g]),
        height=900,
        margin=dict(l=10, r=10, t=50, b=10),
        sliders=[bar],
        updatemenus=[buttons],
        legend=dict(x=0, y=1),
        hovermode="closest",
    )
    fig.update_yaxes(title_text="length [m]", row=2, col=1)
    if tensions is not None:
        fig.update_yaxes(title_text=tension_label, row=3, col=1)
    fig.update_xaxes(title_text=time_label, row=rows, col=1)
    return fig


def view_motion(
    robot: Robot,
    times: npt.ArrayLike,
    poses: npt.ArrayLike,
    *,
    lengths: npt.ArrayLike | None = None,
    tensions: npt.ArrayLike | None = None,
    slack: npt.ArrayLike | None = None,
    frames: int = MAX_FRAMES,
    time_label: str = "time [s]",
    tension_label: str = "tension [N]",
    title: str | None = None,
) -> Figure:
    """An animated 3-D view of ``robot`` through ``poses``, with a time slider, a play
    button, and the cable lengths (and tensions) over time in linked 2-D plots.

    Parameters
    ----------
    robot : Robot
    times : array_like, shape (T,)
        Increasing sample times (or any increasing parameter, named by ``time_label``).
    poses : array_like, shape (T, pose_size)
    lengths : array_like, shape (T, n), optional
        Cable lengths [m] to plot; default: the straight lengths of the poses
        (:func:`taut.kinematics.cable_lengths`).
    tensions : array_like, shape (T, n), optional
        Cable tensions, colouring the cables and plotted under the lengths.
    slack : array_like of bool, shape (T, n), optional
        Cables drawn dashed.
    frames : int, default :data:`MAX_FRAMES`
        Most animation frames, spread evenly over the samples.
    time_label, tension_label : str
        Axis titles of the 2-D plots.
    title : str, optional

    Returns
    -------
    plotly.graph_objects.Figure
        With one frame per shown sample, a slider and play/pause buttons.

    Raises
    ------
    ArgumentError
        Arrays of other shapes, times that do not increase, or ``frames < 1``.
    PoseError
        Poses the robot cannot take.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.viz.interactive import view_motion
    >>> robot = example("planar-4cable")
    >>> poses = np.column_stack([np.linspace(-0.2, 0.2, 50), np.zeros(50), np.zeros(50)])
    >>> fig = view_motion(robot, np.linspace(0, 1, 50), poses, frames=10)
    >>> len(fig.frames), len(fig.layout.sliders[0].steps)
    (10, 10)
    >>> now = next(t for t in fig.data if t.name == "lengths now")
    >>> from taut.kinematics import cable_lengths
    >>> bool(np.allclose(now.y, cable_lengths(robot, poses[0])))
    True
    """
    t = _times(times)
    g = at_poses(robot, poses)
    T, n = len(t), robot.n_cables
    if g.poses.shape[0] != T:
        raise ArgumentError(f"poses: expected {T} poses (one per time), got {g.poses.shape[0]}")
    picks = frame_samples(T, frames)
    shown = at_poses(robot, g.poses[picks])
    L = check_rows("lengths", lengths, T, n)
    tau = check_rows("tensions", tensions, T, n)
    sl = None if slack is None else np.asarray(slack, bool).reshape(T, n)
    return _animate(
        robot,
        t,
        shown,
        g.lengths if L is None else L,
        tau,
        sl,
        None,
        picks,
        time_label=time_label,
        tension_label=tension_label,
        title=title or f"{robot.name}: {T} samples",
    )


def view_trajectory(robot: Robot, result: TrajectoryResult, *, frames: int = MAX_FRAMES) -> Figure:
    """:func:`view_motion` of a wrapping trajectory (:func:`taut.wrapping.run_trajectory`):
    every cable drawn along its path — straight segments and the arcs it winds around
    obstacles and pulleys — with its length and tension over time.

    Parameters
    ----------
    robot : Robot
        The robot of ``result``.
    result : TrajectoryResult
    frames : int, default :data:`MAX_FRAMES`

    Returns
    -------
    plotly.graph_objects.Figure

    Raises
    ------
    ArgumentError
        A result of another robot (another number of cables).

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.viz.interactive import view_trajectory
    >>> from taut.wrapping import builtin_trajectory, run_trajectory
    >>> robot = example("vscr-single-cable")
    >>> res = run_trajectory(robot, *builtin_trajectory(robot, dt=0.05))
    >>> fig = view_trajectory(robot, res, frames=20)
    >>> len(fig.frames), fig.layout.sliders[0].currentvalue.prefix
    (20, 'time = ')
    """
    if result.lengths.shape[1] != robot.n_cables:
        raise ArgumentError(
            f"view_trajectory: the result has {result.lengths.shape[1]} cables, {robot.name} has {robot.n_cables}"
        )
    t = _times(result.times)
    picks = frame_samples(len(t), frames)
    paths: dict[int, list[np.ndarray]] = {}
    for s in picks:
        cables = []
        for i in range(robot.n_cables):
            path = result.ik.path(int(s), i)
            # the winch pulley's arc first, then each segment and the arc where it ends
            pieces = []
            for j, (a, b) in enumerate(path.segments):
                if j < len(path.arcs) and path.arcs[j, 2] > 0 and abs(path.arcs[j, 4]) > 0:
                    pieces.append(path.arc_points(j))
                pieces.append(np.asarray([a, b]))
            cables.append(np.vstack(pieces))
        paths[int(s)] = cables
    return _animate(
        robot,
        t,
        at_poses(robot, result.ik.poses[picks]),
        np.asarray(result.lengths),
        np.asarray(result.tensions),
        None,
        paths,
        picks,
        time_label="time [s]",
        tension_label="tension [N]",
        title=f"{robot.name}: wrapping trajectory, {len(t)} samples, {len(result.transitions)} transitions",
    )


def _times(times: npt.ArrayLike) -> np.ndarray:
    t = np.asarray(times, float).ravel()
    if t.size < 1 or not np.isfinite(t).all():
        raise ArgumentError("times: expected at least one finite time")
    if (np.diff(t) < 0).any():
        raise ArgumentError("times: expected times that do not decrease")
    return t
