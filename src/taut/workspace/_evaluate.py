"""Grid evaluation of a workspace condition (Rushton 2022, §2.1.4): the
poses of a :class:`~taut.workspace.PoseGrid` are split into chunks of flat indices,
each chunk's poses are generated where it is evaluated (in one vectorised call of the
condition), and the chunks are mapped over an executor of :mod:`taut.parallel` (serial,
local processes or dask.distributed — the verdicts are identical whatever the executor
and the chunk size).  Only the verdicts are kept, one byte per pose, so that the memory
does not grow with the pose size: a grid of 64 M six-coordinate poses needs its 64 MB of
verdicts, where the array of its poses would need 2.9 GiB.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.errors import GridSizeError, PoseError, TautError
from taut.kinematics import as_poses, obstacles_met
from taut.model import Robot
from taut.parallel import Executor, as_executor
from taut.statics import WrenchSet
from taut.workspace._conditions import WorkspaceCondition, make_condition
from taut.workspace._grid import MAX_GRID_POSES, AxisSpec, PoseGrid, flat_indices, format_bytes, make_grid

__all__ = ["DEFAULT_CHUNK", "MAX_POSES", "MAX_POSE_ARRAY_BYTES", "WorkspaceResult", "evaluate_workspace"]

#: Poses per chunk: large enough to amortise the per-call overhead, small enough to bound memory.
DEFAULT_CHUNK = 16384
#: Numbers one chunk's evaluation holds (16 MiB; :meth:`WorkspaceCondition.numbers_per_pose`:
#: the structure matrices, or the capsule pairs' distances): a robot with many cables gets
#: fewer poses per chunk (174 for 2000 cables in 6-D, one for their 2 million capsule pairs),
#: so that its memory stays bounded and its progress is reported as often.
CHUNK_ELEMENTS = 1 << 21
#: Poses handed to the executor per call of its ``map``: the verdicts of one such batch are
#: the only per-chunk results held at once before they are copied into the result.
BATCH_POSES = 1 << 22
#: Poses :func:`evaluate_workspace` evaluates when no ``max_poses`` is given: a budget of
#: minutes (10 µs a pose for the wrench closure of 8 cables in 6-D, on one core), where
#: :data:`~taut.workspace._grid.MAX_GRID_POSES` bounds the memory of the verdicts.
MAX_POSES = 10_000_000
#: Largest ``(N, pose_size)`` float array that :attr:`WorkspaceResult.poses` materialises.
MAX_POSE_ARRAY_BYTES = 1 << 30
#: Format tag of the files written by :meth:`WorkspaceResult.save`.
FILE_FORMAT = "taut-workspace/2"


@dataclass(frozen=True)
class WorkspaceResult(Result):
    """The verdicts of a workspace condition over a grid of poses (:func:`evaluate_workspace`).

    Only the verdicts ``inside`` (one byte per pose) are stored: the poses of a grid are
    recomputed from ``grid`` on demand (:attr:`poses`, :meth:`poses_at`), so that a grid of
    hundreds of millions of poses fits in memory.

    Attributes
    ----------
    robot_name : str
    condition : str
        The condition's registry name.
    inside : ndarray of bool, shape (N,)
        The verdict of each pose, in the C order of the grid.
    axes : tuple of ndarray
        The coordinates of each gridded axis (position axes first); empty for explicit poses.
    grid_shape : tuple of int
        ``inside.reshape(grid_shape)`` indexes the grid's axes; ``(N,)`` for explicit poses.
    elapsed_s : float
        Wall-clock seconds of the evaluation.
    axis_names : tuple of str
        The gridded coordinates' names.
    grid : PoseGrid or None
        The grid the poses come from.
    explicit_poses : ndarray, shape (N, pose_size), or None
        The poses given as an array (then ``grid`` is None).
    complete : bool
        Every pose has its verdict.
    wrapped : int
        Poses left outside because a cable, taken as a straight line, meets an obstacle of a
        variable-structure robot there (:func:`~taut.kinematics.obstacles_met`): the cable
        wraps around it and the straight-cable condition does not hold.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import evaluate_workspace
    >>> res = evaluate_workspace(example("planar-4cable"), "static", resolution=21)
    >>> res.count, res.size, res.as_dict()["grid_shape"]
    (330, 441, [21, 21])
    """

    robot_name: str
    condition: str
    inside: np.ndarray  #: ``(N,)`` bool
    axes: tuple[np.ndarray, ...]  #: grid coordinates per gridded axis (position axes first)
    grid_shape: tuple[int, ...]  #: ``inside.reshape(grid_shape)`` in C order
    elapsed_s: float  #: wall-clock seconds of the evaluation
    axis_names: tuple[str, ...] = field(default=())
    grid: PoseGrid | None = None  #: the grid the poses come from
    explicit_poses: np.ndarray | None = None  #: ``(N, pose_size)`` poses given as an array
    complete: bool = True  #: every pose of the grid has its verdict
    wrapped: int = 0  #: poses left outside because a straight cable meets an obstacle there

    @property
    def size(self) -> int:
        """Number of poses evaluated."""
        return int(self.inside.size)

    def poses_at(self, flat: npt.ArrayLike) -> np.ndarray:
        """The poses of flat indices (C order of the grid).

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
            Indices out of range, or a result that holds no poses.
        """
        idx = flat_indices(flat, self.size)
        if self.explicit_poses is not None:
            return self.explicit_poses[idx]
        if self.grid is None:
            raise TautError("this workspace result holds no poses (neither a grid nor an array of poses)")
        return self.grid.poses_at(idx)

    @property
    def poses(self) -> np.ndarray:
        """All poses ``(N, pose_size)``, computed from the grid at each access.  Raises
        :class:`~taut.errors.GridSizeError` when the array would exceed
        :data:`MAX_POSE_ARRAY_BYTES` (use :meth:`poses_at` on a selection instead)."""
        if self.explicit_poses is not None:
            return self.explicit_poses
        width = self.grid.pose_size if self.grid is not None else 0
        need = self.size * width * 8
        if need > MAX_POSE_ARRAY_BYTES:
            raise GridSizeError(
                f"the {self.size:,} poses of this workspace would need {format_bytes(need)} as one array "
                f"(at most {format_bytes(MAX_POSE_ARRAY_BYTES)}); select some with poses_at(indices)"
            )
        return self.poses_at(np.arange(self.size, dtype=np.int64))

    @property
    def count(self) -> int:
        """Number of poses inside."""
        return int(np.count_nonzero(self.inside))

    @property
    def fraction(self) -> float:
        """Fraction of the poses inside (0 for an empty grid)."""
        return self.count / self.inside.size if self.inside.size else 0.0

    @property
    def measure(self) -> float | None:
        """Area (planar) or volume (spatial) of the workspace estimated as the count times
        the grid cell (product of the spacings of the axes with more than one point; for
        a full pose grid that includes the angular axes).  ``None`` without a grid."""
        if not self.axes:
            return None
        cell = 1.0
        for a in self.axes:
            if len(a) > 1:
                cell *= abs(float(a[-1] - a[0])) / (len(a) - 1)
        return self.count * cell

    def summary(self) -> dict[str, object]:
        """The numbers of the result in JSON types, as ``taut workspace --json`` prints them.

        Returns
        -------
        dict
            ``poses`` (count), ``inside`` (count), ``wrapped`` (the poses left outside because
            a straight cable meets an obstacle there), ``fraction``, ``elapsed_s``, ``measure``
            and ``grid_shape``.
        """
        return {
            "poses": int(self.inside.size),
            "inside": self.count,
            "wrapped": int(self.wrapped),
            "fraction": self.fraction,
            "elapsed_s": float(self.elapsed_s),
            "measure": self.measure,
            "grid_shape": [int(s) for s in self.grid_shape],
        }

    def as_dict(self) -> dict[str, Any]:
        """The result in plain JSON types: the robot's name, the condition, the
        :meth:`summary` (the count of poses ``inside``, not the verdict of each: a grid may hold
        a billion poses; they are :attr:`inside` and the file of :meth:`save`), the grid's
        ``axis_names`` and ``axes``, and ``complete``.

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        data: dict[str, object] = {"robot": self.robot_name, "condition": self.condition}
        data |= self.summary()
        data |= {"axis_names": list(self.axis_names), "axes": self.axes, "complete": self.complete}
        return jsonable(data)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write the result to an ``.npz`` file.

        The file holds ``inside``, ``axis_0 …``, ``metadata`` (JSON) and the poses' source: for
        a grid its definition (``grid_index``, ``grid_fixed``; the poses are recomputed on
        :meth:`load`), else the array ``poses``.  It stays the size of the verdicts
        (compressed), whatever the grid's size.

        Parameters
        ----------
        path : str or os.PathLike
        """
        meta = {
            "robot": self.robot_name,
            "condition": self.condition,
            "grid_shape": [int(s) for s in self.grid_shape],
            "axis_names": list(self.axis_names),
            "elapsed_s": float(self.elapsed_s),
            "complete": bool(self.complete),
            "wrapped": int(self.wrapped),
            "format": FILE_FORMAT,
        }
        arrays = {f"axis_{i}": np.asarray(a) for i, a in enumerate(self.axes)}
        if self.grid is not None:
            arrays["grid_index"] = np.asarray(self.grid.index, dtype=np.int64)
            arrays["grid_fixed"] = np.asarray(self.grid.fixed, dtype=float)
        elif self.explicit_poses is not None:
            arrays["poses"] = self.explicit_poses
        arrays["metadata"] = np.array(json.dumps(meta))
        # numpy's stub checks **kwds against its keyword allow_pickle: bool
        np.savez_compressed(path, inside=self.inside, **arrays)  # type: ignore[arg-type]

    @classmethod
    def load(cls, path: str | os.PathLike[str]) -> WorkspaceResult:
        """Read a file written by :meth:`save` (also the first format, which stored ``poses``).

        Parameters
        ----------
        path : str or os.PathLike

        Returns
        -------
        WorkspaceResult

        Raises
        ------
        TautError
            A file that cannot be read or is not a taut workspace file.
        """
        try:
            with np.load(path, allow_pickle=False) as f:
                meta = json.loads(str(f["metadata"]))
                axes = tuple(f[f"axis_{i}"] for i in range(len(meta["grid_shape"])) if f"axis_{i}" in f.files)
                names = tuple(meta.get("axis_names", ()))
                grid = None
                if "grid_index" in f.files:
                    index = tuple(int(i) for i in f["grid_index"])
                    grid = PoseGrid(axes, index, f["grid_fixed"], names)
                return cls(
                    meta["robot"],
                    meta["condition"],
                    f["inside"].astype(bool),
                    axes,
                    tuple(meta["grid_shape"]),
                    meta["elapsed_s"],
                    names,
                    grid,
                    f["poses"] if "poses" in f.files else None,
                    bool(meta.get("complete", True)),
                    int(meta.get("wrapped", 0)),
                )
        except (OSError, KeyError, ValueError) as exc:
            raise TautError(f"{path}: not a taut workspace file ({exc})") from None


#: One chunk of work: the robot, the condition, and the poses — an array, or a grid and a
#: range of its flat indices (computed in the worker, so that no chunk of poses travels).
Chunk = tuple[Robot, WorkspaceCondition, np.ndarray | PoseGrid, int, int]


def _evaluate_chunk(item: Chunk) -> tuple[np.ndarray, int]:
    """Worker function (module level, so that it pickles): one chunk of poses, its verdicts
    and the number of its poses where a straight cable meets an obstacle (outside)."""
    robot, condition, source, start, stop = item
    poses = source.poses(start, stop) if isinstance(source, PoseGrid) else source[start:stop]
    if not robot.obstacles:
        return np.asarray(condition.evaluate(robot, poses), dtype=bool), 0
    clear = (obstacles_met(robot, poses) < 0).all(axis=1)
    verdicts = np.zeros(len(poses), dtype=bool)
    if clear.any():
        verdicts[clear] = condition.evaluate(robot, poses[clear])
    return verdicts, int(np.count_nonzero(~clear))


def _check_grid(robot: Robot, grid: PoseGrid) -> None:
    """Every pose of ``grid`` is a valid pose of ``robot``: the checks of
    :func:`~taut.kinematics.as_poses` are bounds per coordinate, so the grid's two
    corners stand for all its poses."""
    try:
        as_poses(robot, grid.corners())
    except PoseError as exc:
        raise PoseError(f"{exc} (pose 1 is the grid's lowest corner, pose 2 its highest)") from None


def evaluate_workspace(
    robot: Robot,
    condition: str | WorkspaceCondition,
    *,
    grid: PoseGrid | Sequence[AxisSpec] | np.ndarray | None = None,
    poses: npt.ArrayLike | None = None,
    resolution: int | None = None,
    orientation: npt.ArrayLike | None = None,
    wrench_set: WrenchSet | None = None,
    executor: object = None,
    progress: Callable[[int, int | None], None] | None = None,
    chunk: int | None = None,
    max_poses: int = MAX_POSES,
) -> WorkspaceResult:
    """Evaluate a workspace condition over a grid of poses.

    A pose where a cable of a variable-structure robot, taken as a straight line, meets one
    of its obstacles is outside, whatever the condition: the cable wraps around the obstacle
    there, so that the straight-cable condition does not hold (the structure atlas,
    :func:`taut.atlas.atlas_workspace`, models the wrapping); the result counts them
    (:attr:`WorkspaceResult.wrapped`).

    The poses of a grid are generated chunk by chunk (``chunk`` poses, from their flat
    indices) where the chunk is evaluated, and only the verdicts are kept: memory is one
    byte per pose plus a few chunks' work.  Chunks are mapped over ``executor``, and the
    verdicts do not depend on ``chunk`` or the executor.

    Parameters
    ----------
    robot : Robot
    condition : str or WorkspaceCondition
        A name of :data:`~taut.workspace.CONDITIONS` (``wrench-closure``,
        ``wrench-feasible``, ``static``, ``interference-free``) or a condition instance.
    grid : PoseGrid or sequence, optional
        The poses (:func:`~taut.workspace.make_grid`): ``None`` for the default position grid
        of ``resolution`` points per axis at ``orientation``, a :class:`PoseGrid`, or one
        ``(lo, hi, n)`` or array of coordinates per position (or pose) coordinate.
    poses : array_like, shape (N, pose_size), optional
        Explicit poses instead of a grid (then ``axes == ()`` and ``grid_shape == (N,)``).
    resolution : int, optional
        Points per axis of the default position grid.
    orientation : array_like, optional
        The fixed coordinates after the position of a position grid.
    wrench_set : WrenchSet, optional
        Of ``wrench-feasible``: the set required around the external wrench.
    executor : optional
        An executor of :func:`taut.parallel.get_executor` or a ``distributed.Client``;
        default serial.
    progress : callable, optional
        ``progress(done, total)``, called with pose counts as chunks complete.
    chunk : int, optional
        Poses per chunk; default :data:`DEFAULT_CHUNK`, or fewer so that a chunk's evaluation
        holds at most :data:`CHUNK_ELEMENTS` numbers (its structure matrices, or for
        ``"interference-free"`` its capsule pairs' distances).
    max_poses : int, optional
        The budget of poses (default :data:`MAX_POSES`), at most
        :data:`~taut.workspace._grid.MAX_GRID_POSES` (2³⁰).

    Returns
    -------
    WorkspaceResult

    Raises
    ------
    TautError
        An unknown condition or option, a bad chunk, max_poses, progress or grid, poses and a grid given
        together.
    PoseError
        Poses, or grid corners, that :func:`~taut.kinematics.as_poses` refuses.
    GridSizeError
        More than ``max_poses`` poses, or a ``max_poses`` above ``MAX_GRID_POSES``, before
        any work.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import evaluate_workspace
    >>> robot = example("planar-4cable")
    >>> res = evaluate_workspace(robot, "wrench-closure", resolution=21)
    >>> res.count, res.size, round(res.fraction, 3)
    (361, 441, 0.819)
    >>> evaluate_workspace(robot, "static", poses=[[0, 0, 0], [0.9, 0.9, 0]]).inside
    array([ True, False])
    """
    cond = make_condition(condition, wrench_set=wrench_set)
    runner: Executor = as_executor(executor)
    if chunk is None:
        chunk = max(1, min(DEFAULT_CHUNK, CHUNK_ELEMENTS // cond.numbers_per_pose(robot)))
    if isinstance(chunk, bool) or not isinstance(chunk, (int, np.integer)) or chunk < 1:
        raise TautError(f"chunk must be a positive integer, got {chunk!r}")
    if progress is not None and not callable(progress):
        raise TautError(f"progress must be a callable progress(done, total), got {progress!r}")
    if isinstance(max_poses, bool) or not isinstance(max_poses, (int, np.integer)) or max_poses < 1:
        raise TautError(f"max_poses must be a positive integer, got {max_poses!r}")
    if max_poses > MAX_GRID_POSES:
        raise GridSizeError(f"max_poses {max_poses:,} is more than the {MAX_GRID_POSES:,} poses taut evaluates")
    step = int(chunk)
    g: PoseGrid | None = None
    arr: np.ndarray | None = None
    source: np.ndarray | PoseGrid
    if poses is not None:
        if grid is not None or resolution is not None or orientation is not None:
            raise TautError("give either explicit poses or a grid (resolution, orientation), not both")
        arr, _ = as_poses(robot, poses)
        source = arr
        axes: tuple[np.ndarray, ...] = ()
        shape: tuple[int, ...] = (arr.shape[0],)
        names: tuple[str, ...] = ()
        N = int(arr.shape[0])
    else:
        g = make_grid(robot, grid, resolution=resolution, orientation=orientation)
        _check_grid(robot, g)
        source = g
        axes, shape, names = tuple(np.asarray(a) for a in g.axes), g.shape, g.names
        N = g.size
    if N > max_poses:
        raise GridSizeError(
            f"{N:,} poses to evaluate, more than the budget of {int(max_poses):,} (max_poses, taut workspace "
            f"--max-poses; at most {MAX_GRID_POSES:,}): raise it to evaluate them all, or give fewer points per axis"
        )
    inside = np.zeros(N, dtype=bool)
    wrapped = 0
    done = 0
    t0 = time.perf_counter()
    if progress is not None:
        progress(0, N)
    batch = step * max(1, BATCH_POSES // step)
    for b0 in range(0, N, batch):
        starts = range(b0, min(N, b0 + batch), step)
        # a grid travels with its index range; an array only as the chunk's slice
        items: list[Chunk] = [
            (robot, cond, source, s, min(N, s + step))
            if isinstance(source, PoseGrid)
            else (robot, cond, source[s : s + step], 0, min(N, s + step) - s)
            for s in starts
        ]
        sizes = [it[4] - it[3] for it in items]

        def callback(i: int, sizes: list[int] = sizes) -> None:
            nonlocal done
            done += sizes[i]
            if progress is not None:
                progress(done, N)

        results = runner.map(_evaluate_chunk, items, callback=callback)
        for s, (verdicts, blocked) in zip(starts, results):
            inside[s : s + len(verdicts)] = verdicts
            wrapped += blocked
    elapsed = time.perf_counter() - t0
    return WorkspaceResult(robot.name, cond.name, inside, axes, shape, elapsed, names, g, arr, wrapped=wrapped)
