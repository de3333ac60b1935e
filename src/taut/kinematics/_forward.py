"""Forward kinematics of robots whose cables are all taut (``n ≥`` pose size).

Damped Newton (Levenberg–Marquardt, ``scipy.optimize.least_squares(method="lm")``) on
the residual ``l(x) − L`` of the inverse kinematics of :mod:`taut.kinematics._inverse`
(lengths over swivelling pulleys included), from a guess.  Under-constrained robots, whose cables need not all be taut, are the
direct geometrico-static problem (``taut.dgp``), not this.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.errors import PoseError, TautError, UnreachableLengthsError
from taut.kinematics._inverse import lengths_at
from taut.kinematics._pose import as_poses
from taut.model import Robot


@dataclass(frozen=True)
class FKResult(Result):
    """The pose of :func:`forward_kinematics`.

    Attributes
    ----------
    pose : ndarray, shape (pose_size,)
        The pose found.
    residual : float
        ``max |l_i(pose) − L_i|`` [m].
    evaluations : int
        Residual evaluations used.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import cable_lengths, forward_kinematics
    >>> robot = example("planar-4cable")
    >>> fk = forward_kinematics(robot, cable_lengths(robot, [0.1, -0.05, 0.1]))
    >>> sorted(fk.as_dict()), fk.residual < 1e-9
    (['evaluations', 'pose', 'residual'], True)
    """

    pose: np.ndarray  #: the pose found, ``(pose_size,)``
    residual: float  #: ``max |l_i(pose) − L_i|`` [m]
    evaluations: int  #: residual evaluations used


def default_guess(robot: Robot) -> np.ndarray:
    """The starting pose of :func:`forward_kinematics` when none is given: the centroid of the
    exit points, zero orientation, joints at mid-range.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    ndarray, shape (pose_size,)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import default_guess
    >>> default_guess(example("adjustable-8cable"))
    array([5.  , 5.  , 6.  , 0.  , 0.  , 0.  , 2.45])
    """
    pose = np.zeros(robot.pose_size)
    pose[: robot.dimension] = robot.exits.mean(axis=0)
    if robot.n_joints:
        pose[robot.wrench_dim :] = robot.joint_limits.mean(axis=1)
    return pose


def forward_kinematics(
    robot: Robot, lengths: npt.ArrayLike, *, guess: npt.ArrayLike | None = None, tol: float = 1e-9
) -> FKResult:
    """The pose at which the cables have the given lengths, found from a guess.

    Damped Newton (Levenberg–Marquardt; trust-region reflective within the joint limits of a
    jointed platform) on the residual ``l(x) − L`` of the inverse kinematics.  The robot must
    have at least as many cables as pose coordinates (under-constrained robots are the
    geometrico-static problem of ``taut.dgp``).

    Parameters
    ----------
    robot : Robot
    lengths : array_like, shape (n,)
        Cable lengths [m], positive.
    guess : array_like, shape (pose_size,), optional
        The starting pose; default :func:`default_guess`.
    tol : float, optional
        The largest residual ``max |l_i(x) − L_i|`` [m] accepted.

    Returns
    -------
    FKResult

    Raises
    ------
    TautError
        Lengths of the wrong number, not positive or not finite, a bad ``tol``, a robot with
        fewer cables than pose coordinates.
    PoseError
        A guess that :func:`as_poses` refuses.
    UnreachableLengthsError
        No pose near the guess fits the lengths to ``tol`` (lengths that violate a triangle
        inequality, or a guess in another basin).

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.kinematics import cable_lengths, forward_kinematics
    >>> robot = example("planar-4cable")
    >>> forward_kinematics(robot, cable_lengths(robot, [0.1, -0.05, 0.1])).pose.round(6)
    array([ 0.1 , -0.05,  0.1 ])
    """
    from scipy.optimize import least_squares

    try:
        L = np.asarray(lengths, dtype=float)
    except (TypeError, ValueError):
        raise TautError(f"{robot.name}: cable lengths must be numbers, got {lengths!r}") from None
    if isinstance(tol, bool) or not isinstance(tol, numbers.Real) or not (0 < tol < math.inf):
        raise TautError(f"tol must be a positive number [m], got {tol!r}")
    if L.shape != (robot.n_cables,):
        raise TautError(f"{robot.name}: expected {robot.n_cables} cable lengths, got {L.size}")
    if not np.all(np.isfinite(L)) or np.any(L <= 0):
        raise TautError(f"{robot.name}: cable lengths must be positive and finite, got {L.tolist()}")
    if robot.n_cables < robot.pose_size:
        raise TautError(
            f"{robot.name}: {robot.n_cables} cables cannot fix {robot.pose_size} pose coordinates; "
            "an under-constrained robot needs the geometrico-static solver (`taut fk`)"
        )
    x0 = default_guess(robot) if guess is None else as_poses(robot, guess)[0][0]
    lo = np.full(robot.pose_size, -np.inf)
    hi = np.full(robot.pose_size, np.inf)
    if robot.n_joints:
        lo[robot.wrench_dim :], hi[robot.wrench_dim :] = robot.joint_limits.T

    def residual(x: np.ndarray) -> np.ndarray:
        return lengths_at(robot, x[None, :])[0] - L

    method = "trf" if robot.n_joints else "lm"
    sol = least_squares(
        residual,
        x0,
        method=method,
        bounds=(lo, hi) if robot.n_joints else (-np.inf, np.inf),
        xtol=1e-15,
        ftol=1e-15,
        gtol=1e-15,
        max_nfev=2000,
    )
    err = float(np.max(np.abs(sol.fun)))
    if not np.all(np.isfinite(sol.x)) or err > tol:
        raise UnreachableLengthsError(
            f"{robot.name}: no pose near the guess fits the lengths {np.round(L, 6).tolist()} "
            f"(best residual {err:.3g} m)"
        )
    try:
        as_poses(robot, sol.x)
    except PoseError as exc:
        raise UnreachableLengthsError(str(exc)) from None
    return FKResult(sol.x, err, int(sol.nfev))
