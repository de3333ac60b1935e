"""Shared look of taut's figures: one colour per cable, the same in every figure."""

from __future__ import annotations

import numpy as np

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


def new_axes(three_d: bool, figsize=None):
    """A fresh figure (through pyplot, so that it shows in notebooks) and its axes."""
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=figsize or ((7.0, 6.0) if three_d else (6.0, 6.0)))
    ax = fig.add_subplot(projection="3d") if three_d else fig.add_subplot()
    return ax


def is_3d(ax) -> bool:
    return getattr(ax, "name", "") == "3d"


def set_equal_3d(ax, points: np.ndarray, margin: float = 0.05) -> None:
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
