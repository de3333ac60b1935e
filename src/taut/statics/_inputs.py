"""The inputs that hold a robot: its cables and, on a jointed platform, its joint actuators.

A jointed platform's joint may have a motor (``joint.actuator``) exerting a force or torque
``ζ_j`` within its bounds, which may be negative or infinite; a joint without one is passive:
the cables acting across it must hold it.  Equilibrium is then the jointed structure matrix's
``A [τ; ζ] + Q_ext = 0`` (Lieskovský 2020, Eq. 3.3.12): its platform rows are the structure
matrix ``W`` and the external wrench (the bodies' weights included), one more row per joint
with the generalized force of the bodies' weights on it, and a unit column per actuated joint
(Lau, Oetomo & Halgamuge 2013: cables and joint actuators together in the joint-space
equations of a multilink cable robot).  The compiled closed form (:mod:`taut.dynamics`)
takes such columns as they are; the distributions of :mod:`taut.statics` accept non-negative
lower bounds only, so for them each actuator becomes a pushing and a pulling column,
``ζ = ζ⁺ − ζ⁻`` with ``ζ⁺ ∈ [max(ζ_min, 0), max(ζ_max, 0)]`` and ``ζ⁻ ∈ [max(−ζ_max, 0),
max(−ζ_min, 0)]``: the two sets of ``ζ`` are the same, and the least sum or 2-norm of the
split is reached with one of ``ζ⁺``, ``ζ⁻`` at zero (where the bounds allow), so that ``lp``
and ``qp`` minimise ``|ζ|`` and ``ζ²`` beside the tensions.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eqs. 3.3.7–3.3.12.
   (docs/references.bib: lieskovsky2020)
.. [2] D. Lau, D. Oetomo, S. K. Halgamuge, "Generalized modeling of multilink cable-driven
   manipulators with arbitrary routing using the cable-routing matrix", IEEE Transactions on
   Robotics 29(5), 2013 (cables and joint actuators in the joint-space equations of motion).
   (docs/references.bib: lau2013)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import TautError
from taut.kinematics import as_poses, inverse_kinematics, joint_forces, jointed_structure_matrix
from taut.model import Robot
from taut.statics._tension import METHODS, TensionResult, solve_tensions
from taut.statics._wrench import as_floats, bounds_pair, external_wrench

__all__ = ["distribute_tensions", "equilibrium_equations", "input_bounds", "solve_inputs"]


def input_bounds(robot: Robot, cables: tuple[np.ndarray, np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """The bounds of a robot's inputs: its cables' tensions, then its joint actuators' forces.

    Parameters
    ----------
    robot : Robot
    cables : (tmin, tmax)
        The cables' tension bounds [N], each ``(n,)``.

    Returns
    -------
    lower, upper : ndarray, shape (n + n_actuators,)
        ``tmin`` then the actuators' lower bounds, ``tmax`` then their upper bounds
        (:attr:`taut.model.Robot.actuator_bounds`; ``±inf`` where unbounded).

    Examples
    --------
    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> input_bounds(robot, robot.tension_bounds)[1]
    array([100., 100., 100., 100.])
    """
    lo, hi = robot.actuator_bounds
    return np.concatenate([cables[0], lo]), np.concatenate([cables[1], hi])


def _split(
    W: np.ndarray, lo: np.ndarray, hi: np.ndarray, n_cables: int
) -> tuple[np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """``W``'s actuator columns (those after the first ``n_cables``) as a pushing and a pulling
    column each, with their bounds (module docstring): ``[W_cables, W_act, −W_act]``."""
    act = slice(n_cables, W.shape[-1])
    zero = np.zeros_like(lo[act])
    low = np.concatenate([lo[:n_cables], np.maximum(lo[act], zero), np.maximum(-hi[act], zero)])
    high = np.concatenate([hi[:n_cables], np.maximum(hi[act], zero), np.maximum(-lo[act], zero)])
    return np.concatenate([W, -W[..., act]], axis=-1), (low, high)


def _joined(x: np.ndarray, n_cables: int) -> tuple[np.ndarray, np.ndarray]:
    """The tensions and the actuator forces ``ζ = ζ⁺ − ζ⁻`` of a solution ``x`` of
    :func:`_split`'s system."""
    k = (x.shape[-1] - n_cables) // 2
    return x[..., :n_cables].copy(), x[..., n_cables : n_cables + k] - x[..., n_cables + k :]


def solve_inputs(
    W: np.ndarray, wrench: np.ndarray, lo: np.ndarray, hi: np.ndarray, n_cables: int, method: str
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Tensions and actuator forces ``x`` with ``W x = wrench`` and ``lo ≤ x ≤ hi``, by a
    distribution method of :func:`taut.statics.solve_tensions`, the actuators (the columns
    after the first ``n_cables``) split into a pushing and a pulling column (module docstring).

    Parameters
    ----------
    W : ndarray, shape (..., m, n)
        The cables' columns, then one column per actuator.
    wrench : ndarray, shape (..., m)
        The generalized force the inputs must exert.
    lo, hi : ndarray, shape (n,)
        Bounds of the inputs (:func:`input_bounds`): tensions ``≥ 0``, actuator forces of any
        sign, infinite where unbounded.
    n_cables : int
    method : str
        One of :data:`taut.statics.METHODS`.

    Returns
    -------
    x : ndarray, shape (..., n)
        Zeros where no admissible inputs exist.
    feasible : ndarray of bool, shape (...)
    status : ndarray of str, shape (...)
        As :class:`taut.statics.TensionResult`'s.

    Raises
    ------
    TautError
        As :func:`taut.statics.solve_tensions`.

    Examples
    --------
    One cable and one actuator pushing either way along a line: the cable pulls at least 1 N,
    so that the actuator pushes with 3 N against a load of 2 N.

    >>> import numpy as np
    >>> x, ok, status = solve_inputs(
    ...     np.array([[1.0, 1.0]]), np.array([-2.0]), np.array([1.0, -np.inf]), np.array([10.0, np.inf]), 1, "lp"
    ... )
    >>> x, bool(ok)
    (array([ 1., -3.]), True)
    """
    split, bounds = _split(W, lo, hi, n_cables)
    res = solve_tensions(split, -wrench, tension_bounds=bounds, method=method)
    tensions, forces = _joined(np.asarray(res.tensions), n_cables)
    return np.concatenate([tensions, forces], axis=-1), np.asarray(res.feasible), np.asarray(res.status)


def equilibrium_equations(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    wrench: npt.ArrayLike | None = None,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> tuple[np.ndarray, np.ndarray, tuple[np.ndarray, np.ndarray]]:
    """The static equilibrium of ``robot`` at ``poses``: ``W x + w = 0``, ``lo ≤ x ≤ hi``.

    Without joints ``W`` is the structure matrix, ``x`` the tensions and ``w`` the external
    wrench.  On a jointed platform ``W`` is the jointed structure matrix (Lieskovský 2020,
    Eq. 3.3.12) with a row per joint, ``w`` has a row per joint too (the generalized force of
    the bodies' weights on it), and ``x`` holds after the tensions a pushing and a pulling
    force of each joint actuator (module docstring); a passive joint has no column, so that
    the cables alone hold it.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)
    wrench : array_like, shape (N, m) or (m,), optional
        External wrench on the platform [N, N m]; default :func:`external_wrench`, the
        robot's own wrench and weight (and its bodies').  A wrench given replaces the robot's
        own load: the joints then carry none.
    tension_bounds : (tmin, tmax), optional
        Default ``robot.tension_bounds``.

    Returns
    -------
    W : ndarray, shape (N, m + n_joints, n + 2 n_actuators), or without the batch axis
    w : ndarray, shape (N, m + n_joints), or without the batch axis
    bounds : (lo, hi), each ndarray of shape (n + 2 n_actuators,)

    Raises
    ------
    PoseError
        Poses that :func:`taut.kinematics.as_poses` refuses.
    InfeasiblePoseError
        A zero-length cable.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.3, Eq. 3.3.12.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    The adjustable platform's passive joint ``s23`` adds a row, the weight of its 8 kg upper
    body pulling down along the joint:

    >>> from taut.model import example
    >>> W, w, (lo, hi) = equilibrium_equations(example("adjustable-8cable"), [5, 5, 1.5, 0, 0, 0, 1.5])
    >>> W.shape, w[6].round(2), lo.shape
    ((7, 8), np.float64(-78.48), (8,))
    """
    arr, single = as_poses(robot, poses)
    N, n, m = len(arr), robot.n_cables, robot.wrench_dim
    tmin, tmax = (
        as_floats(t, "tension bounds")
        for t in bounds_pair(robot.tension_bounds if tension_bounds is None else tension_bounds)
    )
    if tmin.shape not in ((), (n,)) or tmax.shape not in ((), (n,)):
        raise TautError(f"tension bounds must be numbers or ({n},) for {n} cables, got {tmin.shape} and {tmax.shape}")
    cables = np.broadcast_to(tmin, (n,)).copy(), np.broadcast_to(tmax, (n,)).copy()
    if wrench is None:
        w = external_wrench(robot, arr)
    else:
        w = as_floats(wrench, "wrench")
        if w.shape not in ((m,), (N, m)) or (single and w.ndim == 2):
            raise TautError(f"wrench must have shape ({m},){'' if single else f' or ({N}, {m})'}, got {w.shape}")
        w = np.broadcast_to(w, (N, m))
    if not robot.n_joints:
        W = inverse_kinematics(robot, arr).structure_matrix
        return (W[0], w[0], cables) if single else (W, w, cables)
    A = jointed_structure_matrix(robot, arr)
    W, bounds = _split(A[..., np.r_[:n, n + robot.actuated_joints]], *input_bounds(robot, cables), n)
    loads = -joint_forces(robot, arr, np.zeros(n)) if wrench is None else np.zeros((N, robot.n_joints))
    wj = np.concatenate([w, loads], axis=-1)
    return (W[0], wj[0], bounds) if single else (W, wj, bounds)


def distribute_tensions(
    robot: Robot,
    poses: npt.ArrayLike,
    *,
    wrench: npt.ArrayLike | None = None,
    method: str = "lp",
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
) -> TensionResult:
    """Tension distribution of ``robot`` at ``poses``: :func:`solve_tensions` with the
    structure matrix of :func:`taut.kinematics.inverse_kinematics`, or on a jointed platform
    with the equations of :func:`equilibrium_equations`: a passive joint is held by the
    cables acting across it, a joint with an actuator (``joint.actuator``) by the actuator
    within its bounds too (its force in ``actuator_forces``).

    Parameters
    ----------
    robot : Robot
        The robot.
    poses : array_like, shape (N, pose_size) or (pose_size,)
        Poses (``robot.pose_names``), one or a batch.
    wrench : array_like, shape (N, m) or (m,), optional
        External wrench on the platform [N, N m]; default :func:`external_wrench`, the
        robot's own wrench and weight.
    method : str, default "lp"
        One of :data:`METHODS`.
    tension_bounds : (tmin, tmax), optional
        Tension bounds [N], each a number or ``(n,)``; default ``robot.tension_bounds``.

    Returns
    -------
    TensionResult
        One pose: fields without a batch axis.

    Raises
    ------
    TautError
        For a bad pose (:class:`~taut.errors.PoseError`), wrench, bounds or method.

    References
    ----------
        .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
           of Waterloo, 2022, §2.1.2, Eqs. 2.11–2.13. (docs/references.bib: rushton2022)

    Examples
    --------
    The platform of the planar 4-cable robot hangs at the centre of its frame: the least sum
    of tensions keeps the lower cables at their 1 N minimum and the upper ones carry the
    weight, ``2 · 7.757 · sin 46.5° − 2 · 1 · sin 46.5° = 9.81`` N.

    >>> from taut.model import example
    >>> robot = example("planar-4cable")
    >>> res = distribute_tensions(robot, [0.0, 0.0, 0.0])
    >>> np.round(res.tensions, 3)
    array([1.   , 1.   , 7.757, 7.757])
    >>> bool(distribute_tensions(robot, [0.0, 0.0, 0.0], tension_bounds=(1.0, 5.0)).feasible)
    False

    The adjustable platform's joint is passive: the lower cables 5-8 hold its upper body up.

    >>> res = distribute_tensions(example("adjustable-8cable"), [5, 5, 1.5, 0, 0, 0, 1.5])
    >>> bool(res.feasible), bool(res.tensions[4:].sum() > 0), res.actuator_forces.shape
    (True, True, (0,))
    """
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    W, w, bounds = equilibrium_equations(robot, poses, wrench=wrench, tension_bounds=tension_bounds)
    res = solve_tensions(W, w, tension_bounds=bounds, method=method)
    if not robot.n_joints:
        return res
    tensions, forces = _joined(np.asarray(res.tensions), robot.n_cables)
    return TensionResult(tensions, res.feasible, res.status, method, forces)
