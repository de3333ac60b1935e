"""VSCR trajectories: waypoints or a parametric path, IK, tensions (§4.4, §6.1.2, §6.2 of Rushton 2022).

*Waypoint sequences* (§6.2): the end effector moves on a straight line between
consecutive waypoints at constant ``speed`` and rests ``dwell`` seconds at each one (1 s
in the experiments).  *Parametric paths* ``p(t)``: Eqs. (4.12) and (4.13) of §4.4 are
built in (:data:`PARAMETRIC`) under the names of the examples' trajectories.  Samples are
``dt`` apart; between samples the anchors move on chords (:mod:`taut.wrapping._update`).

Per sample (§6.1.2): the cable lengths and states (:func:`wrapped_inverse_kinematics`),
which cables are length-controlled — ``m`` of the ``n`` cables (``m`` = platform DOF),
chosen in cable order but never two whose active segments leave the same object towards
the same anchor, since "if multiple cables have the same anchor points, one at most can be
length controlled" — and a tension distribution by linear programming (minimum total
tension within the bounds, :func:`taut.statics.solve_tensions`, ``method="lp"``);
samples without a feasible distribution are reported.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.4 (Eqs. 4.12–4.13), §6.1.2, §6.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_number
from taut._results import Result
from taut.errors import PoseError, TautError
from taut.model import Robot
from taut.motion import robot_trajectory
from taut.statics import external_wrench, solve_tensions
from taut.wrapping._ik import WrappedIK, wrapped_inverse_kinematics
from taut.wrapping._tree import OBJ

#: Dwell at each waypoint [s] of the experiments (§6.2).
DWELL = 1.0
#: Speed [m/s] used when a waypoint trajectory gives none (§6.2 prints none).
DEFAULT_SPEED = 0.1

#: Most samples of one trajectory of a VSCR (a timed motion has its own budget, ``MAX_SAMPLES``
#: of :mod:`taut.motion._trajectory`): each carries a pose, lengths, tensions and cable states
#: (about a kilobyte); at the default 0.01 s step this is close to three hours of motion.
MAX_WRAPPING_SAMPLES = 1_000_000


def _check_samples(count: float, dt: float) -> None:
    if not count <= MAX_WRAPPING_SAMPLES:  # also refuses an infinite or NaN count
        raise TautError(
            f"sampling every {dt:g} s gives {count:.3g} samples, more than {MAX_WRAPPING_SAMPLES:,}: choose a larger dt"
        )


#: Parametric paths of the source: name → (p(t) for an array t, t0, t1).
PARAMETRIC = {
    "eq-4.12": (lambda t: np.column_stack([t, 1 + np.cos(2 * np.pi * t / 3)]), 0.0, 4.0),
    "eq-4.13": (
        lambda t: np.column_stack([0.75 * np.cos(np.pi * t / 5), -0.5 + 0.75 * np.sin(np.pi * t / 5)]),
        0.0,
        5.0,
    ),
}


#: Sample step [s] of a trajectory when none is given.
DT = 0.01


def timed_moves(
    waypoints: npt.ArrayLike, *, speed: float = DEFAULT_SPEED, dwell: float = DWELL, dt: float = DT
) -> tuple[np.ndarray, np.ndarray]:
    """Samples of straight moves at constant speed between waypoints, with a rest at each
    (§6.2).

    Parameters
    ----------
    waypoints : array_like, shape (K, k)
        Positions or poses; the moves' lengths are measured in the first two coordinates.
    speed : float, optional
        [m/s] (default :data:`DEFAULT_SPEED`).
    dwell : float, optional
        Rest [s] at each waypoint, the first one included (default 1 s, as in §6.2).
    dt : float, optional
        Largest sample step [s]: each move and rest is divided into a whole number of equal
        steps no longer than ``dt``.

    Returns
    -------
    times : ndarray, shape (T,)
        [s], from 0.
    poses : ndarray, shape (T, k)

    Raises
    ------
    TautError
        No waypoint, numbers that are not finite, bad options, or more than
        :data:`MAX_SAMPLES` samples.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §6.2. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.wrapping import timed_moves
    >>> times, poses = timed_moves([[0, 0], [0.2, 0]], speed=0.1, dwell=0.0, dt=0.5)
    >>> times.tolist(), poses[:, 0].tolist()
    ([0.0, 0.5, 1.0, 1.5, 2.0], [0.0, 0.05, 0.1, 0.15, 0.2])
    """
    W = as_array(waypoints, "waypoints")
    if W.ndim != 2 or len(W) < 1:
        raise TautError("a trajectory needs at least one waypoint")
    dt, speed = as_number(dt, "dt", positive=True), as_number(speed, "speed", positive=True)
    dwell = as_number(dwell, "dwell")
    if dwell < 0:
        raise TautError(f"dwell must be >= 0, got {dwell}")
    moves = [float(np.linalg.norm(b[:2] - a[:2])) / speed if len(a) >= 2 else 0.0 for a, b in zip(W[:-1], W[1:])]
    _check_samples(1 + len(W) * (dwell / dt + 1) + sum(d / dt + 1 for d in moves), dt)
    times, poses, t = [np.zeros(1)], [W[:1]], 0.0

    def hold(p: np.ndarray, duration: float) -> None:
        nonlocal t
        k = math.ceil(duration / dt - 1e-9)
        if k > 0:
            times.append(t + duration * np.arange(1, k + 1) / k)
            poses.append(np.repeat(p[None], k, axis=0))
            t += duration

    hold(W[0], dwell)
    for a, b, duration in zip(W[:-1], W[1:], moves):
        k = max(1, math.ceil(duration / dt - 1e-9))
        s = np.arange(1, k + 1) / k
        times.append(t + duration * s)
        poses.append(a + s[:, None] * (b - a))
        t += duration
        hold(b, dwell)
    return np.concatenate(times), np.vstack(poses)


def sample_path(
    path: Callable[[np.ndarray], npt.ArrayLike], t0: float, t1: float, *, dt: float = DT
) -> tuple[np.ndarray, np.ndarray]:
    """``(times, poses)`` of a parametric path ``path(t) -> (T, k)`` every ``dt``."""
    dt = as_number(dt, "dt", positive=True)
    if not t1 >= t0:
        raise TautError(f"the path needs t1 >= t0, got t0={t0}, t1={t1}")
    _check_samples((t1 - t0) / dt + 1, dt)
    k = max(1, math.ceil((t1 - t0) / dt - 1e-9))
    t = t0 + (t1 - t0) * np.arange(k + 1) / k
    return t, np.asarray(path(t), float)


def builtin_trajectory(
    robot: Robot,
    name: str | None = None,
    *,
    dt: float = DT,
    speed: float | None = None,
    dwell: float | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """The samples of one of a robot's named trajectories: the parametric path of
    :data:`PARAMETRIC` (Eqs. 4.12–4.13) if the name is one, else its waypoints
    (:func:`timed_moves`), read by :func:`taut.motion.robot_trajectory`.

    Parameters
    ----------
    robot : Robot
    name : str, optional
        A key of ``robot.trajectories`` (default the first one).
    dt : float, optional
        Largest sample step [s].
    speed : float, optional
        [m/s] of a waypoint trajectory (default its own, else :data:`DEFAULT_SPEED`).
    dwell : float, optional
        Rest [s] at each waypoint (default its own).

    Returns
    -------
    times : ndarray, shape (T,)
    poses : ndarray, shape (T, k)

    Raises
    ------
    TautError
        No trajectory of that name, or bad options.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.4 (Eqs. 4.12–4.13), §6.2. (docs/references.bib: rushton2022)

    Examples
    --------
    Eq. (4.12) of the single-cable robot, ``p(t) = (t, 1 + cos(2πt/3))`` for ``0 ≤ t ≤ 4``:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.wrapping import builtin_trajectory, run_trajectory
    >>> robot = example("vscr-single-cable")
    >>> times, poses = builtin_trajectory(robot, dt=0.05)
    >>> len(times), poses[0].tolist(), np.round(poses[-1], 3)
    (81, [0.0, 2.0], array([4. , 0.5]))
    """
    tr = robot_trajectory(robot, name)
    if tr.name in PARAMETRIC:
        fn, t0, t1 = PARAMETRIC[tr.name]
        return sample_path(fn, t0, t1, dt=dt)
    return timed_moves(
        tr.waypoints, speed=speed or tr.speed or DEFAULT_SPEED, dwell=tr.dwell if dwell is None else dwell, dt=dt
    )


def full_poses(robot: Robot, poses: npt.ArrayLike) -> np.ndarray:
    """Waypoints given as positions become poses with zero orientation and joints.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (K, dimension) or (K, pose_size)

    Returns
    -------
    ndarray, shape (K, pose_size)

    Raises
    ------
    PoseError
        Rows that are neither positions nor poses of the robot.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.wrapping import full_poses
    >>> full_poses(example("vscr-rigid-t-shaped"), [[0.1, 0.2]])
    array([[0.1, 0.2, 0. ]])
    """
    P = np.atleast_2d(as_array(poses, "waypoints", error=PoseError))
    if P.ndim != 2:
        raise PoseError(f"{robot.name}: waypoints are rows of coordinates, got an array of shape {P.shape}")
    if P.shape[1] == robot.pose_size:
        return P
    if P.shape[1] == robot.dimension:
        return np.hstack([P, np.zeros((len(P), robot.pose_size - robot.dimension))])
    raise TautError(
        f"{robot.name}: a waypoint has {robot.dimension} (position) or {robot.pose_size} (pose) coordinates, got {P.shape[1]}"
    )


def length_controlled(ik: WrappedIK, m: int) -> np.ndarray:
    """``(T, n)`` mask of the ``m`` length-controlled cables per sample (§6.1.2)."""
    T, n = ik.lengths.shape
    mask = np.zeros((T, n), dtype=bool)
    last = np.stack([tree.I[ik.nodes[:, i], OBJ] for i, tree in enumerate(ik.trees)], axis=1)
    ends = np.round(ik.anchors, 12)
    for s in range(T):
        used = set()
        for i in range(n):
            key = (int(last[s, i]) if len(ik.trees[i].path(int(ik.nodes[s, i]))) > 1 else -1 - i, *ends[s, i])
            if key in used:
                continue
            used.add(key)
            mask[s, i] = True
            if mask[s].sum() == m:
                break
    return mask


@dataclass(frozen=True)
class TrajectoryResult(Result):
    """A VSCR trajectory: samples, inverse kinematics, tensions and transitions
    (:func:`run_trajectory`).

    Attributes
    ----------
    times : ndarray, shape (T,)
        [s].
    ik : WrappedIK
    tensions : ndarray, shape (T, n)
        Minimum-sum tensions [N] (zeros where infeasible).
    feasible : ndarray of bool, shape (T,)
        A tension distribution exists.
    controlled : ndarray of bool, shape (T, n)
        The length-controlled cables (§6.1.2).
    transitions : tuple of dict
        Wraps and unwraps in time order: ``{"time", "sample", "cable", "kind", "object"}``
        (0-based cable and object indices).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.4, §6.2. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.wrapping import builtin_trajectory, run_trajectory
    >>> robot = example("vscr-single-cable")
    >>> times, poses = builtin_trajectory(robot, dt=0.05)
    >>> res = run_trajectory(robot, times, poses)
    >>> [(e["kind"], e["object"]) for e in res.transitions], bool(res.feasible.all())
    ([('wrap', 0), ('wrap', 1), ('wrap', 2)], True)
    """

    times: np.ndarray  #: ``(T,)`` [s]
    ik: WrappedIK
    tensions: np.ndarray  #: ``(T, n)`` minimum-sum tensions (zeros where infeasible)
    feasible: np.ndarray  #: ``(T,)`` bool: a tension distribution exists
    controlled: np.ndarray  #: ``(T, n)`` bool: length-controlled cables
    #: ``{"time", "sample", "cable", "kind", "object"}`` (0-based cable and object indices)
    transitions: tuple[dict, ...]

    @property
    def lengths(self) -> np.ndarray:
        """``(T, n)`` cable lengths [m]."""
        return self.ik.lengths

    def summary(self) -> dict:
        """What ``taut trajectory`` reports, with 0-based cables and objects: ``samples``,
        ``duration``, ``lengths``, ``transitions``, ``tension_feasible`` and
        ``infeasible_samples``."""
        return {
            "samples": int(len(self.times)),
            "duration": float(self.times[-1] - self.times[0]),
            "lengths": self.ik.lengths.tolist(),
            "transitions": [{k: e[k] for k in ("time", "cable", "kind", "object")} for e in self.transitions],
            "tension_feasible": bool(self.feasible.all()),
            "infeasible_samples": np.flatnonzero(~self.feasible).tolist(),
        }

    def as_dict(self) -> dict:
        """The trajectory as ``taut trajectory --json`` prints it, with 0-based cables and
        objects: :meth:`summary`, ``times`` and ``length_controlled``."""
        return self.summary() | {"times": self.times.tolist(), "length_controlled": self.controlled.tolist()}


def run_trajectory(
    robot: Robot,
    times: npt.ArrayLike,
    poses: npt.ArrayLike,
    *,
    initial: Mapping[int, Sequence[tuple[int, int]]] | None = None,
    wrench: npt.ArrayLike | None = None,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> TrajectoryResult:
    """Inverse kinematics, length-controlled cables and tensions at every sample of a
    trajectory of a planar variable-structure robot (§6.1.2).

    Parameters
    ----------
    robot : Robot
        A planar robot.
    times : array_like, shape (T,)
        [s].
    poses : array_like, shape (T, pose_size) or (T, dimension)
        Poses, or positions (zero orientation and joints).
    initial : mapping of int to sequence of (int, int), optional
        Starting cable states (:func:`wrapped_inverse_kinematics`).
    wrench : array_like, shape (m,) or (T, m), optional
        External wrench on the platform (default the robot's own).
    tension_bounds : (array_like, array_like), optional
        ``(tmin, tmax)`` (default the cables' own).

    Returns
    -------
    TrajectoryResult

    Raises
    ------
    PoseError
        Bad poses, or an anchor inside an object.
    TautError
        Times that do not match the poses, a bad wrench or tension bounds, or a start state
        that is not taut.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.4, §6.1.2, §6.2. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.wrapping import builtin_trajectory, run_trajectory
    >>> robot = example("vscr-single-cable")
    >>> times, poses = builtin_trajectory(robot, dt=0.05)
    >>> res = run_trajectory(robot, times, poses)
    >>> np.round(res.lengths[[0, -1], 0], 3), len(res.transitions)
    (array([2.   , 5.191]), 3)
    """
    times = as_array(times, "times", shape=(None,))
    if tension_bounds is not None and (not isinstance(tension_bounds, (tuple, list)) or len(tension_bounds) != 2):
        raise TautError(f"tension_bounds: expected a pair (tmin, tmax), got {tension_bounds!r}")
    P = full_poses(robot, poses)
    if len(times) != len(P):
        raise TautError(f"{len(times)} times for {len(P)} poses")
    ik = wrapped_inverse_kinematics(robot, P, initial=initial)
    w = external_wrench(robot, P) if wrench is None else as_array(wrench, "wrench")
    if w.shape not in ((robot.wrench_dim,), (len(P), robot.wrench_dim)):
        raise TautError(
            f"wrench: expected ({robot.wrench_dim},) or ({len(P)}, {robot.wrench_dim}) for {robot.name}, got shape {w.shape}"
        )
    w = np.broadcast_to(w, (len(P), robot.wrench_dim))
    bounds = robot.tension_bounds if tension_bounds is None else tension_bounds
    res = solve_tensions(ik.structure_matrix, w, tension_bounds=bounds, method="lp")
    controlled = length_controlled(ik, robot.wrench_dim)
    return TrajectoryResult(
        times, ik, res.tensions, np.asarray(res.feasible, bool), controlled, tuple(ik.transitions(times))
    )
