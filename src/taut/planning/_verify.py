"""Independent check of a planned path (Bohigas et al. 2013, §5, Fig. 6), of any robot
whose cables can balance a set of wrenches around its own (as many cables as wrench
components, at least; no jointed bodies).

The poses of a path are interpolated (``subdivide`` points per segment; positions linearly,
each angle of the orientation along its shortest difference, the short way of
``docs/architecture.md`` §2.3, so that a segment between two writings of one rotation does not
turn) and each is tested with the general wrench-feasibility test of
:mod:`taut.statics._feasibility` (hyperplane shifting, not the equations of the manifold
planner): the structure matrix of ``taut.kinematics`` with moments moved to the
platform point ``P_m`` of the nominal wrench, the ellipsoid
``{ŵ : (ŵ − ŵ_0)ᵀ E (ŵ − ŵ_0) ≤ 1}`` as an :class:`~taut.statics.EllipsoidWrenchSet` of
shape ``E⁻¹`` around the robot's external wrench ``ŵ_0`` (weight included), the cables' tension
bounds, and their length bounds.  On request, the checks beyond wrench feasibility of
:func:`pose_validity`: no interference of the capsule model (:func:`taut.collision.proximity`),
no cable entering an obstacle (planar robots, :func:`taut.wrapping.collidable_objects` with
:func:`taut.geometry.segment_meets_circle` and :func:`taut.geometry.segment_enters_polygon`),
and cable lengths inside given bounds.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5, Fig. 6. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count
from taut._results import Result, jsonable
from taut.errors import PoseError, TautError
from taut.geometry import cross, segment_enters_polygon, segment_meets_circle
from taut.kinematics import anchors_at, batch_structure_matrices, platform_frame
from taut.model import Robot
from taut.statics import EllipsoidWrenchSet, external_wrench, wrench_feasible

__all__ = [
    "MAX_PATH_POSES",
    "PathCheck",
    "angle_columns",
    "interpolate_poses",
    "pose_validity",
    "refuse_unplannable",
    "short_way",
    "verify_path",
    "wrench_ellipsoid",
]

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
    poses : ndarray, shape (N, pose_size)
        The interpolated poses.
    feasible : ndarray of bool, shape (N,)
        Wrench-feasible, with the cable lengths strictly inside their bounds (and the checks
        asked for).
    lengths : ndarray, shape (N, n)
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

    poses: np.ndarray  #: ``(N, pose_size)`` interpolated poses
    feasible: np.ndarray  #: ``(N,)`` wrench-feasible and lengths inside their bounds
    lengths: np.ndarray  #: ``(N, n)``

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


def angle_columns(robot: Robot) -> np.ndarray:
    """The columns of ``robot``'s poses that are angles of its orientation (2π-periodic): the
    three of a spatial rigid platform, the one of a planar one, none of a point mass."""
    if robot.is_point_mass:
        return np.zeros(0, int)
    return np.arange(robot.dimension, robot.wrench_dim)


def short_way(diff: np.ndarray, angles: np.ndarray) -> np.ndarray:
    """Pose differences ``(..., k)`` with the ``angles`` columns taken the short way, in
    ``[−π, π)``."""
    out = np.array(diff, float)
    out[..., angles] = np.mod(out[..., angles] + np.pi, 2 * np.pi) - np.pi
    return out


def interpolate_poses(poses: npt.ArrayLike, subdivide: int, angles: npt.ArrayLike = ()) -> np.ndarray:
    """``subdivide`` evenly spaced poses on each segment of ``poses`` ``(M, k)``, ends included;
    the columns ``angles`` along their shortest difference."""
    poses = np.asarray(poses, float)
    t = np.linspace(0.0, 1.0, subdivide, endpoint=False)
    step = short_way(np.diff(poses, axis=0), np.asarray(angles, int))
    inner = poses[:-1, None, :] + t[None, :, None] * step[:, None, :]
    return np.vstack([inner.reshape(-1, poses.shape[1]), poses[-1:]])


def refuse_unplannable(robot: Robot, what: str) -> None:
    """:class:`TautError` unless ``robot``'s wrench-feasible poses can fill an open set of its
    pose space: at least as many cables as wrench components, no jointed bodies."""
    if robot.n_joints:
        raise TautError(f"{robot.name}: {what} takes no jointed platform (the joint forces are not balanced)")
    if robot.n_cables < robot.wrench_dim:
        raise TautError(
            f"{robot.name}: {what} needs at least as many cables as wrench components ({robot.wrench_dim}), "
            f"got {robot.n_cables}: its equilibria form a lower-dimensional set that no pose sample meets"
        )


def wrench_ellipsoid(robot: Robot, E: npt.ArrayLike | None) -> np.ndarray:
    """The matrix ``E`` of the wrench ellipsoid (default ``10⁴ I``), checked symmetric positive definite."""
    m = robot.wrench_dim
    E = 1e4 * np.eye(m) if E is None else as_array(E, "E", shape=(m, m))
    if not np.allclose(E, E.T) or np.linalg.eigvalsh(E).min() <= 0:
        raise TautError("E: the wrench ellipsoid matrix must be symmetric positive definite")
    return E


def _length_bounds(robot: Robot, lengths: tuple[npt.ArrayLike, npt.ArrayLike] | None) -> tuple[np.ndarray, np.ndarray]:
    lo = np.array([c.length[0] if c.length else 0.0 for c in robot.cables])
    hi = np.array([c.length[1] if c.length else np.inf for c in robot.cables])
    if lengths is not None:
        if not isinstance(lengths, tuple | list) or len(lengths) != 2:
            raise TautError(f"lengths: expected (lmin, lmax), each a number or one per cable, got {lengths!r}")
        n = robot.n_cables
        lmin = np.broadcast_to(as_array(lengths[0], "lengths (lmin)", finite=False), (n,))
        lmax = np.broadcast_to(as_array(lengths[1], "lengths (lmax)", finite=False), (n,))
        if np.isnan(lmin).any() or np.isnan(lmax).any() or (lmin >= lmax).any() or (lmin < 0).any():
            raise TautError(f"lengths: expected 0 <= lmin < lmax for every cable, got {lengths!r}")
        lo, hi = np.maximum(lo, lmin), np.minimum(hi, lmax)
    return lo, hi


def _tension_bounds(robot: Robot, bounds: tuple[npt.ArrayLike, npt.ArrayLike]) -> tuple[np.ndarray, np.ndarray]:
    if not isinstance(bounds, tuple | list) or len(bounds) != 2:
        raise TautError(f"tension_bounds: expected (tmin, tmax), each a number or one per cable, got {bounds!r}")
    n = robot.n_cables
    tmin = as_array(bounds[0], "tension_bounds (tmin)")
    tmax = as_array(bounds[1], "tension_bounds (tmax)", finite=False)
    if any(b.shape not in ((), (n,)) for b in (tmin, tmax)):
        raise TautError(f"tension_bounds: expected numbers or one per cable ({n}), got {bounds!r}")
    tmin, tmax = np.broadcast_to(tmin, (n,)), np.broadcast_to(tmax, (n,))
    if np.isnan(tmax).any() or (tmin < 0).any() or (tmin > tmax).any():
        raise TautError(f"tension_bounds: expected 0 <= tmin <= tmax for every cable, got {bounds!r}")
    return tmin, tmax


def pose_validity(
    robot: Robot,
    *,
    E: npt.ArrayLike | None = None,
    interference: bool = False,
    obstacles: bool = False,
    lengths: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]:
    """The validity test of the module docstring as a function of a batch of poses
    ``(N, pose_size)`` → ``(valid (N,), cable lengths (N, n))``.

    Parameters
    ----------
    robot : Robot
        A robot of :func:`refuse_unplannable`.
    E : array_like, shape (m, m), optional
        The wrench ellipsoid (default ``10⁴ I``).
    interference : bool, optional
        Also no interference of the capsule model (cable–cable, cable–platform).
    obstacles : bool, optional
        Also no cable entering a disallowed region (planar robots).  A robot's obstacles
        are checked whatever this says: its cables are straight only clear of them (where
        one would wrap, the straight model is wrong, :mod:`taut.wrapping`).
    lengths : (lmin, lmax), optional
        Also cable lengths strictly inside these bounds [m], besides the cables' own.
    tension_bounds : (tmin, tmax), optional
        Tension bounds [N] in place of the robot's, each a number or one per cable: a
        planner's stricter test (:mod:`taut.planning._posespace`).

    Returns
    -------
    callable
        ``valid(poses)``: ``(ok, lengths)``, ``ok`` ``(N,)`` bool, ``lengths`` ``(N, n)`` [m].

    Raises
    ------
    TautError
        A robot of another kind, a bad ``E``, ``lengths`` or ``tension_bounds``, or
        ``obstacles`` on a spatial robot.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §5. (docs/references.bib: bohigas2013)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.planning import pose_validity
    >>> valid = pose_validity(example("spatial-8cable"))
    >>> valid(np.array([[0, 0, 0, 0, 0, 0], [0, 0, 0, 0, 1.2, 0]]))[0]
    array([ True, False])
    """
    refuse_unplannable(robot, "a path check")
    E = wrench_ellipsoid(robot, E)
    ws = EllipsoidWrenchSet(np.zeros(robot.wrench_dim), np.linalg.inv(E))
    bounds = robot.tension_bounds if tension_bounds is None else _tension_bounds(robot, tension_bounds)
    lo, hi = _length_bounds(robot, lengths)
    d = robot.dimension
    pm = None
    if not robot.is_point_mass and robot.platform.wrench_point is not None:
        pm = np.asarray(robot.platform.wrench_point, float)
    circles: np.ndarray = np.zeros((0, 3))
    regions: list[np.ndarray] = []
    if obstacles and d != 2:
        raise TautError(f"{robot.name}: obstacles are planar; a spatial robot has none to check")
    if obstacles or robot.obstacles:
        from taut.wrapping import collidable_objects

        circles, regions = collidable_objects(robot)
    exits = robot.exits
    # Without jointed bodies the external wrench about P_m is the same at every pose: the
    # platform's wrench and weight, both applied at P_m.
    q0 = np.zeros((1, robot.pose_size))
    w = external_wrench(robot, q0)
    if pm is not None:
        _, R0 = platform_frame(robot, q0)
        w[:, d:] -= cross(R0 @ pm, w[:, :d]).reshape(1, -1)

    def valid(q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        lengths_q, W, ok = batch_structure_matrices(robot, q)  # ok: every cable has a direction
        if pm is not None:  # moments about P_m: M_m = M_p − (R p_m) × F
            _, R = platform_frame(robot, q)
            arm = R @ pm
            W = W.copy()
            mom = cross(arm[:, None, :], np.moveaxis(W[:, :d, :], 1, 2))  # (N, n, 3), or (N, n) planar
            W[:, d:, :] -= np.moveaxis(mom, 2, 1) if mom.ndim == 3 else mom[:, None, :]
        ok &= np.all((lengths_q > lo) & (lengths_q < hi), axis=1)
        if ok.any():
            ok[ok] = wrench_feasible(W[ok], ws, tension_bounds=bounds, wrench=w[0])
        if interference and ok.any():
            from taut.collision import proximity

            ok[ok] = proximity(robot, q[ok]).interference_free
        if (len(circles) or regions) and ok.any():
            b = anchors_at(robot, q[ok])
            a = np.broadcast_to(exits, b.shape)
            hit = np.zeros(b.shape[:2], bool)
            for x, y, r in circles:
                hit |= segment_meets_circle(a, b, np.array([x, y]), r)
            for poly in regions:
                hit |= segment_enters_polygon(a, b, poly)
            ok[ok] = ~hit.any(axis=1)
        return ok, lengths_q

    return valid


def verify_path(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    E: npt.ArrayLike | None = None,
    subdivide: int = 10,
    max_poses: int = MAX_PATH_POSES,
    interference: bool = False,
    obstacles: bool = False,
    lengths: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> PathCheck:
    """Check every interpolated pose of a path for wrench feasibility (module docstring),
    independently of the planner's equations, in chunks of :data:`CHUNK` poses.

    Parameters
    ----------
    robot : Robot
        A robot with at least as many cables as wrench components and no jointed bodies
        (point mass, planar or spatial, any orientation convention).
    poses : array_like, shape (M, pose_size) or (pose_size,)
        The path's poses (``x, y, z, φ, θ, σ`` [m, rad] for a tilt-and-torsion robot).
        Consecutive poses are joined the short way: each angle along its shortest difference.
    E : array_like, shape (m, m), optional
        The wrench ellipsoid ``(ŵ − ŵ_0)ᵀ E (ŵ − ŵ_0) ≤ 1`` around the external wrench, about
        the platform's ``wrench_point`` (default ``10⁴ I``, §5).
    subdivide : int, optional
        Poses per segment of the path, interpolated (its end included).
    max_poses : int, optional
        Budget of interpolated poses (default :data:`MAX_PATH_POSES`).
    interference : bool, optional
        Also no interference of the capsule model (:func:`taut.collision.proximity`).
    obstacles : bool, optional
        Also no cable entering a disallowed region (planar robots); the robot's obstacles
        are always checked (:func:`pose_validity`).
    lengths : (lmin, lmax), optional
        Also cable lengths strictly inside these bounds [m] (each a number or one per cable).

    Returns
    -------
    PathCheck

    Raises
    ------
    PoseError
        Poses that are not rows of ``pose_size`` finite numbers.
    TautError
        A robot of another kind, a bad ``E``, ``lengths`` or ``subdivide``, or more interpolated
        poses (``subdivide`` per segment, and the last) than ``max_poses``, before any work.

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

    The planar 4-cable robot at its centre: θ = −3.14159 and θ = 3.14159 are 5.3e-6 rad apart
    the short way, which the check follows (not the turn through θ = 0):

    >>> check = verify_path(example("planar-4cable"), [[0, 0, -3.14159], [0, 0, 3.14159]], subdivide=3)
    >>> check.poses[:, 2].round(5), check.all_feasible
    (array([-3.14159, -3.14159, -3.14159,  3.14159]), True)
    """
    k = robot.pose_size
    P = as_array(poses, "poses", error=PoseError)
    path = as_array(P[None] if P.ndim == 1 else P, "poses", shape=(None, k), error=PoseError)
    subdivide = as_count(subdivide, "subdivide")
    valid = pose_validity(robot, E=E, interference=interference, obstacles=obstacles, lengths=lengths)
    total = (len(path) - 1) * subdivide + 1
    if total > max_poses:
        raise TautError(
            f"the path's {len(path) - 1} steps at {subdivide} poses each make {total:,} poses to check, more than "
            f"{max_poses:,} (max_poses): give a subdivide of at most {max(1, (max_poses - 1) // max(1, len(path) - 1))}"
        )
    q = interpolate_poses(path, subdivide, angle_columns(robot))
    ok = np.zeros(len(q), bool)
    lengths_out = np.zeros((len(q), robot.n_cables))
    for s in range(0, len(q), CHUNK):
        ok[s : s + CHUNK], lengths_out[s : s + CHUNK] = valid(q[s : s + CHUNK])
    return PathCheck(q, ok, lengths_out)
