"""Whether sag matters: the sagging-cable statics (:func:`taut.cables.sagging_ik`) against the
straight model (:func:`taut.statics.distribute_tensions` with the same cables, weightless)
over a grid of the workspace.

At every pose of the grid where both models find tensions, the map holds each cable's
length difference (the unstrained length the catenary needs minus the length the straight
model would command: its chord, shortened by its stretch ``l/(1 + τ/EA)`` when elastic), its
sag (the largest distance from its chord) and the tension increase at its exit (the
catenary's exit tension minus the straight model's tension).  Kozak, Zhou & Wang (2006, §IV)
and Riehl et al. (2009, §IV) compare the two models this way.

References
----------
.. [1] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
   non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §IV.
   (docs/references.bib: kozak2006)
.. [2] N. Riehl, M. Gouttefarde, S. Krut, C. Baradat, F. Pierrot, "Effects of non-negligible
   cable mass on the static behavior of large workspace cable-driven parallel mechanisms",
   IEEE ICRA, 2009, §IV. (docs/references.bib: riehl2009)
"""

from __future__ import annotations

import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.cables import sagging_ik
from taut.errors import TautError
from taut.kinematics import batch_structure_matrices
from taut.model import Robot
from taut.statics import METHODS, distribute_tensions
from taut.workspace._grid import DEFAULT_SHRINK, AxisSpec, PoseGrid, default_bounds, make_grid, position_grid

#: Poses evaluated at once (the progress callback is called after each chunk).
SAG_CHUNK = 2048
#: Points per axis of the default grid of :func:`sag_map` (planar, spatial).
SAG_RESOLUTION = {2: 41, 3: 11}
#: Extent of the exits along gravity, relative to their largest extent, below which a robot
#: is suspended (its exits about one level): its default grid hangs below them.
SUSPENDED_RTOL = 0.1


@dataclass(frozen=True)
class SagMap(Result):
    """The sagging-cable statics against the straight model over ``N`` grid poses of a robot
    with ``n`` cables (:func:`sag_map`).

    Attributes
    ----------
    pose_names : tuple of str
        The names of the pose coordinates.
    poses : ndarray, shape (N, pose_size)
        The grid's poses.
    feasible : ndarray of bool, shape (N,)
        Consistent tensions with sagging cables, within the bounds at both ends.
    straight_feasible : ndarray of bool, shape (N,)
        Tensions within the bounds with straight (weightless) cables.
    length_difference : ndarray, shape (N, n)
        Unstrained length with sag minus the straight model's length [m] (0 where either
        model has no tensions).
    sag : ndarray, shape (N, n)
        The largest distance of each cable from its chord [m] (0 where not ``feasible``).
    exit_tension_increase : ndarray, shape (N, n)
        Exit tension with sag minus the straight model's tension [N] (0 where either model
        has no tensions).
    method : str
        The tension distribution method of both models.
    elapsed_s : float
        Wall-clock seconds.

    Examples
    --------
    >>> from taut.model import example
    >>> m = sag_map(example("cogiro-sagging"), grid=[(0, 0, 1), (0, 0, 1), (2.0, 2.0, 1)])
    >>> m.summary()["largest_sag"]
    [0.42..., 0.03..., 0.03..., 0.51..., 0.51..., 0.03..., 0.03..., 0.46...]
    """

    pose_names: tuple[str, ...]
    poses: np.ndarray
    feasible: np.ndarray
    straight_feasible: np.ndarray
    length_difference: np.ndarray
    sag: np.ndarray
    exit_tension_increase: np.ndarray
    method: str
    elapsed_s: float

    def summary(self) -> dict[str, Any]:
        """Per cable (0-based order), over the poses where both models have tensions: the
        largest absolute length difference [m], the largest sag [m] and the largest exit
        tension increase [N]; and the pose counts.

        Returns
        -------
        dict
            ``poses``, ``feasible``, ``straight_feasible``, ``both``, ``largest_length_difference``,
            ``largest_sag``, ``largest_exit_tension_increase`` (lists of ``n``; ``None`` when
            no pose has both).
        """
        both = self.feasible & self.straight_feasible
        out: dict[str, Any] = {
            "poses": int(self.poses.shape[0]),
            "feasible": int(self.feasible.sum()),
            "straight_feasible": int(self.straight_feasible.sum()),
            "both": int(both.sum()),
        }
        for key, values in (
            ("largest_length_difference", np.abs(self.length_difference)),
            ("largest_sag", self.sag),
            ("largest_exit_tension_increase", self.exit_tension_increase),
        ):
            out[key] = values[both].max(axis=0).tolist() if both.any() else None
        return out

    def as_dict(self) -> dict[str, Any]:
        """The summary and the map in plain JSON types: per pose, the lengths, sags and tension
        increases ``None`` where either model has no tensions.

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        both = (self.feasible & self.straight_feasible).tolist()
        rows = {
            name: [r if ok else None for r, ok in zip(jsonable(getattr(self, name)), both)]
            for name in ("length_difference", "sag", "exit_tension_increase")
        }
        return {
            "summary": self.summary(),
            "method": self.method,
            "elapsed_s": float(self.elapsed_s),
            "pose_names": list(self.pose_names),
            "poses": jsonable(self.poses),
            "feasible": jsonable(self.feasible),
            "straight_feasible": jsonable(self.straight_feasible),
        } | rows


def sag_bounds(robot: Robot) -> np.ndarray:
    """The default bounds of :func:`sag_map`'s grid: :func:`~taut.workspace.default_bounds`,
    except for a suspended robot with gravity along an axis, whose exits are about level:
    along gravity, its grid spans half the exits' largest extent below the lowest exit.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    ndarray, shape (d, 2)
        ``[lo, hi]`` of each position coordinate [m].

    Examples
    --------
    >>> from taut.model import example
    >>> sag_bounds(example("cogiro-sagging")).round(2)
    array([[-7.02,  7.03],
           [-5.06,  5.16],
           [-1.71,  5.32]])
    """
    bounds = default_bounds(robot)
    g = robot.gravity
    axis = int(np.argmax(np.abs(g)))
    if np.count_nonzero(g) != 1:
        return bounds
    ext = robot.exits.max(axis=0) - robot.exits.min(axis=0)
    if ext[axis] > SUSPENDED_RTOL * ext.max():
        return bounds
    depth = ext.max() / 2
    if g[axis] < 0:
        top = robot.exits[:, axis].min()
        lo, hi = top - depth, top
    else:
        bottom = robot.exits[:, axis].max()
        lo, hi = bottom, bottom + depth
    bounds[axis] = [lo + DEFAULT_SHRINK * depth, hi - DEFAULT_SHRINK * depth]
    return bounds


def straight_model(robot: Robot) -> Robot:
    """``robot`` with weightless (straight) cables, their stiffness kept: the model
    :func:`sag_map` compares the sagging cables with.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    Robot

    Examples
    --------
    >>> from taut.model import example
    >>> straight_model(example("cogiro-sagging")).sagging_cables
    ()
    """
    return robot.model_copy(update={"cables": tuple(c.model_copy(update={"weight": None}) for c in robot.cables)})


def sag_map(
    robot: Robot,
    *,
    grid: PoseGrid | Sequence[AxisSpec] | np.ndarray | None = None,
    resolution: int | None = None,
    orientation: npt.ArrayLike | None = None,
    method: str = "lp",
    progress: Callable[[int, int | None], None] | None = None,
) -> SagMap:
    """The length differences, sags and exit tension increases of a robot's sagging cables
    against the straight model over a grid of poses (module docstring).

    Parameters
    ----------
    robot : Robot
        A robot without jointed bodies; its cables with a ``weight`` sag.
    grid : PoseGrid or sequence of axes, optional
        As :func:`~taut.workspace.evaluate_workspace` takes it; default a position grid over
        :func:`sag_bounds`.
    resolution : int, optional
        Points per axis of the default position grid (default :data:`SAG_RESOLUTION`).
    orientation : array_like, optional
        The fixed coordinates after the position.
    method : str, default "lp"
        The tension distribution method of both models (:data:`taut.statics.METHODS`).
    progress : callable, optional
        ``progress(done, total)`` after each chunk of poses.

    Returns
    -------
    SagMap

    Raises
    ------
    TautError
        A bad grid, orientation or method.
    UnsupportedRobotError
        A platform with jointed bodies.

    References
    ----------
    .. [1] N. Riehl et al., "Effects of non-negligible cable mass on the static behavior of
       large workspace cable-driven parallel mechanisms", IEEE ICRA, 2009, §IV.
       (docs/references.bib: riehl2009)

    Examples
    --------
    >>> from taut.model import example
    >>> m = sag_map(example("cogiro-sagging"), grid=[(-1, 1, 3), (0, 0, 1), (2.0, 2.0, 1)], method="qp")
    >>> m.feasible.tolist(), m.summary()["both"]
    ([True, True, True], 3)
    """
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    start = time.perf_counter()
    if grid is None:
        points = SAG_RESOLUTION[robot.dimension] if resolution is None else resolution
        pose_grid = position_grid(robot, resolution=points, bounds=sag_bounds(robot), orientation=orientation)
    else:
        pose_grid = make_grid(robot, grid, resolution=resolution, orientation=orientation)
    poses = pose_grid.poses()
    N, n = poses.shape[0], robot.n_cables
    straight = straight_model(robot)
    feasible = np.zeros(N, bool)
    straight_feasible = np.zeros(N, bool)
    difference, sag, increase = np.zeros((N, n)), np.zeros((N, n)), np.zeros((N, n))
    ea = robot.axial_stiffness
    for lo in range(0, N, SAG_CHUNK):
        chunk = np.arange(lo, min(N, lo + SAG_CHUNK))
        ok = batch_structure_matrices(robot, poses[chunk])[2]
        k = chunk[ok]
        if k.size:
            res = sagging_ik(robot, poses[k], method=method)
            ref = distribute_tensions(straight, poses[k], method=method)
            feasible[k], straight_feasible[k] = res.feasible, ref.feasible
            both = np.asarray(res.feasible) & np.asarray(ref.feasible)
            lengths = res.chord_lengths / (1.0 + ref.tensions / ea)
            difference[k] = np.where(both[:, None], res.unstrained_lengths - lengths, 0.0)
            increase[k] = np.where(both[:, None], res.exit_tensions - ref.tensions, 0.0)
            sag[k] = res.sag
        if progress is not None:
            progress(int(chunk[-1]) + 1, N)
    return SagMap(
        tuple(robot.pose_names),
        poses,
        feasible,
        straight_feasible,
        difference,
        sag,
        increase,
        method,
        time.perf_counter() - start,
    )
