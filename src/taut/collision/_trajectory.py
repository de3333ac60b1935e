"""Checking a trajectory for self-collision and singularities (§4.2 of
Lieskovský (2020): simulations a–d of the adjustable platform).

A trajectory is a sequence of poses ``X_1 … X_N`` (1-based steps, as in §4.2).  A named
trajectory of a robot (``trajectories:`` in its file, read by
:func:`taut.motion.robot_trajectory`) is sampled by joining its waypoints with straight
moves of ``steps[k]`` increments each (:func:`straight_moves`; :data:`DEFAULT_STEPS` when
not given),
so that simulation a (``steps: [100, 100]``) gives the 201 configurations ``X_1 … X_201`` of
Eqs. 4.2.1–4.2.6.  Waypoints that give only a position take the rest of the pose from the
robot's first reference pose (zeros, joints at mid-range, without one).

At every step :func:`check_poses` reports the colliding capsule pairs (§3.4,
:mod:`taut.collision._proximity`), the smallest clearance ``ε``, and the Jacobian and
force-closure singularities (§2.3.1, :mod:`taut.collision._singularity`).  Poses where a
cable has zero length are reported as singular (no structure matrix exists there).  On a
variable-structure robot a cable whose straight line meets one of the robot's obstacles is
an obstacle contact, a problem of its own (:func:`taut.kinematics.obstacles_met`): the cable
wraps around the obstacle there, so the singularity tests of the straight cables are not run
at that pose (its flags are false and its ``jacobian_ratio`` NaN, ``None`` in JSON); the
capsules are still the straight cables.

Trajectory files (:func:`load_trajectory`):

* CSV — one pose per line, ``pose_size`` comma-separated numbers; an optional first line
  of column names (e.g. ``x,y,z,a,b,c,s23``); ``#`` starts a comment;
* YAML or JSON — a list of poses, or a mapping with ``poses: [...]``, or a mapping with
  ``waypoints: [...]`` and optional ``steps: [...]`` (sampled as above).

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §4.2 (simulations a–d, Eqs.
   4.2.1–4.2.6), §3.4, §2.3.1. (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

import json
import numbers
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.collision._capsules import CapsuleModel, capsule_model, capsule_segments
from taut.collision._proximity import ProximityResult, proximity
from taut.collision._singularity import JACOBIAN_TOL, check_method, force_closure_singular, jacobian_singular
from taut.errors import PoseError, TautError
from taut.kinematics import CABLE_OK, actuator_jacobian, as_poses, ik_status, obstacles_met
from taut.model import Robot
from taut.motion import complete_waypoints, robot_trajectory

__all__ = ["CheckResult", "check_poses", "load_trajectory", "straight_moves", "trajectory_poses"]

#: Increments per move of a named trajectory that gives no ``steps``.
DEFAULT_STEPS = 100


def _fill(robot: Robot, waypoints: np.ndarray, what: str) -> np.ndarray:
    d, size = robot.dimension, robot.pose_size
    if waypoints.ndim != 2 or waypoints.shape[1] not in (d, size):
        width = waypoints.shape[1] if waypoints.ndim == 2 else waypoints.shape
        raise PoseError(
            f"{what}: {robot.name} takes poses of {size} coordinates ({', '.join(robot.pose_names)}) "
            f"or positions of {d}, got {width}"
        )
    return complete_waypoints(robot, waypoints, what=what)


def straight_moves(
    robot: Robot, waypoints: npt.ArrayLike, steps: Iterable[int] | None = None, *, what: str = "trajectory"
) -> np.ndarray:
    """Poses along straight moves between waypoints.

    Parameters
    ----------
    robot : Robot
    waypoints : array_like, shape (K, pose_size) or (K, d)
        Waypoints; one of ``d`` coordinates gives a position and takes the rest of the pose
        from the robot's first reference pose.
    steps : sequence of int, optional
        Increments of each move (``K − 1`` positive integers); default
        :data:`DEFAULT_STEPS` (100) each.
    what : str, optional
        What the waypoints are, for messages.

    Returns
    -------
    ndarray, shape (1 + Σ steps, pose_size)

    Raises
    ------
    PoseError
        Waypoints that are not numbers or of the wrong width, no waypoint, bad ``steps``, a
        pose outside the joint limits.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.collision import straight_moves
    >>> straight_moves(example("planar-4cable"), [[0, 0, 0], [0.2, 0.1, 0]], [4])
    array([[0.   , 0.   , 0.   ],
           [0.05 , 0.025, 0.   ],
           [0.1  , 0.05 , 0.   ],
           [0.15 , 0.075, 0.   ],
           [0.2  , 0.1  , 0.   ]])
    """
    try:
        wp = np.asarray(waypoints, dtype=float)
    except (TypeError, ValueError):
        raise PoseError(f"{what}: waypoints must be lists of numbers") from None
    wp = _fill(robot, np.atleast_2d(wp), what)
    if len(wp) < 1:
        raise PoseError(f"{what}: no waypoints")
    steps = [DEFAULT_STEPS] * (len(wp) - 1) if steps is None else list(steps)
    if len(steps) != len(wp) - 1 or any(not isinstance(s, (int, np.integer)) or s < 1 for s in steps):
        raise PoseError(f"{what}: steps must be {len(wp) - 1} positive integers (one per move), got {steps}")
    parts = [wp[:1]]
    for k, s in enumerate(steps):
        t = np.arange(1, s + 1)[:, None] / s
        parts.append(wp[k] + t * (wp[k + 1] - wp[k]))
    return as_poses(robot, np.concatenate(parts))[0]


def trajectory_poses(robot: Robot, name: str) -> np.ndarray:
    """The poses of one of the robot's named trajectories (``trajectories:`` in its file).

    Parameters
    ----------
    robot : Robot
    name : str
        E.g. ``sim-c`` of ``adjustable-8cable`` (Lieskovský 2020, §4.2).

    Returns
    -------
    ndarray, shape (1 + Σ steps, pose_size)
        Sampled by :func:`straight_moves` with the trajectory's ``steps``.

    Raises
    ------
    TrajectoryError
        No trajectory of that name (:func:`taut.motion.robot_trajectory`).

    Examples
    --------
    Simulation a joins three waypoints by 100 increments each: ``X_1 … X_201``.

    >>> from taut.model import example
    >>> from taut.collision import trajectory_poses
    >>> trajectory_poses(example("adjustable-8cable"), "sim-a").shape
    (201, 7)
    """
    t = robot_trajectory(robot, name)
    return straight_moves(robot, t.waypoints, t.steps, what=f"trajectory {name}")


def _csv(text: str, robot: Robot, source: str) -> np.ndarray:
    rows, first = [], True
    for lineno, line in enumerate(text.splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        cells = [c.strip() for c in line.split(",")]
        header, first = first, False
        try:
            rows.append([float(c) for c in cells])
        except ValueError:
            if not header:
                raise PoseError(f"{source}, line {lineno}: expected numbers, got {line!r}") from None
            if [c.lower() for c in cells] != [n.lower() for n in robot.pose_names]:
                raise PoseError(
                    f"{source}, line {lineno}: expected numbers or the header "
                    f"{','.join(robot.pose_names)}, got {line!r}"
                ) from None
    if not rows:
        raise PoseError(f"{source}: no poses")
    widths = {len(r) for r in rows}
    if len(widths) != 1:
        raise PoseError(f"{source}: every line must have {robot.pose_size} numbers, got lines of {sorted(widths)}")
    return np.array(rows)


def load_trajectory(robot: Robot, path: str | Path) -> np.ndarray:
    """The poses of a trajectory file.

    CSV: one pose per line, an optional header of the pose's coordinate names, ``#``
    comments; YAML or JSON: a list of poses, a mapping with ``poses``, or a mapping with
    ``waypoints`` and optional ``steps`` (sampled by :func:`straight_moves`).

    Parameters
    ----------
    robot : Robot
    path : str or pathlib.Path
        A ``.csv``, ``.json`` or YAML file.

    Returns
    -------
    ndarray, shape (N, pose_size)

    Raises
    ------
    TautError
        A file that cannot be read or parsed, or of another structure.
    PoseError
        Poses that are not numbers, of the wrong width or outside the joint limits; the
        message names the file.

    Examples
    --------
    >>> import pathlib, tempfile
    >>> from taut.model import example
    >>> from taut.collision import load_trajectory
    >>> folder = tempfile.TemporaryDirectory()
    >>> path = pathlib.Path(folder.name) / "moves.csv"
    >>> _ = path.write_text("x,y,theta\\n0,0,0\\n0.1,0.2,0.05\\n")
    >>> load_trajectory(example("planar-4cable"), path)
    array([[0.  , 0.  , 0.  ],
           [0.1 , 0.2 , 0.05]])
    >>> folder.cleanup()
    """
    path = Path(path)
    source = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise TautError(f"{source}: cannot read the trajectory file ({exc.strerror or exc})") from None
    if path.suffix.lower() == ".csv":
        poses = _csv(text, robot, source)
        if poses.shape[1] != robot.pose_size:
            raise PoseError(
                f"{source}: {robot.name} takes poses of {robot.pose_size} coordinates "
                f"({', '.join(robot.pose_names)}), got {poses.shape[1]}"
            )
        return as_poses(robot, poses)[0]
    try:
        if path.suffix.lower() == ".json":
            data = json.loads(text)
        else:
            import yaml

            data = yaml.safe_load(text)
    except Exception as exc:  # noqa: BLE001 — any parser error is bad input
        raise TautError(f"{source}: not valid {path.suffix.lstrip('.').upper() or 'YAML'}: {exc}") from None
    if isinstance(data, dict) and "poses" in data:
        data = data["poses"]
    if isinstance(data, dict) and "waypoints" in data:
        return straight_moves(robot, data["waypoints"], data.get("steps"), what=source)
    if not isinstance(data, list) or not data:
        raise TautError(f"{source}: expected a list of poses, or a mapping with 'poses' or 'waypoints'")
    try:
        poses = np.array(data, dtype=float)
    except (TypeError, ValueError):
        raise PoseError(f"{source}: every pose must be a list of {robot.pose_size} numbers") from None
    if poses.ndim != 2 or poses.shape[1] != robot.pose_size:
        raise PoseError(
            f"{source}: {robot.name} takes poses of {robot.pose_size} coordinates "
            f"({', '.join(robot.pose_names)}), got shape {poses.shape}"
        )
    try:
        return as_poses(robot, poses)[0]
    except PoseError as exc:
        raise PoseError(f"{source}: {exc}") from None


@dataclass(frozen=True)
class CheckResult(Result):
    """Collision and singularity verdicts at ``N`` poses (:func:`check_poses`; index 0 is
    step 1 of the sources).

    Attributes
    ----------
    poses : ndarray, shape (N, pose_size)
    proximity : ProximityResult
        The capsule proximities and clearances.
    jacobian_singular : ndarray of bool, shape (N,)
    jacobian_ratio : ndarray, shape (N,)
        ``σ_min / σ_max`` of the Jacobian.
    force_closure_singular : ndarray of bool, shape (N,)
    obstacle_contacts : ndarray of int, shape (N, n)
        The 0-based obstacle each cable's straight line meets at each pose, ``-1`` where none
        (:func:`taut.kinematics.obstacles_met`).

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.collision import check_poses, trajectory_poses
    >>> robot = example("adjustable-8cable")
    >>> res = check_poses(robot, trajectory_poses(robot, "sim-b")[120:130])
    >>> res.steps()[5]["force_closure_singular"], sorted(res.as_dict())
    (True, ['capsules', 'jacobian_ratio', 'poses', 'steps', 'summary'])
    """

    poses: np.ndarray  #: ``(N, pose_size)``
    proximity: ProximityResult
    jacobian_singular: np.ndarray  #: ``(N,)`` bool
    jacobian_ratio: np.ndarray  #: ``(N,)`` ``σ_min / σ_max`` of ``J``
    force_closure_singular: np.ndarray  #: ``(N,)`` bool
    obstacle_contacts: np.ndarray  #: ``(N, n)`` 0-based obstacle each straight cable meets, -1 none

    @property
    def model(self) -> CapsuleModel:
        """The capsule model."""
        return self.proximity.model

    @property
    def collides(self) -> np.ndarray:
        """``(N,)`` bool: some capsule pair collides."""
        return ~self.proximity.interference_free

    @property
    def touches_obstacle(self) -> np.ndarray:
        """``(N,)`` bool: a cable's straight line meets an obstacle."""
        return np.asarray((self.obstacle_contacts >= 0).any(axis=1))

    @property
    def problems(self) -> np.ndarray:
        """``(N,)`` bool: a collision, a singularity or an obstacle contact."""
        return self.collides | self.jacobian_singular | self.force_closure_singular | self.touches_obstacle

    def capsules(self, robot: Robot, k: int) -> tuple[np.ndarray, np.ndarray]:
        """The end points of every capsule of :attr:`model` at one checked pose.

        Parameters
        ----------
        robot : Robot
            The robot that was checked.
        k : int
            The pose's 0-based index.

        Returns
        -------
        A, B : ndarray, shape (C, 3)
            The capsules' end points (:func:`capsule_segments`).
        """
        A, B = capsule_segments(robot, self.poses[k : k + 1], model=self.model)
        return A[0], B[0]

    def first(self, flags: np.ndarray) -> int | None:
        """The first pose whose flag is true.

        Parameters
        ----------
        flags : ndarray of bool, shape (N,)
            E.g. :attr:`problems`, :attr:`collides` or :attr:`force_closure_singular`.

        Returns
        -------
        int or None
            Its 0-based index, or None.
        """
        idx = np.flatnonzero(flags)
        return int(idx[0]) if idx.size else None

    def steps(self) -> list[dict]:
        """One record per pose: its 0-based ``index``, the 0-based capsule pairs in
        ``collisions`` (cables first, as in :attr:`model`), the two singularity flags, the
        smallest clearance (None where no pair is checked) and the 0-based ``[cable,
        obstacle]`` pairs of ``obstacle_contacts``."""
        clear = self.proximity.min_clearance
        return [
            {
                "index": k,
                "collisions": [[i, j] for i, j in self.proximity.collisions(k)],
                "jacobian_singular": bool(self.jacobian_singular[k]),
                "force_closure_singular": bool(self.force_closure_singular[k]),
                "min_clearance": float(clear[k]) if np.isfinite(clear[k]) else None,
                "obstacle_contacts": [
                    [int(i), int(self.obstacle_contacts[k, i])] for i in np.flatnonzero(self.obstacle_contacts[k] >= 0)
                ],
            }
            for k in range(len(self.poses))
        ]

    def summary(self) -> dict[str, Any]:
        """The verdict of the whole trajectory, with 0-based pose indices: the number of
        ``poses``; the first pose that collides (``first_collision``), is Jacobian singular,
        force-closure singular, has a straight cable meeting an obstacle
        (``first_obstacle_contact``), or any of them (``first_problem``), each None when none
        does; the inclusive ``[first, last]`` runs of consecutive poses that collide
        (``collision_steps``), are singular or meet an obstacle (``obstacle_contact_steps``);
        and the smallest ``min_clearance`` [m] (None without poses or pairs).

        Returns
        -------
        dict
            In plain JSON types.

        Examples
        --------
        >>> from taut.model import example
        >>> from taut.collision import check_poses, trajectory_poses
        >>> robot = example("adjustable-8cable")
        >>> check_poses(robot, trajectory_poses(robot, "sim-b")[120:130]).summary()["force_closure_singular_steps"]
        [[5, 9]]
        """
        flags = {
            "collision": self.collides,
            "jacobian_singular": self.jacobian_singular,
            "force_closure_singular": self.force_closure_singular,
            "obstacle_contact": self.touches_obstacle,
        }
        clear = self.proximity.min_clearance
        return jsonable(
            {"poses": len(self.poses)}
            | {f"first_{name}": self.first(f) for name, f in flags.items()}
            | {"first_problem": self.first(self.problems)}
            | {f"{name}_steps": _runs(f) for name, f in flags.items()}
            | {"min_clearance": float(np.min(clear)) if len(clear) else None}
        )

    def as_dict(self) -> dict[str, Any]:
        """The result in plain JSON types: the ``capsules``' names (0-based, cables first),
        the ``poses``, the ``jacobian_ratio`` of each pose, its record of :meth:`steps` and
        the :meth:`summary` (0-based pose and capsule indices).

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        return jsonable(
            {
                "capsules": self.model.names,
                "poses": self.poses,
                "jacobian_ratio": self.jacobian_ratio,
                "steps": self.steps(),
                "summary": self.summary(),
            }
        )


def _runs(flags: np.ndarray) -> list[list[int]]:
    """The inclusive ``[first, last]`` index ranges of consecutive true ``flags``."""
    idx = np.flatnonzero(flags)
    if not idx.size:
        return []
    breaks = np.flatnonzero(np.diff(idx) > 1)
    starts = np.r_[idx[0], idx[breaks + 1]]
    ends = np.r_[idx[breaks], idx[-1]]
    return [[int(s), int(e)] for s, e in zip(starts, ends)]


def check_poses(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    tol: float = JACOBIAN_TOL,
    method: str = "fast",
    model: CapsuleModel | None = None,
) -> CheckResult:
    """Self-collision and singularity check at each pose of a trajectory.

    At every pose: the colliding capsule pairs (§3.4), the smallest clearance, and the
    Jacobian and force-closure singularities (§2.3.1).  Poses where a cable has no direction
    are singular.  Where a cable of a variable-structure robot meets an obstacle as a straight
    line, the contact is reported (:attr:`CheckResult.obstacle_contacts`) and the straight
    cables' singularities are not tested (see the module's docstring).

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)
    tol : float, optional
        The Jacobian singularity ratio (:func:`jacobian_singular`).
    method : {"fast", "lp"}, optional
        The force-closure test (:func:`force_closure_singular`).
    model : CapsuleModel, optional
        ``robot``'s capsule model; default :func:`capsule_model`.

    Returns
    -------
    CheckResult

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.
    TautError
        An unknown method, a bad ``tol``, a model of another robot.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    Simulation b of the adjustable platform reaches a force-closure singularity at step 126,
    where four cables lie in one plane:

    >>> from taut.model import example
    >>> from taut.collision import check_poses, trajectory_poses
    >>> robot = example("adjustable-8cable")
    >>> res = check_poses(robot, trajectory_poses(robot, "sim-b"))
    >>> res.first(res.force_closure_singular) + 1, res.first(res.collides)
    (126, None)
    """
    check_method(method)
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real) or not 0 <= tol < 1:
        raise TautError(f"tol must be a number in [0, 1) (a ratio of singular values), got {tol!r}")
    arr, _ = as_poses(robot, poses)
    model = capsule_model(robot) if model is None else model
    prox = proximity(robot, arr, model=model)
    N = arr.shape[0]
    jac, ratio, fc = np.ones(N, bool), np.zeros(N), np.ones(N, bool)
    ok = (ik_status(robot, arr)[1] == CABLE_OK).all(axis=1)
    contacts = obstacles_met(robot, arr)
    wrapped = (contacts >= 0).any(axis=1)
    jac[wrapped], ratio[wrapped], fc[wrapped] = False, np.nan, False
    if ok.any():
        J = actuator_jacobian(robot, arr[ok])
        jac[ok], ratio[ok] = jacobian_singular(J, tol=tol)
        W = -np.swapaxes(J[:, : robot.n_cables, : robot.wrench_dim], 1, 2)  # J = [−Wᵀ, …]
        fc[ok] = force_closure_singular(W, method=method)
    return CheckResult(arr, prox, jac, ratio, fc, contacts)
