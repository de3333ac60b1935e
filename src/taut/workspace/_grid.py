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

import math
import numbers
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.errors import GridSizeError, TautError
from taut.model import Robot

__all__ = [
    "MAX_GRID_POSES",
    "PoseGrid",
    "check_grid_size",
    "default_bounds",
    "default_orientation",
    "format_bytes",
    "make_grid",
    "pose_grid",
    "position_grid",
]

#: One axis of a grid: ``(lo, hi, n)`` (``n`` evenly spaced points) or explicit coordinates.
AxisSpec = tuple[float, float, int] | npt.ArrayLike

#: Default points per axis: planar (2-D) and spatial (3-D) position grids.
DEFAULT_RESOLUTION = {2: 101, 3: 41}
#: Most poses a grid may have: the verdicts take one byte per pose (1 GiB at the limit).
MAX_GRID_POSES = 2**30
#: The default bounds are the box of the exit points shrunk by this fraction of its size per side.
DEFAULT_SHRINK = 0.02


def format_bytes(n: int) -> str:
    """``n`` bytes in binary units (``"3 GiB"``), for messages."""
    size = float(n)
    units = ("B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB", "ZiB", "YiB")
    for unit in units[:-1]:
        if size < 1024:
            return f"{size:.3g} {unit}"
        size /= 1024
    return f"{size:.3g} {units[-1]}"


def check_grid_size(counts: Sequence[int], pose_size: int) -> int:
    """The number of poses of a grid of ``counts`` points per axis; a
    :class:`~taut.errors.GridSizeError` above :data:`MAX_GRID_POSES`, before anything
    is allocated (the verdicts take one byte per pose)."""
    n = math.prod(int(c) for c in counts)
    if n > MAX_GRID_POSES:
        shape = " × ".join(f"{int(c):,}" for c in counts)
        raise GridSizeError(
            f"the grid has {n:,} poses ({shape}): their verdicts alone would need {format_bytes(n)} "
            f"(the poses {format_bytes(n * pose_size * 8)}); at most {MAX_GRID_POSES:,} poses are evaluated, "
            "give fewer points per axis"
        )
    return n


@dataclass(frozen=True)
class PoseGrid(Result):
    """A Cartesian grid of poses: axes over some pose coordinates, the others held fixed.

    The poses are never stored: :meth:`poses_at` computes any of them from its flat index
    (C order), so that a grid of any size is evaluated chunk by chunk in bounded memory.

    Attributes
    ----------
    axes : tuple of ndarray
        The coordinates of each gridded axis.
    index : tuple of int
        The pose coordinate of each axis (0-based).
    fixed : ndarray, shape (pose_size,)
        A full pose: the coordinates that are not gridded take their values here (its gridded
        entries are ignored).
    names : tuple of str
        The axes' coordinate names.

    Raises
    ------
    TautError
        Not one pose coordinate per axis.
    GridSizeError
        More than :data:`MAX_GRID_POSES` poses.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import position_grid
    >>> grid = position_grid(example("planar-4cable"), resolution=5)
    >>> grid.shape, grid.size, grid.names
    ((5, 5), 25, ('x', 'y'))
    >>> grid.poses_at([0, 24])
    array([[-0.96, -0.96,  0.  ],
           [ 0.96,  0.96,  0.  ]])
    """

    axes: tuple[np.ndarray, ...]
    index: tuple[int, ...]
    fixed: np.ndarray
    names: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if len(self.axes) != len(self.index):
            raise TautError(
                f"a pose grid needs one pose coordinate per axis, got {len(self.axes)} axes, index {self.index}"
            )
        check_grid_size(self.shape, np.size(self.fixed))
        super().__post_init__()

    @property
    def shape(self) -> tuple[int, ...]:
        """The number of points of each axis."""
        return tuple(len(a) for a in self.axes)

    @property
    def size(self) -> int:
        """The number of poses."""
        return math.prod(self.shape)

    @property
    def pose_size(self) -> int:
        """The number of coordinates of a pose."""
        return int(np.size(self.fixed))

    def poses_at(self, flat: npt.ArrayLike) -> np.ndarray:
        """The poses of flat (C-order) indices.

        Parameters
        ----------
        flat : array_like of int, shape (K,)
            Indices in ``[0, size)``.

        Returns
        -------
        ndarray, shape (K, pose_size)

        Raises
        ------
        TautError
            Indices that are not integers or out of range.
        """
        flat = flat_indices(flat, self.size)
        out = np.repeat(np.asarray(self.fixed, dtype=float)[None, :], flat.size, axis=0)
        for col, axis, idx in zip(self.index, self.axes, np.unravel_index(flat, self.shape)):
            out[:, col] = axis[idx]
        return out

    def poses(self, start: int = 0, stop: int | None = None) -> np.ndarray:
        """The poses ``start:stop`` of the grid (all by default), in C order.

        Parameters
        ----------
        start, stop : int, optional
            Flat indices, non-negative; ``stop`` beyond the grid's size means its end.

        Returns
        -------
        ndarray, shape (K, pose_size)

        Raises
        ------
        TautError
            ``start`` or ``stop`` not a non-negative integer.
        """
        for value in (start, stop):
            if value is not None and (isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < 0):
                raise TautError(f"start and stop must be non-negative integers, got {start!r}, {stop!r}")
        stop = self.size if stop is None else min(stop, self.size)
        return self.poses_at(np.arange(start, stop, dtype=np.int64))

    def corners(self) -> np.ndarray:
        """The box every pose of the grid lies in.

        Returns
        -------
        ndarray, shape (2, pose_size)
            The fixed pose with every gridded coordinate at its axis' least (row 0) and
            greatest (row 1) value.
        """
        out = np.repeat(np.asarray(self.fixed, dtype=float)[None, :], 2, axis=0)
        for col, axis in zip(self.index, self.axes):
            out[:, col] = (np.min(axis), np.max(axis)) if len(axis) else (np.nan, np.nan)
        return out


def flat_indices(flat: npt.ArrayLike, size: int) -> np.ndarray:
    """``flat`` as a 1-D array of indices of a grid of ``size`` poses, each in ``[0, size)``."""
    try:
        idx = np.asarray(flat)
    except (TypeError, ValueError):
        raise TautError(f"pose indices must be integers, got {flat!r}") from None
    if idx.size and idx.dtype.kind not in "iu":
        raise TautError(f"pose indices must be integers, got {flat!r}")
    idx = idx.astype(np.int64).ravel()
    if idx.size and (idx.min() < 0 or idx.max() >= size):
        raise TautError(f"pose indices must lie in [0, {size}), got {idx.min()} … {idx.max()}")
    return idx


def default_bounds(robot: Robot, *, shrink: float = DEFAULT_SHRINK) -> np.ndarray:
    """The default bounds of a position grid: the box of the exit points, slightly shrunk.

    An axis along which all exits are level (a suspended robot with coplanar exits) spans
    ``[c − E, c + E]``, ``E`` half the largest extent.

    Parameters
    ----------
    robot : Robot
    shrink : float, optional
        The fraction of the box's size cut from each side, in ``[0, 0.5)``.

    Returns
    -------
    ndarray, shape (d, 2)
        ``[lo, hi]`` of each position coordinate [m].

    Raises
    ------
    TautError
        ``shrink`` not a number in ``[0, 0.5)``.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import default_bounds
    >>> default_bounds(example("planar-4cable"))  # exits at ±1 m, 2 % of 2 m cut per side
    array([[-0.96,  0.96],
           [-0.96,  0.96]])
    """
    if isinstance(shrink, bool) or not isinstance(shrink, numbers.Real) or not 0 <= shrink < 0.5:
        raise TautError(f"shrink must be a number in [0, 0.5), got {shrink!r}")
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


def _orientation(robot: Robot, orientation: npt.ArrayLike | None) -> np.ndarray:
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


def _axis_count(spec: AxisSpec, what: str) -> int:
    """The number of points of an axis spec, validated without building the axis."""
    if isinstance(spec, tuple) and len(spec) == 3:
        lo, hi, n = spec
        if isinstance(n, bool) or not isinstance(n, numbers.Real) or not np.isfinite(float(n)):
            raise TautError(f"{what}: the number of points must be a positive integer, got {n!r}")
        if float(n) != int(float(n)) or int(float(n)) < 1:
            raise TautError(f"{what}: the number of points must be a positive integer, got {n!r}")
        if not (np.isfinite(lo) and np.isfinite(hi)):
            raise TautError(f"{what}: the bounds must be finite, got {lo!r}, {hi!r}")
        if lo > hi:
            raise TautError(f"{what}: inverted bounds {lo} > {hi}")
        return int(float(n))
    a = np.asarray(spec, dtype=float)
    if a.ndim != 1 or a.size == 0 or not np.all(np.isfinite(a)):
        raise TautError(f"{what}: expected (lo, hi, n) or a 1-D array of finite coordinates, got {spec!r}")
    return int(a.size)


def _axes(robot: Robot, specs: Sequence[AxisSpec]) -> tuple[np.ndarray, ...]:
    """The axes of ``specs`` (one per leading pose coordinate), the grid's size checked
    before any axis is built."""
    counts = [_axis_count(spec, f"axis {robot.pose_names[i]}") for i, spec in enumerate(specs)]
    check_grid_size(counts, robot.pose_size)
    out = []
    for spec, n in zip(specs, counts):
        if isinstance(spec, tuple) and len(spec) == 3:
            out.append(np.linspace(float(spec[0]), float(spec[1]), n))
        else:
            out.append(np.asarray(spec, dtype=float))
    return tuple(out)


def position_grid(
    robot: Robot,
    *,
    resolution: int | None = None,
    bounds: npt.ArrayLike | None = None,
    orientation: npt.ArrayLike | None = None,
) -> PoseGrid:
    """A grid over the position at a fixed orientation: a constant-orientation workspace.

    Parameters
    ----------
    robot : Robot
    resolution : int, optional
        Points per axis; default 101 (planar) or 41 (spatial).
    bounds : array_like, shape (d, 2), optional
        ``[lo, hi]`` of each position coordinate [m]; default :func:`default_bounds`.
    orientation : array_like, shape (pose_size − d,), optional
        The pose coordinates after the position (angles [rad], joint coordinates); default
        zero angles and the joints at mid-range.

    Returns
    -------
    PoseGrid

    Raises
    ------
    TautError
        A resolution that is not a positive integer, bounds or orientation of the wrong shape
        or not finite.
    GridSizeError
        More than :data:`MAX_GRID_POSES` poses.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import position_grid
    >>> grid = position_grid(example("planar-4cable"), resolution=3, bounds=[[-0.5, 0.5], [0, 0.2]], orientation=[0.1])
    >>> grid.shape, grid.poses(0, 2)
    ((3, 3), array([[-0.5,  0. ,  0.1],
           [-0.5,  0.1,  0.1]]))
    """
    d = robot.dimension
    res = DEFAULT_RESOLUTION[d] if resolution is None else resolution
    if isinstance(res, bool) or not isinstance(res, numbers.Integral) or res < 1:
        raise TautError(f"resolution must be a positive integer, got {resolution!r}")
    try:
        b = default_bounds(robot) if bounds is None else np.asarray(bounds, dtype=float)
    except (TypeError, ValueError):
        raise TautError(f"{robot.name}: bounds must be numbers, got {bounds!r}") from None
    if b.shape != (d, 2):
        raise TautError(f"{robot.name}: bounds must have shape ({d}, 2), got {b.shape}")
    axes = _axes(robot, [(float(lo), float(hi), int(res)) for lo, hi in b])
    fixed = np.concatenate([np.zeros(d), _orientation(robot, orientation)])
    return PoseGrid(axes, tuple(range(d)), fixed, tuple(robot.pose_names[:d]))


def pose_grid(robot: Robot, axes: Sequence[AxisSpec]) -> PoseGrid:
    """A grid over every pose coordinate.

    Parameters
    ----------
    robot : Robot
    axes : sequence
        One axis per pose coordinate: ``(lo, hi, n)`` (``n`` evenly spaced points) or an
        array of coordinates.

    Returns
    -------
    PoseGrid

    Raises
    ------
    TautError
        Not one valid axis per pose coordinate.
    GridSizeError
        More than :data:`MAX_GRID_POSES` poses.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import pose_grid
    >>> grid = pose_grid(example("planar-4cable"), [(-0.5, 0.5, 3), (-0.5, 0.5, 3), (0.0, 0.2, 2)])
    >>> grid.shape, grid.poses_at([17])
    ((3, 3, 2), array([[0.5, 0.5, 0.2]]))
    """
    if isinstance(axes, (str, bytes)) or not isinstance(axes, (Sequence, np.ndarray)):
        raise TautError(f"axes must be a sequence of one axis per pose coordinate, got {axes!r}")
    if len(axes) != robot.pose_size:
        raise TautError(
            f"{robot.name}: a full pose grid needs {robot.pose_size} axes ({', '.join(robot.pose_names)}), got {len(axes)}"
        )
    return PoseGrid(
        _axes(robot, axes), tuple(range(robot.pose_size)), np.zeros(robot.pose_size), tuple(robot.pose_names)
    )


def make_grid(
    robot: Robot,
    grid: PoseGrid | Sequence[AxisSpec] | np.ndarray | None = None,
    *,
    resolution: int | None = None,
    orientation: npt.ArrayLike | None = None,
) -> PoseGrid:
    """The grid of the ``grid`` argument of :func:`~taut.workspace.evaluate_workspace`.

    Parameters
    ----------
    robot : Robot
    grid : PoseGrid or sequence, optional
        ``None``: :func:`position_grid` with ``resolution`` and ``orientation``; a
        :class:`PoseGrid`: used as is; one axis per position coordinate (``(lo, hi, n)`` or
        coordinates): a position grid at ``orientation``; one axis per pose coordinate: a
        full pose grid (:func:`pose_grid`).
    resolution : int, optional
        Points per axis of the default position grid.
    orientation : array_like, optional
        The fixed coordinates after the position (not with a full pose grid).

    Returns
    -------
    PoseGrid

    Raises
    ------
    TautError
        A grid of neither form, or an orientation with a full pose grid.
    GridSizeError
        More than :data:`MAX_GRID_POSES` poses, before the grid is built.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import make_grid
    >>> grid = make_grid(example("planar-4cable"), [(-0.5, 0.5, 3), (0, 0.2, 2)], orientation=[0.1])
    >>> grid.shape, grid.fixed
    ((3, 2), array([0. , 0. , 0.1]))
    """
    if grid is None:
        return position_grid(robot, resolution=resolution, orientation=orientation)
    if isinstance(grid, PoseGrid):
        return grid
    if isinstance(grid, (str, bytes)) or not isinstance(grid, (Sequence, np.ndarray)):
        raise TautError(f"grid must be a PoseGrid or a sequence of axes, got {type(grid).__name__}")
    specs: list[AxisSpec] = list(grid)
    d = robot.dimension
    if len(specs) == d:
        fixed = np.concatenate([np.zeros(d), _orientation(robot, orientation)])
        return PoseGrid(_axes(robot, specs), tuple(range(d)), fixed, tuple(robot.pose_names[:d]))
    if len(specs) == robot.pose_size:
        if orientation is not None:
            raise TautError("a full pose grid grids the orientation too: do not give a fixed orientation")
        return pose_grid(robot, specs)
    raise TautError(
        f"{robot.name}: grid needs {d} position axes or {robot.pose_size} pose axes ({', '.join(robot.pose_names)}), got {len(specs)}"
    )
