"""Independent check of a planned path (Bohigas et al. 2013, §5, Fig. 6).

The poses of a path are interpolated linearly (``subdivide`` points per segment) and each
is tested with the general wrench-feasibility test of :mod:`taut.statics._feasibility`
(hyperplane shifting, not the equations of the planner): the structure matrix of
:mod:`taut.kinematics._inverse` with moments moved to the platform point ``P_m`` of the
nominal wrench, the ellipsoid ``{ŵ : (ŵ − ŵ_0)ᵀ E (ŵ − ŵ_0) ≤ 1}`` as an
:class:`~taut.statics.EllipsoidWrenchSet` of shape ``E⁻¹``, the cables' tension
bounds, and their length bounds.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5, Fig. 6. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count
from taut._results import Result, jsonable
from taut.errors import PoseError, TautError
from taut.kinematics import inverse_kinematics, platform_frame
from taut.model import Robot
from taut.statics import EllipsoidWrenchSet, wrench_feasible

__all__ = ["MAX_PATH_POSES", "PathCheck", "interpolate_poses", "verify_path"]

#: Interpolated poses :func:`verify_path` checks when no ``max_poses`` is given: their
#: :class:`PathCheck` holds 97 bytes each (97 MB at the limit), a few seconds of work.
MAX_PATH_POSES = 1_000_000
#: Poses checked at once: the structure matrices of a chunk take 19 MB.
CHUNK = 1 << 16


@dataclass(frozen=True)
class PathCheck(Result):
    """The independent check of a path (:func:`verify_path`).

    Attributes
    ----------
    poses : ndarray, shape (N, 6)
        The interpolated poses.
    feasible : ndarray of bool, shape (N,)
        Wrench-feasible, with the cable lengths strictly inside their bounds.
    lengths : ndarray, shape (N, 6)
        Cable lengths [m].
    all_feasible : bool
        Every pose is feasible (a property).

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §5, Fig. 6.
       (docs/references.bib: bohigas2013)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.planning import verify_path
    >>> robot = example("robocrane")
    >>> q = robot.reference.poses
    >>> check = verify_path(robot, [q["q1"], q["q2"]], subdivide=4)
    >>> check.poses.shape, check.feasible.tolist()
    ((5, 6), [True, False, False, False, True])
    """

    poses: np.ndarray  #: ``(N, 6)`` interpolated poses
    feasible: np.ndarray  #: ``(N,)`` wrench-feasible and lengths inside their bounds
    lengths: np.ndarray  #: ``(N, 6)``

    @property
    def all_feasible(self) -> bool:
        """Every interpolated pose is feasible."""
        return bool(self.feasible.all())

    def as_dict(self) -> dict:
        """``poses``, ``feasible``, ``lengths`` and ``all_feasible`` in plain JSON types."""
        return {
            "poses": jsonable(self.poses),
            "feasible": jsonable(self.feasible),
            "lengths": jsonable(self.lengths),
            "all_feasible": self.all_feasible,
        }


def interpolate_poses(poses: npt.ArrayLike, subdivide: int) -> np.ndarray:
    """``subdivide`` evenly spaced poses on each segment of ``poses`` ``(M, 6)``, ends included."""
    poses = np.asarray(poses, float)
    t = np.linspace(0.0, 1.0, subdivide, endpoint=False)
    inner = poses[:-1, None, :] + t[None, :, None] * np.diff(poses, axis=0)[:, None, :]
    return np.vstack([inner.reshape(-1, poses.shape[1]), poses[-1:]])


def verify_path(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    E: npt.ArrayLike | None = None,
    subdivide: int = 10,
    max_poses: int = MAX_PATH_POSES,
) -> PathCheck:
    """Check every interpolated pose of a path for wrench feasibility (module docstring),
    independently of the planner's equations, in chunks of :data:`CHUNK` poses.

    Parameters
    ----------
    robot : Robot
        A rigid 6-cable spatial robot with a constant platform wrench.
    poses : array_like, shape (M, 6) or (6,)
        The path's poses ``x, y, z, φ, θ, σ`` [m, rad].
    E : array_like, shape (6, 6), optional
        The wrench ellipsoid ``(ŵ − ŵ_0)ᵀ E (ŵ − ŵ_0) ≤ 1`` (default ``10⁴ I``, §5).
    subdivide : int, optional
        Poses per segment of the path, linearly interpolated (its end included).
    max_poses : int, optional
        Budget of interpolated poses (default :data:`MAX_PATH_POSES`).

    Returns
    -------
    PathCheck

    Raises
    ------
    PoseError
        Poses that are not rows of six finite numbers.
    TautError
        A bad ``E`` or ``subdivide``, or more interpolated poses (``subdivide`` per segment,
        and the last) than ``max_poses``, before any work.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §5, Fig. 6.
       (docs/references.bib: bohigas2013)

    Examples
    --------
    The reference pose q1 of the Robocrane is wrench-feasible; the straight line to q2 is
    not (Bohigas et al. 2013, §5).

    >>> from taut.model import example
    >>> from taut.planning import verify_path
    >>> robot = example("robocrane")
    >>> q = robot.reference.poses
    >>> verify_path(robot, q["q1"]).all_feasible, verify_path(robot, [q["q1"], q["q2"]]).all_feasible
    (True, False)
    """
    E = 1e4 * np.eye(6) if E is None else as_array(E, "E", shape=(6, 6))
    P = as_array(poses, "poses", error=PoseError)
    path = as_array(P[None] if P.ndim == 1 else P, "poses", shape=(None, 6), error=PoseError)
    subdivide = as_count(subdivide, "subdivide")
    total = (len(path) - 1) * subdivide + 1
    if total > max_poses:
        raise TautError(
            f"the path's {len(path) - 1} steps at {subdivide} poses each make {total:,} poses to check, more than "
            f"{max_poses:,} (max_poses): give a subdivide of at most {max(1, (max_poses - 1) // max(1, len(path) - 1))}"
        )
    q = interpolate_poses(path, subdivide)
    ws = EllipsoidWrenchSet(np.asarray(robot.platform.wrench, float), np.linalg.inv(E))
    tmin = np.array([c.tension[0] for c in robot.cables], float)
    tmax = np.array([c.tension[1] for c in robot.cables], float)
    lo = np.array([c.length[0] if c.length else 0.0 for c in robot.cables])
    hi = np.array([c.length[1] if c.length else np.inf for c in robot.cables])
    pm = np.zeros(3) if robot.platform.wrench_point is None else np.asarray(robot.platform.wrench_point, float)
    ok = np.zeros(len(q), bool)
    lengths = np.zeros((len(q), robot.n_cables))
    for s in range(0, len(q), CHUNK):
        part = q[s : s + CHUNK]
        ik = inverse_kinematics(robot, part)
        W = ik.structure_matrix.copy()
        _, R = platform_frame(robot, part)
        arm = R @ pm  # moments about P_m: M_m = M_p − (R p_m) × F
        W[:, 3:, :] -= np.cross(arm[:, None, :], W[:, :3, :].transpose(0, 2, 1)).transpose(0, 2, 1)
        inside = np.all((ik.lengths > lo) & (ik.lengths < hi), axis=1)
        ok[s : s + CHUNK] = wrench_feasible(W, ws, tension_bounds=(tmin, tmax)) & inside
        lengths[s : s + CHUNK] = ik.lengths
    return PathCheck(q, ok, lengths)
