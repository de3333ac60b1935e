"""Figures of a trajectory check (:func:`taut.collision.check_poses`, Lieskovský (2020), §4.2):
:func:`plot_check` — the smallest clearance ``ε`` and the singularity flags over the steps,
and the robot at the first step with a problem, its colliding capsules in red.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.viz._robot import draw_robot
from taut.viz._style import DISALLOWED, empty_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure

    from taut.collision import CheckResult
    from taut.model import Robot

__all__ = ["plot_check"]


def _bands(ax: Axes, steps: np.ndarray, flags: np.ndarray, y0: float, y1: float, color: str, label: str) -> None:
    """Shade the steps where ``flags`` holds between the axes fractions ``y0`` and ``y1``;
    only the first band carries ``label`` (one legend entry)."""
    idx = np.flatnonzero(flags)
    if not idx.size:
        return
    breaks = np.flatnonzero(np.diff(idx) > 1)
    for k, (s, e) in enumerate(zip(np.r_[idx[0], idx[breaks + 1]], np.r_[idx[breaks], idx[-1]])):
        ax.axvspan(
            steps[s] - 0.5, steps[e] + 0.5, ymin=y0, ymax=y1, color=color, alpha=0.35, lw=0, label=None if k else label
        )


def plot_check(robot: Robot, result: CheckResult, fig: Figure | None = None) -> Figure:
    """Figure: clearance and flags over the steps (left), robot at the first problem (right;
    the first step when there is none; 3-D for a spatial robot), laid out on the empty
    figure ``fig`` (``None``: a new one; a figure that already has axes raises
    :class:`~taut.errors.ArgumentError`), which is returned."""
    N = len(result.poses)
    steps = np.arange(1, N + 1)
    fig = empty_figure(fig, "a trajectory check", (13.0, 5.5))
    ax = fig.add_subplot(1, 2, 1)
    ax.plot(steps, result.proximity.min_clearance, color="black", lw=1.4, label="smallest clearance ε")
    ax.axhline(0.0, color="grey", lw=0.8, ls=":")
    _bands(ax, steps, result.collides, 0.0, 1.0, DISALLOWED, "self-collision")
    _bands(ax, steps, result.force_closure_singular, 0.0, 0.5, "#ff9f1c", "force-closure singular")
    _bands(ax, steps, result.jacobian_singular, 0.5, 1.0, "#7b2cbf", "Jacobian singular")
    ax.set_xlabel("step")
    ax.set_ylabel("clearance ε = δ − (ρ_i + ρ_j) [m]")
    ax.set_xlim(0.5, N + 0.5)
    ax.legend(loc="best", fontsize=8)
    first = result.first(result.problems)
    k = first or 0
    three_d = robot.dimension == 3
    rax = fig.add_subplot(1, 2, 2, projection="3d") if three_d else fig.add_subplot(1, 2, 2)
    draw_robot(robot, result.poses[k], ax=rax)
    A, B = result.capsules(robot, k)
    hit = sorted({c for pair in result.proximity.collisions(k) for c in pair})
    for c in hit:
        pts = np.stack([A[c], B[c]])[:, : robot.dimension]
        rax.plot(*pts.T, color=DISALLOWED, lw=4, gid=f"colliding-{c + 1}")
    what = "no problem" if first is None else "first problem"
    rax.set_title(
        f"{what}: step {k + 1}" + (f", colliding {', '.join(str(c + 1) for c in hit)}" if hit else ""), fontsize=10
    )
    ax.set_title(f"{robot.name}: {N} steps", fontsize=10)
    fig.tight_layout()
    return fig
