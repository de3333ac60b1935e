"""Figures of the geometrico-static problems of under-constrained robots
(Berti 2015, Ch. 2–4).

:func:`plot_equilibria` draws every equilibrium of a DGP solve, one panel each (the
drawings of Fig. 4.7); :func:`plot_tracking` shows a run of tracking forward kinematics
(§4.1.2) — platform position and cable tensions per update, taut-set changes marked.

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

from taut.errors import ArgumentError
from taut.viz._robot import draw_robot
from taut.viz._style import cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.dgp import DGPSolution
    from taut.model import Robot

__all__ = ["plot_equilibria", "plot_tracking"]


def plot_equilibria(
    robot: Robot, solutions: Sequence[DGPSolution], columns: int = 3, fig: Figure | None = None
) -> Figure:
    """One panel per solution of ``robot`` (3-D for a spatial one), ``columns`` panels a row, titled
    with its taut cables and stability; a single note when there is none.  Laid out on the
    empty figure ``fig`` (``None``: a new one), which is returned.  A figure that already
    has axes or ``columns < 1`` raise :class:`~taut.errors.ArgumentError`."""
    if columns < 1:
        raise ArgumentError(f"columns must be at least 1, got {columns}")
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
        ax = fig.add_subplot(rows, cols, k + 1, projection="3d" if robot.dimension == 3 else None)
        draw_robot(robot, np.concatenate([s.position, s.orientation]), ax=ax)
        taut = ",".join(str(i + 1) for i in s.taut)
        ax.set_title(f"#{k + 1}: cables {taut} taut, {'stable' if s.stable else 'unstable'}", fontsize=9)
    fig.tight_layout()
    return fig


def plot_tracking(path: Sequence[DGPSolution], fig: Figure | None = None) -> Figure:
    """Position (left) and tensions (right) along a :func:`taut.dgp.track_path` result; a
    dotted line where the set of taut cables changes.  Laid out on the empty figure ``fig``
    (``None``: a new one), which is returned.  A figure that already has axes or an empty
    ``path`` raise :class:`~taut.errors.ArgumentError`."""
    if not path:
        raise ArgumentError("plot_tracking needs at least one tracked solution, got none")
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
