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
cable has zero length are reported as singular (no structure matrix exists there).

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
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from taut.collision._capsules import CapsuleModel, capsule_model, capsule_segments
from taut.collision._proximity import ProximityResult, proximity
from taut.collision._singularity import JACOBIAN_TOL, force_closure_singular, jacobian_singular
from taut.errors import PoseError, TautError
from taut.kinematics import CABLE_OK, actuator_jacobian, as_poses, ik_status
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
    return complete_waypoints(robot, waypoints, what)


def straight_moves(
    robot: Robot, waypoints: npt.ArrayLike, steps: Iterable[int] | None = None, what: str = "trajectory"
) -> np.ndarray:
    """Poses ``(1 + Σ steps, pose_size)`` along straight moves between ``waypoints``, with
    ``steps[k]`` increments on move ``k`` (default :data:`DEFAULT_STEPS` each)."""
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
    """The poses of the robot's named trajectory (e.g. ``sim-c`` of ``adjustable-8cable``):
    :func:`straight_moves` through its waypoints."""
    t = robot_trajectory(robot, name)
    return straight_moves(robot, t.waypoints, t.steps, f"trajectory {name}")


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
    """Poses from a trajectory file (CSV, YAML or JSON; formats in the module docstring).
    Raises :class:`PoseError` / :class:`TautError` naming the file for bad content."""
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
        return straight_moves(robot, data["waypoints"], data.get("steps"), source)
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
class CheckResult:
    """Collision and singularity verdicts at ``N`` poses (index 0 = step 1)."""

    poses: np.ndarray  #: ``(N, pose_size)``
    proximity: ProximityResult
    jacobian_singular: np.ndarray  #: ``(N,)`` bool
    jacobian_ratio: np.ndarray  #: ``(N,)`` ``σ_min / σ_max`` of ``J``
    force_closure_singular: np.ndarray  #: ``(N,)`` bool

    @property
    def model(self) -> CapsuleModel:
        return self.proximity.model

    @property
    def collides(self) -> np.ndarray:
        return ~self.proximity.interference_free

    @property
    def problems(self) -> np.ndarray:
        """``(N,)`` bool: a collision or a singularity."""
        return self.collides | self.jacobian_singular | self.force_closure_singular

    def capsules(self, robot: Robot, k: int) -> tuple[np.ndarray, np.ndarray]:
        """End points ``A, B`` ``(C, 3)`` of every capsule of :attr:`model` at pose ``k``
        (0-based) of ``robot``, the robot that was checked (:func:`capsule_segments`)."""
        A, B = capsule_segments(robot, self.poses[k : k + 1], self.model)
        return A[0], B[0]

    def first(self, flags: np.ndarray) -> int | None:
        """0-based index of the first pose whose flag is true, or None."""
        idx = np.flatnonzero(flags)
        return int(idx[0]) if idx.size else None

    def steps(self) -> list[dict]:
        """One record per pose: its 0-based ``index``, the 0-based capsule pairs in
        ``collisions`` (cables first, as in :attr:`model`), the two singularity flags and the
        smallest clearance (None where no pair is checked)."""
        clear = self.proximity.min_clearance
        return [
            {
                "index": k,
                "collisions": [[i, j] for i, j in self.proximity.collisions(k)],
                "jacobian_singular": bool(self.jacobian_singular[k]),
                "force_closure_singular": bool(self.force_closure_singular[k]),
                "min_clearance": float(clear[k]) if np.isfinite(clear[k]) else None,
            }
            for k in range(len(self.poses))
        ]


def check_poses(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    jacobian_tol: float = JACOBIAN_TOL,
    method: str = "fast",
    model: CapsuleModel | None = None,
) -> CheckResult:
    """Self-collision and singularity check at each of the poses ``(N, pose_size)``.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §4.2.
       (docs/references.bib: lieskovsky2020)
    """
    arr, _ = as_poses(robot, poses)
    model = capsule_model(robot) if model is None else model
    prox = proximity(robot, arr, model)
    N = arr.shape[0]
    jac, ratio, fc = np.ones(N, bool), np.zeros(N), np.ones(N, bool)
    ok = (ik_status(robot, arr)[1] == CABLE_OK).all(axis=1)
    if ok.any():
        J = actuator_jacobian(robot, arr[ok])
        jac[ok], ratio[ok] = jacobian_singular(J, jacobian_tol)
        W = -np.swapaxes(J[:, : robot.n_cables, : robot.wrench_dim], 1, 2)  # J = [−Wᵀ, …]
        fc[ok] = force_closure_singular(W, method)
    return CheckResult(arr, prox, jac, ratio, fc)
