"""Shared look of taut's figures (one colour per cable, the same in every figure) and the
checks of the axes, figures and arrays that the plotting functions are given (each raises
:class:`~taut.errors.ArgumentError`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from mpl_toolkits.mplot3d.axes3d import Axes3D

#: Colours cycled over cables (matplotlib's ``tab10``): cable *i* (1-based) has ``CABLE_COLORS[(i-1) % 10]``.
CABLE_COLORS = (
    "#1f77b4",
    "#ff7f0e",
    "#2ca02c",
    "#d62728",
    "#9467bd",
    "#8c564b",
    "#e377c2",
    "#7f7f7f",
    "#bcbd22",
    "#17becf",
)
FRAME = "#9a9a9a"
OBSTACLE = "#b0b0b0"
DISALLOWED = "#d9534f"
PLATFORM = "#3b5b7a"
INSIDE = "#4c9f70"
OUTSIDE = "#eeeeee"


def cable_color(i: int) -> str:
    """Colour of the cable with 0-based index ``i``."""
    return CABLE_COLORS[i % len(CABLE_COLORS)]


def axes_2d(ax: Axes | None, what: str, figsize: tuple[float, float] = (6.0, 6.0)) -> Axes:
    """``ax`` if it is 2-D, else an ``ArgumentError`` naming ``what`` is drawn; with ``ax=None``
    the axes of a new figure (through pyplot, so that it shows in notebooks)."""
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.axes3d import Axes3D

    if ax is None:
        return plt.figure(figsize=figsize).add_subplot()
    if isinstance(ax, Axes3D):
        raise ArgumentError(f"{what} is drawn on 2-D axes, got 3-D axes (projection='3d')")
    return ax


def axes_3d(ax: Axes | None, what: str, figsize: tuple[float, float] = (7.0, 6.0)) -> Axes3D:
    """``ax`` if it is a 3-D ``Axes3D`` (``projection="3d"``), else an ``ArgumentError`` naming
    ``what`` is drawn; with ``ax=None`` the 3-D axes of a new figure."""
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.axes3d import Axes3D

    if ax is None:
        ax = plt.figure(figsize=figsize).add_subplot(projection="3d")
    if not isinstance(ax, Axes3D):
        raise ArgumentError(f"{what} is drawn on 3-D axes (projection='3d'), got 2-D axes")
    return ax


def empty_figure(fig: Figure | None, what: str, figsize: tuple[float, float]) -> Figure:
    """``fig`` if it holds no axes yet, else an ``ArgumentError`` naming ``what`` is drawn (its
    panels are laid out over the whole figure); with ``fig=None`` a new figure of
    ``figsize`` through pyplot."""
    import matplotlib.pyplot as plt

    if fig is None:
        return plt.figure(figsize=figsize)
    if fig.axes:
        raise ArgumentError(f"{what} lays out its panels on an empty figure, the given one has {len(fig.axes)} axes")
    return fig


def set_equal_3d(ax: Axes3D, points: npt.ArrayLike, margin: float = 0.05) -> None:
    """Limits enclosing ``points`` (k, 3) with a box aspect that makes metres equal on all axes."""
    pts = np.asarray(points, float).reshape(-1, 3)
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    if not len(pts):
        return
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = hi - lo
    pad = margin * max(float(span.max()), 1e-9)
    span = np.maximum(span, 2 * pad)  # a flat scene still gets a visible box
    mid = (lo + hi) / 2
    lo, hi = mid - span / 2 - pad, mid + span / 2 + pad
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    ax.set_box_aspect(tuple(hi - lo))
    from matplotlib.ticker import MaxNLocator

    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(5))
