"""Certified-workspace figure: :func:`plot_certified` draws the boxes of a certified workspace
(inner boxes green, the undecided boundary layer grey, outer boxes blank) over x–y, with the
grid workspace of the same condition as dots when one is given, and the robot's fixed parts.
A spatial result is drawn as its slice at a height ``z``: the boxes that meet that plane.
This is the look of the box coverings of Gouttefarde, Daney & Merlet (2011), Figs. 3–6.

The result is duck-typed (:class:`CertifiedBoxes`).

References
----------
.. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011, Figs. 3–6. (docs/references.bib: gouttefarde2011)
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import numpy as np

from taut._checks import as_array
from taut.errors import ArgumentError
from taut.model import Robot
from taut.viz._robot import draw_scene_2d
from taut.viz._style import INSIDE, axes_2d

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from taut.viz._workspace import GridWorkspace

__all__ = ["CertifiedBoxes", "plot_certified"]

#: The undecided boundary layer's colour.
UNDECIDED = "#9a9a9a"


class CertifiedBoxes(Protocol):
    """What :func:`plot_certified` reads of a certified workspace (such as
    :class:`taut.workspace.CertifiedWorkspace`)."""

    @property
    def condition(self) -> str: ...
    @property
    def region(self) -> np.ndarray: ...
    @property
    def inner(self) -> np.ndarray: ...
    @property
    def undecided(self) -> np.ndarray: ...
    @property
    def inner_volume(self) -> float: ...
    @property
    def undecided_volume(self) -> float: ...


def _at_height(boxes: np.ndarray, z: float | None) -> np.ndarray:
    """The x–y rectangles ``(K, 2, 2)`` of the boxes that meet the plane at height ``z``."""
    if boxes.shape[1] == 2 or z is None:
        return boxes[:, :2]
    meet = (boxes[:, 2, 0] <= z) & (z <= boxes[:, 2, 1])
    return boxes[meet, :2]


def plot_certified(
    result: CertifiedBoxes,
    robot: Robot | None = None,
    ax: Axes | None = None,
    *,
    grid: GridWorkspace | None = None,
    z: float | None = None,
) -> Axes:
    """Draw a certified workspace: inner boxes green, undecided grey, outer blank.

    Parameters
    ----------
    result : CertifiedBoxes
        Such as :class:`taut.workspace.CertifiedWorkspace`.
    robot : Robot, optional
        Overlays its fixed parts (exit points, frame).
    ax : matplotlib Axes, optional
        2-D axes to draw on (default a new figure).
    grid : GridWorkspace, optional
        A grid result of the same condition (a planar one, or a spatial slice at ``z``),
        drawn as dots over the boxes: inside poses dark, outside ones hollow.
    z : float, optional
        The height of the slice of a spatial result (default the middle of its region).

    Returns
    -------
    matplotlib Axes

    Raises
    ------
    ArgumentError
        Boxes that are not ``(K, d, 2)`` arrays with ``d`` 2 or 3, or 3-D axes.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> from taut.model import example
    >>> from taut.workspace import certified
    >>> robot = example("planar-4cable")
    >>> ax = plot_certified(certified(robot, "static", eps=0.1), robot)
    >>> ax.get_title().startswith("static workspace, certified")
    True
    """
    from matplotlib.collections import PolyCollection
    from matplotlib.patches import Patch

    region = as_array(result.region, "region", error=ArgumentError)
    d = region.shape[0]
    if region.shape != (d, 2) or d not in (2, 3):
        raise ArgumentError(f"plot_certified draws 2- or 3-coordinate regions, got a region of shape {region.shape}")
    boxes = {}
    for name in ("inner", "undecided"):
        b = np.asarray(getattr(result, name), float)
        if b.ndim != 3 or b.shape[1:] != (d, 2):
            raise ArgumentError(f"{name} boxes must have shape (K, {d}, 2), got {b.shape}")
        boxes[name] = b
    height = None if d == 2 else (0.5 * (region[2, 0] + region[2, 1]) if z is None else float(z))
    axes = axes_2d(ax, "a certified workspace")
    for name, colour in (("inner", INSIDE), ("undecided", UNDECIDED)):
        r = _at_height(boxes[name], height)
        corners = np.stack(
            [r[:, :, 0], np.stack([r[:, 0, 1], r[:, 1, 0]], -1), r[:, :, 1], np.stack([r[:, 0, 0], r[:, 1, 1]], -1)], 1
        )
        axes.add_collection(
            PolyCollection(list(corners), facecolors=colour, edgecolors="none", zorder=0, gid=f"certified-{name}")
        )
    if grid is not None:
        poses = np.asarray(grid.poses, float)
        inside = np.asarray(grid.inside, bool).ravel()
        axes.scatter(poses[inside, 0], poses[inside, 1], s=2, c="k", zorder=2, gid="grid-inside")
        axes.scatter(
            poses[~inside, 0],
            poses[~inside, 1],
            s=2,
            facecolors="none",
            edgecolors="k",
            linewidths=0.3,
            zorder=2,
            gid="grid-outside",
        )
    lo, hi = region[:2, 0].copy(), region[:2, 1].copy()
    if robot is not None:
        draw_scene_2d(robot, axes)
        exits = np.asarray(robot.exits, float)[:, :2]
        lo, hi = np.minimum(lo, exits.min(axis=0)), np.maximum(hi, exits.max(axis=0))
    pad = 0.03 * (hi - lo)
    axes.set_xlim(lo[0] - pad[0], hi[0] + pad[0])
    axes.set_ylim(lo[1] - pad[1], hi[1] + pad[1])
    axes.set_aspect("equal")
    unit = "m²" if d == 2 else "m³"
    title = (
        f"{result.condition} workspace, certified: inner {result.inner_volume:.4g} {unit}, "
        f"undecided {result.undecided_volume:.4g} {unit}"
    )
    if height is not None:
        title += f"\nslice z = {height:.3g} m"
    axes.set_title(title, fontsize=10)
    axes.legend(
        handles=[Patch(color=INSIDE, label="inner (proven inside)"), Patch(color=UNDECIDED, label="undecided")],
        loc="upper right",
        fontsize=8,
    )
    return axes
