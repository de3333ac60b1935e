"""A controlled motion (:func:`taut.dynamics.simulate_control`, ``taut simulate --out``):
:func:`view_control` — the reference and the simulated robot side by side, animated, and the
tension margin over time (how far the closest tension is from its bounds)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError
from taut.viz.interactive._motion import MAX_FRAMES, _times, frame_samples, slider
from taut.viz.interactive._plotly import graph_objects
from taut.viz.interactive._scene import at_poses, bounds, check_rows, pose_traces, scene_traces, tension_range

if TYPE_CHECKING:
    from plotly.graph_objects import Figure

    from taut.model import Robot

__all__ = ["view_control", "tension_margin"]


def tension_margin(robot: Robot, tensions: np.ndarray) -> np.ndarray:
    """``(T,)`` the smallest distance of a tension to its bounds at each sample [N] (negative
    beyond them): ``min_i min(τ_i − τ_min,i, τ_max,i − τ_i)``, an infinite upper bound left out."""
    lo, hi = robot.tension_bounds
    below = tensions - np.asarray(lo, float)
    above = np.where(np.isfinite(hi), np.asarray(hi, float) - tensions, np.inf)
    return np.asarray(np.minimum(below, above).min(axis=1))


def view_control(
    robot: Robot,
    times: npt.ArrayLike,
    poses: npt.ArrayLike,
    reference: npt.ArrayLike,
    tensions: npt.ArrayLike,
    *,
    frames: int = MAX_FRAMES,
    title: str | None = None,
) -> Figure:
    """The reference motion (left) and the simulated one (right, cables coloured by tension)
    animated side by side with one slider, and below the tension margin over time.

    Parameters
    ----------
    robot : Robot
    times : array_like, shape (T,)
    poses, reference : array_like, shape (T, pose_size)
        Simulated and reference poses (:class:`taut.dynamics.ControlResult` ``poses`` and
        ``reference``, or the columns of ``taut simulate --out``).
    tensions : array_like, shape (T, n)
        Commanded tensions [N].
    frames : int, default :data:`~taut.viz.interactive.MAX_FRAMES`
    title : str, optional

    Returns
    -------
    plotly.graph_objects.Figure

    Raises
    ------
    ArgumentError
        Arrays of other shapes.

    Examples
    --------
    >>> from taut.dynamics import simulate_control
    >>> from taut.model import example
    >>> from taut.motion import trajectory_from_waypoints
    >>> from taut.viz.interactive import view_control
    >>> robot = example("spatial-8cable")
    >>> motion = trajectory_from_waypoints(robot, [[0, 0, 0, 0, 0, 0], [0.2, 0, 0.1, 0, 0, 0]], duration=1.0)
    >>> run = simulate_control(robot, motion, decimate=10)
    >>> fig = view_control(robot, run.times, run.poses, run.reference, run.tensions, frames=20)
    >>> fig.layout.scene.domain.x[1] <= fig.layout.scene2.domain.x[0], len(fig.frames)
    (True, 20)
    >>> margin = next(t for t in fig.data if t.name == "tension margin")
    >>> bool(abs(margin.y.min() - run.min_tension_margin) < 1e-6)
    True
    """
    from plotly.subplots import make_subplots

    go = graph_objects()
    t = _times(times)
    T, n = len(t), robot.n_cables
    P = check_rows("poses", poses, T, robot.pose_size)
    R = check_rows("reference", reference, T, robot.pose_size)
    tau = check_rows("tensions", tensions, T, n)
    assert P is not None and R is not None and tau is not None
    if np.isnan(P).any() or np.isnan(R).any():
        raise ArgumentError("poses: NaN cannot be drawn")
    picks = frame_samples(T, frames)
    ref, sim = at_poses(robot, R[picks]), at_poses(robot, P[picks])
    margin = tension_margin(robot, tau)
    crange = tension_range(tau)
    fig = make_subplots(
        rows=2,
        cols=2,
        specs=[[{"type": "scene"}, {"type": "scene"}], [{"type": "xy", "colspan": 2}, None]],
        row_heights=[0.72, 0.28],
        subplot_titles=["reference", "simulated", ""],
        vertical_spacing=0.08,
        horizontal_spacing=0.02,
    )

    def robots(k: int) -> list[Any]:
        s = int(picks[k])
        stamp = f"t {t[s]:.4g} s"
        return [
            *pose_traces(robot, ref, k, label=f"reference, {stamp}", scene="scene"),
            *pose_traces(robot, sim, k, tensions=tau[s], crange=crange, label=f"simulated, {stamp}", scene="scene2"),
        ]

    def now(k: int) -> Any:
        s = int(picks[k])
        return go.Scatter(
            x=[t[s]],
            y=[margin[s]],
            mode="markers",
            name="margin now",
            marker=dict(size=10, color="black"),
            showlegend=False,
        )

    for col in (1, 2):
        for tr in scene_traces(robot):
            fig.add_trace(tr.update(showlegend=col == 1), row=1, col=col)
    first = len(fig.data)
    for k, tr in enumerate(robots(0)):
        tr.showlegend = k < len(robots(0)) // 2 and tr.showlegend is not False
        fig.add_trace(tr, row=1, col=1 if tr.scene == "scene" else 2)
    fig.add_trace(go.Scatter(x=t, y=margin, mode="lines", name="tension margin", line=dict(color="#3b5b7a")), 2, 1)
    fig.add_trace(now(0), row=2, col=1)
    moving = [*range(first, first + len(robots(0))), len(fig.data) - 1]
    fig.frames = [go.Frame(data=[*robots(k), now(k)], traces=moving, name=str(k)) for k in range(len(picks))]
    bar, buttons = slider(t[picks], "time = ")
    layout = bounds(robot, [ref, sim])
    error = float(np.abs(P[:, : robot.dimension] - R[:, : robot.dimension]).max())
    fig.update_layout(
        title=title
        or f"{robot.name}: controlled motion, max position error {1e3 * error:.3g} mm, "
        f"min tension margin {margin.min():.4g} N",
        scene=layout,
        scene2=layout,
        height=850,
        margin=dict(l=10, r=10, t=70, b=10),
        sliders=[bar],
        updatemenus=[buttons],
        legend=dict(x=0, y=1),
    )
    fig.update_yaxes(title_text="tension margin [N]", row=2, col=1)
    fig.update_xaxes(title_text="time [s]", row=2, col=1)
    return fig
