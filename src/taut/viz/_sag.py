"""Whether sag matters, drawn from a :class:`taut.workspace.SagMap`: :func:`plot_sag`.

Two panels: per cable (in its colour, labelled with its 1-based number) the largest sag and
the largest length difference from the straight model over the poses where both models have
tensions; and over the first two position coordinates, the largest length difference of any
cable at each grid pose (the largest over the other coordinates when the grid has more), the
comparison of the two models Riehl et al. (2009, §IV) map.

References
----------
.. [1] N. Riehl, M. Gouttefarde, S. Krut, C. Baradat, F. Pierrot, "Effects of non-negligible
   cable mass on the static behavior of large workspace cable-driven parallel mechanisms",
   IEEE ICRA, 2009, §IV. (docs/references.bib: riehl2009)
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from taut.errors import ArgumentError
from taut.viz._style import cable_color, empty_figure

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from taut.model import Robot
    from taut.workspace import SagMap

__all__ = ["plot_sag"]


def plot_sag(sag: SagMap, robot: Robot | None = None, fig: Figure | None = None) -> Figure:
    """Draw a sag map (module docstring) on the empty figure ``fig`` (``None``: a new one) and
    return it.

    Parameters
    ----------
    sag : SagMap
        The map of :func:`taut.workspace.sag_map`.
    robot : Robot, optional
        Names the figure.
    fig : Figure, optional
        An empty figure.

    Returns
    -------
    Figure

    Raises
    ------
    ArgumentError
        ``sag`` without the fields of a sag map, or a figure that already has axes.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import sag_map
    >>> robot = example("cogiro-sagging")
    >>> m = sag_map(robot, grid=[(-1, 1, 3), (-1, 1, 2), (2.0, 2.0, 1)], method="qp")
    >>> len(plot_sag(m, robot).axes)
    3
    """
    try:
        poses = np.asarray(sag.poses, float)
        both = np.asarray(sag.feasible, bool) & np.asarray(sag.straight_feasible, bool)
        diff = np.abs(np.asarray(sag.length_difference, float))
        sags = np.asarray(sag.sag, float)
    except AttributeError:
        raise ArgumentError(f"plot_sag draws a SagMap, got {type(sag).__name__}") from None
    if poses.ndim != 2 or poses.shape[1] < 2 or diff.shape != sags.shape or diff.shape[0] != poses.shape[0]:
        raise ArgumentError(f"a sag map of {poses.shape} poses with lengths of shape {diff.shape}")
    n = diff.shape[1]
    fig = empty_figure(fig, "a sag map", (11.0, 4.5))
    bars, plane = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.3]})
    cables = np.arange(1, n + 1)
    worst_sag = sags[both].max(axis=0) if both.any() else np.zeros(n)
    worst_diff = diff[both].max(axis=0) if both.any() else np.zeros(n)
    colours = [cable_color(i) for i in range(n)]
    bars.bar(cables - 0.2, worst_sag, width=0.4, color=colours, label="largest sag [m]")
    bars.bar(cables + 0.2, worst_diff, width=0.4, color=colours, hatch="//", alpha=0.6, label="largest |Δ length| [m]")
    bars.set_xticks(cables)
    bars.set_xlabel("cable")
    bars.set_ylabel("m")
    bars.legend(fontsize=8)
    bars.set_title(f"{int(both.sum())} of {poses.shape[0]} poses with tensions in both models", fontsize=10)
    names = list(sag.pose_names)
    xy = poses[:, :2]
    keys, inverse = np.unique(xy, axis=0, return_inverse=True)
    worst = np.full(keys.shape[0], np.nan)
    value = np.where(both, diff.max(axis=1), np.nan)
    for j in range(keys.shape[0]):
        here = value[inverse.ravel() == j]
        if np.isfinite(here).any():
            worst[j] = np.nanmax(here)
    shown = np.isfinite(worst)
    plane.scatter(keys[~shown, 0], keys[~shown, 1], c="#dddddd", s=12, marker="x", label="no tensions")
    points = plane.scatter(keys[shown, 0], keys[shown, 1], c=1e3 * worst[shown], cmap="viridis", s=30)
    fig.colorbar(points, ax=plane, label="largest |Δ length| of any cable [mm]")
    plane.set_xlabel(f"{names[0]} [m]")
    plane.set_ylabel(f"{names[1]} [m]")
    plane.set_aspect("equal", adjustable="datalim")
    plane.legend(fontsize=8, loc="upper right")
    title = "unstrained length with sag minus the straight model's"
    if robot is not None:
        title = f"{robot.name}: {title}"
    fig.suptitle(title, fontsize=11)
    return fig
