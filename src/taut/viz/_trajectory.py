"""Figures of a VSCR trajectory (Figs. 4.7, 4.10, 6.10 and 4.8, 4.9 of Rushton 2022).

:func:`plot_trajectory`: the cable lengths over time with every CST transition marked by a
black circle (wrap: filled, unwrap: open), above snapshots of the robot in which each
cable is drawn as its wrapped path — straight segments and arcs.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Figs. 4.7–4.10, 6.10. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.errors import ArgumentError
from taut.viz._style import axes_2d, cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from taut.model import Robot
    from taut.wrapping import TrajectoryResult

__all__ = ["draw_wrapped_cables", "plot_trajectory"]


def draw_wrapped_cables(result: TrajectoryResult, sample: int, ax: Axes | None = None) -> Axes:
    """Draw every cable of ``result`` at ``sample`` as its path — static segments solid,
    the active segment dashed, arcs around the objects — on 2-D axes ``ax`` (``None``: a
    new figure; 3-D axes raise :class:`~taut.errors.ArgumentError`) and return that ``Axes``."""
    ax = axes_2d(ax, "a wrapped cable path")
    for i in range(result.ik.lengths.shape[1]):
        path = result.ik.path(sample, i)
        col = cable_color(i)
        for j, (a, b) in enumerate(path.segments):
            ax.plot(
                [a[0], b[0]],
                [a[1], b[1]],
                color=col,
                lw=1.6,
                ls="--" if j == len(path.segments) - 1 else "-",
                gid=f"wrapped-cable-{i + 1}",
            )
        for k in range(len(path.arcs)):
            if path.arcs[k, 2] > 0 and abs(path.arcs[k, 4]) > 0:
                pts = path.arc_points(k)
                ax.plot(pts[:, 0], pts[:, 1], color=col, lw=2.2)
    return ax


def plot_trajectory(robot: Robot, result: TrajectoryResult, snapshots: int = 3, fig: Figure | None = None) -> Figure:
    """Lengths over time with transitions (top) and ``snapshots`` robot drawings (bottom)
    laid out on the empty figure ``fig`` (``None``: a new one); returns that figure.  A
    figure that already has axes or ``snapshots < 1`` raise
    :class:`~taut.errors.ArgumentError`."""
    from taut.viz._robot import draw_robot

    if snapshots < 1:
        raise ArgumentError(f"plot_trajectory draws at least one snapshot, got snapshots={snapshots}")
    fig = empty_figure(fig, "a trajectory", (4.0 * snapshots, 7.5))
    gs = fig.add_gridspec(2, snapshots, height_ratios=[1.0, 1.2])
    ax = fig.add_subplot(gs[0, :])
    t, L = result.times, result.ik.lengths
    for i in range(L.shape[1]):
        ax.plot(t, L[:, i], color=cable_color(i), label=f"cable {i + 1}")
    for e in result.transitions:
        i, j = e["cable"], e["sample"]
        y = np.interp(e["time"], t[j - 1 : j + 1], L[j - 1 : j + 1, i])
        ax.plot(e["time"], y, "o", ms=7, mec="k", mfc="k" if e["kind"] == "wrap" else "none", zorder=5)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("cable length [m]")
    ax.set_title("cable lengths; black circles: CST transitions (filled: wrap, open: unwrap)")
    ax.legend(loc="best", fontsize="small")
    picks = np.linspace(0, len(t) - 1, snapshots + 2)[1:-1].round().astype(int) if snapshots > 1 else [0]
    for c, s in enumerate(picks):
        sub = fig.add_subplot(gs[1, c])
        draw_robot(robot, result.ik.poses[s], ax=sub)
        for line in list(sub.lines):
            if (line.get_gid() or "").startswith("cable-"):
                line.remove()
        draw_wrapped_cables(result, int(s), sub)
        sub.set_title(f"t = {t[s]:.2f} s", fontsize="small")
        leg = sub.get_legend()
        if leg is not None:
            leg.remove()
    fig.tight_layout()
    return fig
