"""Pose grids for workspace evaluation by discretisation (Rushton (2022)
§2.1.4: "discretizing the installation space into a grid of end effector poses and
testing each one").

A :class:`PoseGrid` is a Cartesian product of 1-D axes over some pose coordinates, the
other coordinates being held fixed: either a *position grid* (x, y[, z] gridded, the
orientation and joint coordinates fixed — a constant-orientation workspace) or a *full
pose grid* (every pose coordinate gridded).  Poses are listed in C order, so that
``inside.reshape(grid.shape)`` indexes ``[ix, iy(, iz)]``.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import numbers
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from taut.errors import TautError
from taut.model.robot import Robot

__all__ = ["PoseGrid", "default_bounds", "default_orientation", "make_grid", "pose_grid", "position_grid"]

#: Default points per axis: planar (2-D) and spatial (3-D) position grids.
DEFAULT_RESOLUTION = {2: 101, 3: 41}
#: The default bounds are the box of the exit points shrunk by this fraction of its size per side.
DEFAULT_SHRINK = 0.02


@dataclass(frozen=True)
class PoseGrid:
    """Axes ``axes[i]`` over the pose coordinates ``index[i]``; every other coordinate
    takes its value in ``fixed`` (a full pose of which the gridded entries are ignored)."""

    axes: tuple[np.ndarray, ...]
    index: tuple[int, ...]
    fixed: np.ndarray
    names: tuple[str, ...] = ()

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(a) for a in self.axes)

    @property
    def size(self) -> int:
        return int(np.prod(self.shape, dtype=np.int64))

    def poses(self, start: int = 0, stop: int | None = None) -> np.ndarray:
        """Poses ``start:stop`` of the grid (all by default), ``(K, pose_size)``, C order."""
        stop = self.size if stop is None else min(stop, self.size)
        flat = np.arange(start, stop)
        out = np.repeat(self.fixed[None, :], flat.size, axis=0)
        for col, axis, idx in zip(self.index, self.axes, np.unravel_index(flat, self.shape)):
            out[:, col] = axis[idx]
        return out

    def cell_measure(self) -> float:
        """Product of the axis spacings (axes with one point count as 1)."""
        out = 1.0
        for a in self.axes:
            if len(a) > 1:
                out *= float(a[-1] - a[0]) / (len(a) - 1)
        return abs(out)


def default_bounds(robot: Robot, shrink: float = DEFAULT_SHRINK) -> np.ndarray:
    """``(d, 2)`` bounds: the bounding box of the exit points, shrunk by ``shrink`` of its
    size on each side.  An axis along which all exits are level (a suspended robot with
    coplanar exits) spans ``[c − E, c + E]``, ``E`` half the largest extent."""
    lo, hi = robot.exits.min(axis=0), robot.exits.max(axis=0)
    ext = hi - lo
    big = float(ext.max()) if ext.size else 0.0
    if big == 0.0:
        big = 2.0
    flat = ext <= 1e-9 * big
    c = (lo + hi) / 2
    lo = np.where(flat, c - big / 2, lo + shrink * ext)
    hi = np.where(flat, c + big / 2, hi - shrink * ext)
    return np.stack([lo, hi], axis=1)


def default_orientation(robot: Robot) -> np.ndarray:
    """Zero orientation and joints at mid-range: the pose coordinates after the position."""
    tail = np.zeros(robot.pose_size - robot.dimension)
    if robot.n_joints:
        tail[robot.wrench_dim - robot.dimension :] = robot.joint_limits.mean(axis=1)
    return tail


def _orientation(robot: Robot, orientation) -> np.ndarray:
    k = robot.pose_size - robot.dimension
    if orientation is None:
        return default_orientation(robot)
    o = np.atleast_1d(np.asarray(orientation, dtype=float))
    if o.ndim != 1 or o.size != k:
        names = ", ".join(robot.pose_names[robot.dimension :]) or "none"
        raise TautError(f"{robot.name}: the fixed orientation has {k} coordinates ({names}), got {o.size}")
    if not np.all(np.isfinite(o)):
        raise TautError(f"{robot.name}: the fixed orientation must be finite, got {o.tolist()}")
    return o


def _axis(spec, what: str) -> np.ndarray:
    """``(lo, hi, n)`` as a tuple, or explicit coordinates (list / array)."""
    if isinstance(spec, tuple) and len(spec) == 3:
        lo, hi, n = spec
        if not isinstance(n, numbers.Real) or not np.isfinite(n) or float(n) != int(n) or int(n) < 1:
            raise TautError(f"{what}: the number of points must be a positive integer, got {n!r}")
        if not (np.isfinite(lo) and np.isfinite(hi)):
            raise TautError(f"{what}: the bounds must be finite, got {lo!r}, {hi!r}")
        if lo > hi:
            raise TautError(f"{what}: inverted bounds {lo} > {hi}")
        return np.linspace(float(lo), float(hi), int(n))
    a = np.asarray(spec, dtype=float)
    if a.ndim != 1 or a.size == 0 or not np.all(np.isfinite(a)):
        raise TautError(f"{what}: expected (lo, hi, n) or a 1-D array of finite coordinates, got {spec!r}")
    return a


def position_grid(robot: Robot, resolution: int | None = None, bounds=None, orientation=None) -> PoseGrid:
    """Grid over the position (x, y[, z]) with ``resolution`` points per axis between
    ``bounds`` ``(d, 2)`` (default :func:`default_bounds`), at a fixed ``orientation``
    (the pose coordinates after the position; default :func:`default_orientation`)."""
    d = robot.dimension
    res = DEFAULT_RESOLUTION[d] if resolution is None else resolution
    if isinstance(res, bool) or not isinstance(res, numbers.Integral) or res < 1:
        raise TautError(f"resolution must be a positive integer, got {resolution!r}")
    b = default_bounds(robot) if bounds is None else np.asarray(bounds, dtype=float)
    if b.shape != (d, 2):
        raise TautError(f"{robot.name}: bounds must have shape ({d}, 2), got {b.shape}")
    axes = tuple(_axis((float(lo), float(hi), int(res)), f"axis {robot.pose_names[i]}") for i, (lo, hi) in enumerate(b))
    fixed = np.concatenate([np.zeros(d), _orientation(robot, orientation)])
    return PoseGrid(axes, tuple(range(d)), fixed, tuple(robot.pose_names[:d]))


def pose_grid(robot: Robot, axes: Sequence) -> PoseGrid:
    """Full pose grid: one axis (``(lo, hi, n)`` tuple or coordinates) per pose coordinate."""
    if len(axes) != robot.pose_size:
        raise TautError(
            f"{robot.name}: a full pose grid needs {robot.pose_size} axes ({', '.join(robot.pose_names)}), got {len(axes)}"
        )
    arr = tuple(_axis(a, f"axis {robot.pose_names[i]}") for i, a in enumerate(axes))
    return PoseGrid(arr, tuple(range(robot.pose_size)), np.zeros(robot.pose_size), tuple(robot.pose_names))


def make_grid(robot: Robot, grid=None, resolution: int | None = None, orientation=None) -> PoseGrid:
    """Normalise the ``grid`` argument of :func:`taut.workspace.evaluate_workspace`:

    ``None`` — :func:`position_grid` with ``resolution`` and ``orientation``; a
    :class:`PoseGrid` — used as is; a sequence of one axis per position coordinate
    (``(lo, hi, n)`` tuples or coordinate arrays) — a position grid at ``orientation``;
    one axis per pose coordinate — a full pose grid."""
    if grid is None:
        return position_grid(robot, resolution, orientation=orientation)
    if isinstance(grid, PoseGrid):
        return grid
    if isinstance(grid, (str, bytes)) or not isinstance(grid, Sequence) and not isinstance(grid, np.ndarray):
        raise TautError(f"grid must be a PoseGrid or a sequence of axes, got {type(grid).__name__}")
    d = robot.dimension
    if len(grid) == d:
        axes = tuple(_axis(a, f"axis {robot.pose_names[i]}") for i, a in enumerate(grid))
        fixed = np.concatenate([np.zeros(d), _orientation(robot, orientation)])
        return PoseGrid(axes, tuple(range(d)), fixed, tuple(robot.pose_names[:d]))
    if len(grid) == robot.pose_size:
        if orientation is not None:
            raise TautError("a full pose grid grids the orientation too: do not give a fixed orientation")
        return pose_grid(robot, grid)
    raise TautError(
        f"{robot.name}: grid needs {d} position axes or {robot.pose_size} pose axes ({', '.join(robot.pose_names)}), got {len(grid)}"
    )
