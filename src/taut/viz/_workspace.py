"""Workspace figure: :func:`plot_workspace` for a grid ``WorkspaceResult``.

Planar grids (two position axes) are drawn as an image of the inside mask over x–y
(inside green, outside light grey), with the robot's fixed parts overlaid (exit points
with cable numbers, frame outline, obstacles, installation space, disallowed regions);
this is the look of the approximate workspaces of Rushton (2022)
(Figs. 5.9 c, 6.5, 6.12) and of the constant-orientation WFW slice of
Berti (2015) (Fig. 4.4).  A spatial grid with one axis of a single value
is such a slice too.  Full spatial grids are a 3-D scatter of the inside poses (randomly
subsampled, with a fixed seed, beyond ``max_points``), coloured by height, over the exit
points.  The title names the condition and the inside fraction.

The result is duck-typed (:class:`GridWorkspace`): anything with ``condition``,
``poses (N, pose_size)``, ``inside (N,)``, ``axes`` (1-D coordinates per position axis) and
``grid_shape`` (``inside.reshape(grid_shape)`` in C order, axes x, y[, z]) is drawn;
``fraction`` is used when present.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Figs. 5.9c, 6.5, 6.12. (docs/references.bib: rushton2022)
.. [2] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, Fig. 4.4. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Protocol

import numpy as np

from taut._checks import as_array
from taut.errors import ArgumentError
from taut.model import Robot
from taut.viz._robot import draw_scene_2d, draw_scene_3d, scene_points_3d
from taut.viz._style import INSIDE, OUTSIDE, axes_2d, axes_3d, set_equal_3d

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from mpl_toolkits.mplot3d.axes3d import Axes3D

__all__ = ["GridWorkspace", "plot_workspace"]


class GridWorkspace(Protocol):
    """What :func:`plot_workspace` reads of a grid workspace result (such as
    :class:`taut.workspace.WorkspaceResult`)."""

    @property
    def condition(self) -> str: ...

    @property
    def poses(self) -> np.ndarray: ...

    @property
    def inside(self) -> np.ndarray: ...

    @property
    def axes(self) -> Sequence[np.ndarray]: ...

    @property
    def grid_shape(self) -> Sequence[int]: ...


_AXIS_NAMES = ("x", "y", "z")


def _fixed_coordinates(result: GridWorkspace, robot: Robot | None, used: list[int]) -> str:
    """'theta=0' for pose coordinates that are the same at every grid pose (orientation
    of a constant-orientation workspace, the held coordinate of a slice)."""
    grid = getattr(result, "grid", None)
    if grid is not None:  # a grid result does not hold its poses: the grid's box bounds them
        lo, hi = grid.corners()
    else:
        poses = np.asarray(result.poses, float)
        if poses.ndim != 2 or not len(poses):
            return ""
        lo, hi = poses.min(axis=0), poses.max(axis=0)
    names = (
        list(robot.pose_names)
        if robot is not None and len(robot.pose_names) == lo.size
        else [(_AXIS_NAMES[j] if j < len(result.axes) else f"q{j + 1}") for j in range(lo.size)]
    )
    return ", ".join(f"{names[j]}={lo[j]:.3g}" for j in range(lo.size) if j not in used and lo[j] == hi[j])


def _edges(c: np.ndarray) -> tuple[float, float]:
    c = np.asarray(c, float)
    if len(c) == 1:
        return c[0] - 0.5, c[0] + 0.5
    h = (c[-1] - c[0]) / (len(c) - 1) / 2
    return c[0] - h, c[-1] + h


def plot_workspace(
    result: GridWorkspace, robot: Robot | None = None, ax: Axes | None = None, *, max_points: int = 4000
) -> Axes:
    """Draw a grid workspace result (see the module docstring) on ``ax``; return that ``Axes``.

    ``robot`` (optional) overlays its fixed parts.  A planar result (or a slice) is drawn on
    2-D axes, a full spatial one on 3-D axes (an ``Axes3D``, ``projection="3d"``);
    ``ax=None`` makes a new figure with axes of the right kind, axes of the other kind raise
    :class:`~taut.errors.ArgumentError`, as does a result whose arrays do not match its
    ``grid_shape``."""
    shape = tuple(int(s) for s in result.grid_shape)
    inside = np.asarray(result.inside, bool).ravel()
    coords = [as_array(a, "workspace grid axes", finite=False, error=ArgumentError) for a in result.axes]
    if len(coords) != len(shape) or len(shape) not in (2, 3):
        raise ArgumentError(f"plot_workspace draws 2- or 3-axis grids, got grid_shape {shape} with {len(coords)} axes")
    if inside.size != int(np.prod(shape)):
        raise ArgumentError(f"inside has {inside.size} values, grid_shape {shape} needs {int(np.prod(shape))}")
    n_in, total = int(inside.sum()), inside.size
    fraction = float(getattr(result, "fraction", n_in / total if total else 0.0))
    mask = inside.reshape(shape)
    keep = [j for j, s in enumerate(shape) if s > 1] if len(shape) == 3 else [0, 1]
    drawn: Axes
    if len(shape) == 3 and len(keep) == 3:
        drawn = _scatter(result, robot, axes_3d(ax, "a spatial workspace"), mask, coords, max_points)
        shown = min(n_in, max_points)
        extra = f", {shown} shown" if shown < n_in else ""
    else:
        if len(keep) < 2:  # a line or a point of a spatial grid: show its first two axes
            keep = [j for j in range(3) if j not in keep][: 2 - len(keep)] + keep
            keep.sort()
        drawn = _image(robot, axes_2d(ax, "a planar workspace (or a slice)"), mask, coords, keep)
        extra = ""
    held = _fixed_coordinates(result, robot, keep)
    title = f"{result.condition} workspace: {n_in} of {total} grid poses ({100 * fraction:.1f} %{extra})"
    if held:
        title += f"\nat {held}"
    drawn.set_title(title, fontsize=10)
    return drawn


def _image(robot: Robot | None, ax: Axes, mask: np.ndarray, coords: list[np.ndarray], keep: list[int]) -> Axes:
    from matplotlib.colors import ListedColormap
    from matplotlib.patches import Patch

    img = mask
    if img.ndim == 3:
        drop = next(j for j in range(3) if j not in keep)
        img = np.take(img, 0, axis=drop)
    i, j = keep
    xe, ye = _edges(coords[i]), _edges(coords[j])
    ax.imshow(
        img.T.astype(float),
        origin="lower",
        extent=(*xe, *ye),
        cmap=ListedColormap([OUTSIDE, INSIDE]),
        vmin=0,
        vmax=1,
        interpolation="nearest",
        aspect="equal",
        zorder=0,
        gid="workspace",
    )
    if robot is not None and robot.dimension == 2 and keep == [0, 1]:
        draw_scene_2d(robot, ax)
        ax.margins(0.05)
        ax.autoscale_view()
    ax.set_aspect("equal")
    ax.set_xlabel(f"{_AXIS_NAMES[i]} [m]")
    ax.set_ylabel(f"{_AXIS_NAMES[j]} [m]")
    ax.legend(
        handles=[Patch(fc=INSIDE, label="inside"), Patch(fc=OUTSIDE, ec="#bbbbbb", label="outside")],
        fontsize=8,
        loc="upper left",
        bbox_to_anchor=(1.02, 1.0),
        borderaxespad=0.0,
    )
    return ax


def _scatter(
    result: GridWorkspace,
    robot: Robot | None,
    ax: Axes3D,
    mask: np.ndarray,
    coords: list[np.ndarray],
    max_points: int,
) -> Axes3D:
    idx = np.flatnonzero(mask.ravel())
    if len(idx) > max_points:
        idx = idx[np.sort(np.random.default_rng(0).choice(len(idx), max_points, replace=False))]
    if hasattr(result, "poses_at"):  # computes the drawn poses only (a grid result holds none)
        pts = np.asarray(result.poses_at(idx), float)[:, :3]
    else:
        poses = np.asarray(result.poses, float)
        if poses.ndim == 2 and poses.shape[0] == mask.size and poses.shape[1] >= 3:
            pts = poses[idx, :3]
        else:  # positions from the grid axes
            pts = np.column_stack([c[i] for c, i in zip(coords, np.unravel_index(idx, mask.shape))])
    ax.scatter(
        pts[:, 0], pts[:, 1], pts[:, 2], c=pts[:, 2], cmap="viridis", s=5, alpha=0.45, depthshade=False, gid="workspace"
    )
    bounds = np.array([[c.min(), c.max()] for c in coords]).T
    drawn = [bounds]
    if robot is not None and robot.dimension == 3:
        draw_scene_3d(robot, ax)
        drawn.append(scene_points_3d(robot))
    set_equal_3d(ax, np.concatenate(drawn))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    return ax
