"""Forward dynamics: the platform's acceleration under given cable tensions, and its motion.

:func:`acceleration` solves the equations of motion of :mod:`taut.dynamics._platform` for
``q̈`` at one state or a batch (compiled, :mod:`taut.dynamics._kernels`); :func:`rk4_step`
advances states by one classical Runge–Kutta step with the inputs held (the step of a control
loop); :func:`forward_dynamics` integrates a motion with :func:`scipy.integrate.solve_ivp`
(``RK45``, ``DOP853`` — the Dormand–Prince 8(5,3) pair of Hairer, Nørsett and Wanner —,
``Radau``, ``BDF``, ``LSODA``, ``RK23``) or fixed RK4 steps.  The cables are driven either by
tensions given as a function of time, or by commanded (unstretched) lengths ``l0(t)`` of
elastic cables: ``τ = EA (l − l0)/l0`` while ``l > l0``, and a slack cable pulls nothing
(Rushton 2022, Eq. 2.15; ``EA`` is each cable's ``stiffness``).  A sagging cable
(``cables[].weight``) is a quasi-static elastic catenary (Irvine 1981, §1.3,
:mod:`taut.dynamics._sagging`): given its tension, it is its tension at the platform end and it
pulls along the catenary's tangent there; given its unstrained length, the catenary through
its ends gives its pull (:func:`taut.cables.catenary_forces`); its mass is left out of the
platform's inertia.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.6, Eq. 2.15. (docs/references.bib: rushton2022)
.. [3] E. Hairer, S. P. Nørsett, G. Wanner, "Solving Ordinary Differential Equations I: Nonstiff
   Problems", 2nd ed., Springer, 1993 (the DOP853 code). (docs/references.bib: hairer1993)
.. [4] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic catenary).
   (docs/references.bib: irvine1981)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, replace
from time import perf_counter

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.dynamics._platform import (
    CONVENTION_FACTORS,
    PLANAR,
    SPATIAL,
    PlatformDynamics,
    as_rates,
    check_callable,
    platform_dynamics,
    positive,
)
from taut.dynamics._sagging import SaggingCables
from taut.errors import InfeasiblePoseError, SingularConfigurationError, TautError, UnsupportedRobotError
from taut.kinematics import as_poses, robot_stiffness, tension_from_stretch
from taut.model import MAX_MAGNITUDE, Robot

__all__ = [
    "IntegrationError",
    "ForwardDynamicsResult",
    "INTEGRATORS",
    "acceleration",
    "rk4_step",
    "cable_tensions",
    "forward_dynamics",
]

#: The integrators of :func:`forward_dynamics`: the methods of :func:`scipy.integrate.solve_ivp`
#: (adaptive, with ``rtol`` and ``atol``) and ``RK4`` (classical Runge–Kutta, fixed steps).
INTEGRATORS = ("RK45", "DOP853", "RK23", "Radau", "BDF", "LSODA", "RK4")


class IntegrationError(TautError):
    """The integrator failed: a step size underflow, a singular configuration on the way
    (gimbal lock, a zero-length cable), or a motion that leaves the representable range.

    Examples
    --------
    >>> from taut.dynamics import IntegrationError
    >>> from taut.errors import TautError
    >>> issubclass(IntegrationError, TautError)
    True
    """


@dataclass(frozen=True)
class ForwardDynamicsResult(Result):
    """A simulated motion at ``K`` times of a robot with ``n`` cables and ``dof`` coordinates
    (:func:`forward_dynamics`).

    Attributes
    ----------
    times : ndarray, shape (K,)
        [s].
    poses : ndarray, shape (K, dof)
    velocity : ndarray, shape (K, dof)
        Pose rates ``q̇``.
    tensions : ndarray, shape (K, n)
        The tensions that acted [N] (elastic cables: from the stretch).
    slack : ndarray of bool, shape (K, n)
        Elastic cables not stretched (always False for given tensions).
    beyond_limits : ndarray of bool, shape (K, n_joints)
        Joint coordinates outside their ``limits`` (the dynamics has no joint stops).
    method : str
        The integrator.
    evaluations : int
        Right-hand side evaluations.
    elapsed_s : float
        Wall-clock seconds of the integration.
    complete : bool
        The motion reaches the end of its duration.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import forward_dynamics
    >>> res = forward_dynamics(example("planar-4cable"), np.zeros(3), np.zeros(3), 0.1, tensions=lambda t: np.zeros(4), method="RK4", step=0.05)
    >>> res.times, res.complete, res.evaluations
    (array([0.  , 0.05, 0.1 ]), True, 8)
    """

    times: np.ndarray  #: ``(K,)``
    poses: np.ndarray  #: ``(K, dof)``
    velocity: np.ndarray  #: ``(K, dof)`` pose rates ``q̇``
    tensions: np.ndarray  #: ``(K, n)`` the tensions that acted (elastic cables: from the stretch)
    slack: np.ndarray  #: ``(K, n)`` bool: elastic cables not stretched (always False for given tensions)
    beyond_limits: np.ndarray  #: ``(K, n_joints)`` bool: joint coordinates outside their limits
    method: str
    evaluations: int  #: right-hand side evaluations
    elapsed_s: float = 0.0  #: wall-clock seconds of the integration
    complete: bool = True  #: the motion reaches the end of ``duration``


@dataclass(frozen=True)
class KernelModel:
    """The compiled kernels' arguments for one robot (:mod:`taut.dynamics._kernels`; cables
    straight or through swivelling pulleys, platforms with or without jointed bodies)."""

    pd: PlatformDynamics
    args: tuple[np.ndarray, np.ndarray, np.ndarray]
    n: int


_MODELS: dict[tuple[int, bool], tuple[Robot, KernelModel]] = {}


def kernel_model(robot: Robot, *, actuators: bool = False, sagging: bool = False) -> KernelModel:
    """The kernel arguments of ``robot``, built once per robot object (a control loop calls
    :func:`acceleration` thousands of times with the same robot).  With ``actuators`` the
    joint actuators follow the cables as inputs (:data:`taut.dynamics._tree.ACTUATOR` rows):
    ``n`` counts both.  The kernels pull along chords: a robot with sagging cables is
    refused unless its caller (``sagging``: :func:`forward_dynamics`, the control loop)
    applies their pull itself, the kernels' sagging cables pulling nothing."""
    if robot.sagging_cables and not sagging:
        raise UnsupportedRobotError(
            f"{robot.name}: acceleration, rk4_step and cable_tensions model straight cables, and its cables "
            f"{[i + 1 for i in robot.sagging_cables]} sag (cables[].weight); forward_dynamics and simulate_control "
            "(taut simulate) model them as quasi-static catenaries"
        )
    if robot.routed_cables and robot.is_point_mass:
        raise UnsupportedRobotError(
            f"{robot.name}: the dynamics of cables routed through via points (cables[].via) needs a rigid platform"
        )
    key = (id(robot), actuators)
    hit = _MODELS.get(key)
    if hit is not None and hit[0] is robot:
        return hit[1]
    from taut.dynamics._kernels import FLOAT_LAYOUT
    from taut.dynamics._tree import CABLE_COLUMNS, PLATFORM_FLOATS

    pd = platform_dynamics(robot)
    axes, T = CONVENTION_FACTORS[pd.orientation]
    Tm = np.array(T, dtype=float)
    d = pd.dimension
    cables = np.zeros((robot.n_cables, CABLE_COLUMNS))
    cables[:, :d], cables[:, 3 : 3 + d] = robot.exits, robot.anchors
    cables[:, 7] = robot.cable_bodies
    # EA of the straight elastic cables; 0 for the others, which then pull nothing when elastic
    cables[:, 6] = [0.0 if c.weight or c.stiffness is None else c.stiffness for c in robot.cables]
    if robot.swivel_cables:
        from taut.kinematics import swivel_parameters

        which, axes_, radii = swivel_parameters(robot)
        cables[which, 8 : 8 + d], cables[which, 11] = axes_, radii
    fp = np.zeros(PLATFORM_FLOATS)
    fp[FLOAT_LAYOUT["mass"]] = pd.mass
    fp[FLOAT_LAYOUT["com"]][: pd.dimension] = pd.com
    fp[FLOAT_LAYOUT["inertia"]] = pd.inertia.ravel()
    if pd.kind == SPATIAL:
        fp[FLOAT_LAYOUT["inertia_inv"]] = np.linalg.inv(pd.inertia).ravel()
    fp[FLOAT_LAYOUT["force"]][: pd.dimension] = pd.force
    fp[FLOAT_LAYOUT["moment"]][: pd.moment.size] = pd.moment
    fp[FLOAT_LAYOUT["T"]] = Tm.ravel()
    fp[FLOAT_LAYOUT["Tinv"]] = np.linalg.inv(Tm).ravel()
    ip = np.array([pd.kind, *axes], dtype=np.int64)
    if robot.n_joints or robot.routed_cables:
        ip, fp = _tree_arrays(robot, pd, ip, fp)
    if actuators and robot.actuated_joints.size:
        from taut.dynamics._tree import ACTUATOR

        rows = np.zeros((robot.actuated_joints.size, CABLE_COLUMNS))
        rows[:, 7] = ACTUATOR - robot.actuated_joints
        cables = np.concatenate([cables, rows])
    model = KernelModel(pd, (ip, fp, cables), cables.shape[0])
    if len(_MODELS) >= 16:
        _MODELS.pop(next(iter(_MODELS)))
    _MODELS[key] = (robot, model)
    return model


def _tree_arrays(robot: Robot, pd: PlatformDynamics, ip: np.ndarray, fp: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``ip`` and ``fp`` of a jointed platform, or of one with routed cables, for
    :mod:`taut.dynamics._tree`: the platform's, then its bodies' joints, masses and inertias
    (:func:`taut.dynamics._jointed.body_inertia` names a body without them), then the via
    points of the routed cables."""
    from taut.dynamics._jointed import body_inertia
    from taut.dynamics._tree import BODY_FLOATS, JOINTED, VIA_FLOATS

    if pd.kind not in (PLANAR, SPATIAL):
        raise UnsupportedRobotError(f"{robot.name}: the dynamics of jointed bodies needs a rigid platform")
    inertia = body_inertia(robot)
    index = {"platform": 0} | {b.name: k for k, b in enumerate(robot.platform.bodies, 1)}
    bodies = robot.platform.bodies
    parents = [index[b.parent] for b in bodies]
    revolute = [int(b.joint.kind == "revolute") for b in bodies]
    extra = np.zeros((len(bodies), BODY_FLOATS))
    d = robot.dimension
    for k, body in enumerate(bodies):
        axis = np.zeros(3)
        if revolute[k] and d == 2:
            axis[2] = 1.0
        else:
            axis[:d] = np.asarray(body.joint.axis, dtype=float)
            axis /= np.linalg.norm(axis)
        extra[k, :3] = axis
        if body.joint.origin is not None:
            extra[k, 3 : 3 + d] = body.joint.origin
        extra[k, 6] = inertia.masses[k + 1]
        extra[k, 7:10] = inertia.coms[k + 1]
        extra[k, 10:19] = inertia.inertias[k + 1].ravel()
        extra[k, 19:22] = inertia.forces[k + 1]
    cables, via_bodies, points = robot.via_points
    vias = np.zeros((cables.size, VIA_FLOATS))
    vias[:, 0], vias[:, 1], vias[:, 2 : 2 + d] = cables, via_bodies, points
    ip = np.array([JOINTED, *ip[1:4], pd.kind, len(bodies), *parents, *revolute, cables.size], dtype=np.int64)
    return ip, np.concatenate([fp, extra.ravel(), vias.ravel()])


def _status_error(robot: Robot, status: np.ndarray, where: str) -> TautError:
    from taut.dynamics._kernels import GIMBAL_LOCK
    from taut.dynamics._tree import SINGULAR_INERTIA

    k = int(np.flatnonzero(status)[0])
    if status[k] == GIMBAL_LOCK:
        return SingularConfigurationError(
            f"{robot.name}: {where} {k + 1}: the orientation is at the gimbal lock of the "
            f"{robot.orientation} convention (the angle rates are undefined)"
        )
    if status[k] == SINGULAR_INERTIA:
        return SingularConfigurationError(
            f"{robot.name}: {where} {k + 1}: the mass matrix is singular (a body without inertia about its joint axis)"
        )
    return InfeasiblePoseError(
        f"{robot.name}: {where} {k + 1}: a cable has no direction (zero length, or its anchor on a swivel axis "
        "or on its pulley)"
    )


def _inputs(
    robot: Robot, q: npt.ArrayLike, qd: npt.ArrayLike, u: npt.ArrayLike, w_ext: npt.ArrayLike | None, what: str
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool]:
    """States, cable inputs and wrenches as C-contiguous ``(N, ·)`` arrays."""
    dof = robot.pose_size
    quick = quick_rows(robot, q, ((qd, dof), (u, robot.n_cables), (w_ext, dof)))
    if quick is None:
        return _checked_inputs(robot, q, qd, u, w_ext, what)
    (arr, vel, cab, w), single = quick
    return arr, vel, cab, w, single


def quick_rows(
    robot: Robot, q: npt.ArrayLike, others: tuple[tuple[npt.ArrayLike | None, int], ...]
) -> tuple[list[np.ndarray], bool] | None:
    """Poses ``q`` and per-pose arrays ``others`` (value, width; None for zeros) as
    C-contiguous ``(N, ·)`` arrays, and whether ``q`` was one pose, when the shapes are right
    and every value is finite (and the poses within ``MAX_MAGNITUDE``, like
    :func:`~taut.kinematics.as_poses`) — checked in a few operations, because a control
    loop calls this every step; None otherwise, and the caller's full checks name the problem.
    Not for jointed platforms (no joint limits are checked)."""
    try:
        arr = np.asarray(q, dtype=float)
        rest = [np.zeros(width) if x is None else np.asarray(x, dtype=float) for x, width in others]
    except (TypeError, ValueError):
        return None
    single = arr.ndim == 1
    N = 1 if single else (arr.shape[0] if arr.ndim == 2 else 0)
    if arr.shape[-1:] != (robot.pose_size,) or N == 0 or robot.n_joints:
        return None
    total = 0.0
    for x, (_, width) in zip(rest, others):
        if x.shape not in ((width,), (1, width), (N, width)):
            return None
        flat = x.ravel()
        total += float(flat @ flat)
    flat = arr.ravel()
    size = float(flat @ flat)
    if not (math.isfinite(total + size) and size <= 1e18):
        return None
    return [_rows(arr, N)] + [_rows(x, N) for x in rest], single


def _rows(x: np.ndarray, N: int) -> np.ndarray:
    """``x`` of shape ``(k,)``, ``(1, k)`` or ``(N, k)`` as a C-contiguous ``(N, k)`` array."""
    if x.ndim == 1:
        x = x.reshape(1, -1)
    if x.shape[0] != N:
        x = np.repeat(x, N, axis=0)
    return np.ascontiguousarray(x)


def _checked_inputs(
    robot: Robot, q: npt.ArrayLike, qd: npt.ArrayLike, u: npt.ArrayLike, w_ext: npt.ArrayLike | None, what: str
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool]:
    arr, single = as_poses(robot, q)
    N = arr.shape[0]
    vel = np.ascontiguousarray(as_rates(robot, qd, N))
    try:
        cab = np.asarray(u, dtype=float)
    except (TypeError, ValueError):
        raise TautError(f"{what} must be numbers") from None
    if cab.shape[-1:] != (robot.n_cables,) or cab.ndim > 2 or (cab.ndim == 2 and cab.shape[0] not in (1, N)):
        raise TautError(
            f"{robot.name}: {what} must have shape ({robot.n_cables},) or ({N}, {robot.n_cables}), got {cab.shape}"
        )
    if not np.isfinite(cab).all():
        raise TautError(f"{robot.name}: {what} are not finite")
    cab = np.ascontiguousarray(np.broadcast_to(cab, (N, robot.n_cables)))
    w = np.zeros((N, robot.pose_size)) if w_ext is None else np.array(as_rates(robot, w_ext, N, "external wrenches"))
    return np.ascontiguousarray(arr), vel, cab, w, single


def _accelerate(
    robot: Robot, model: KernelModel, q: np.ndarray, qd: np.ndarray, u: np.ndarray, w: np.ndarray, elastic: bool
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(q̈, τ, status)`` of ``N`` validated states."""
    from taut.dynamics._kernels import accelerations

    N = q.shape[0]
    qdd = np.empty((N, robot.pose_size))
    status = np.empty(N, np.int64)
    tau = np.empty((N, model.n))
    accelerations(*model.args, elastic, q, qd, u, w, qdd, tau, status)
    return qdd, tau, status


def acceleration(
    robot: Robot,
    q: npt.ArrayLike,
    qd: npt.ArrayLike,
    tensions: npt.ArrayLike,
    *,
    wrench: npt.ArrayLike | None = None,
) -> np.ndarray:
    """The pose accelerations ``q̈`` of the platform under given cable tensions.

    The solution of ``M q̈ + C q̇ + g = Jᵀ (W τ + w)`` (compiled Newton–Euler), with ``w`` an
    external wrench besides the robot's own weight.  On a platform carrying jointed bodies
    ``q`` holds the joint coordinates too, ``W`` is the cable part of the jointed structure
    matrix (:func:`taut.kinematics.jointed_structure_matrix`) and ``w`` a wrench on the
    platform followed by joint forces (joint actuators; zero: passive joints).

    Parameters
    ----------
    robot : Robot
    q, qd : array_like, shape (N, dof) or (dof,)
        Poses and pose rates.
    tensions : array_like, shape (N, n) or (n,)
        Cable tensions [N].
    wrench : array_like, shape (N, dof) or (dof,), optional
        External wrench (taut's convention: forces, then moments about ``p``, fixed frame).

    Returns
    -------
    ndarray, shape (N, dof) or (dof,) for one state

    Raises
    ------
    TautError
        Bad shapes or values (:class:`~taut.errors.PoseError` for poses and rates).
    SingularConfigurationError
        At the gimbal lock of the orientation convention.
    InfeasiblePoseError
        Where a cable has zero length.
    UnsupportedRobotError
        For a robot without mass or inertia (a jointed platform: any of its bodies, named).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
           and Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)

    Examples
    --------
    Equal tensions at the centre of the planar robot cancel: the platform falls at ``g``.

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import acceleration
    >>> acceleration(example("planar-4cable"), np.zeros(3), np.zeros(3), np.full(4, 10.0)).round(4) + 0.0
    array([ 0.  , -9.81,  0.  ])
    """
    model = kernel_model(robot)
    arr, vel, tau, w, single = _inputs(robot, q, qd, tensions, wrench, "tensions")
    qdd, _, status = _accelerate(robot, model, arr, vel, tau, w, False)
    if status.any():
        raise _status_error(robot, status, "state")
    return qdd[0] if single else qdd


def cable_tensions(robot: Robot, q: npt.ArrayLike, unstretched: npt.ArrayLike) -> np.ndarray:
    """The tensions ``EA (l − l0)/l0`` of elastic cables of unstretched lengths ``l0``, zero for
    a slack cable (Rushton 2022, Eq. 2.15).

    Parameters
    ----------
    robot : Robot
        Every cable with a ``stiffness`` (``EA``).
    q : array_like, shape (N, dof) or (dof,)
        Poses.
    unstretched : array_like, shape (N, n) or (n,)
        Unstretched lengths ``l0`` [m], positive.

    Returns
    -------
    ndarray, shape (N, n) or (n,) for one pose
        [N].

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.
    TautError
        Lengths of the wrong shape, not positive or not finite; a cable without stiffness.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)

    Examples
    --------
    Cables of ``EA = 20`` kN stretched by 0.1 %:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.kinematics import cable_lengths
    >>> from taut.dynamics import cable_tensions
    >>> robot = example("planar-4cable")
    >>> robot = robot.model_copy(update={"cables": tuple(c.model_copy(update={"stiffness": 2e4}) for c in robot.cables)})
    >>> cable_tensions(robot, np.zeros(3), cable_lengths(robot, np.zeros(3)) / 1.001).round(6)
    array([20., 20., 20., 20.])
    """
    from taut.kinematics import lengths_at

    arr, single = as_poses(robot, q)
    l0 = _unstretched(robot, unstretched, arr.shape[0])
    tau = tension_from_stretch(lengths_at(robot, arr), l0, robot_stiffness(robot))
    return tau[0] if single else tau


def _unstretched(robot: Robot, l0: npt.ArrayLike, N: int) -> np.ndarray:
    try:
        arr = np.asarray(l0, dtype=float)
    except (TypeError, ValueError):
        raise TautError("commanded cable lengths must be numbers") from None
    if arr.shape[-1:] != (robot.n_cables,) or arr.ndim > 2:
        raise TautError(
            f"{robot.name}: commanded cable lengths must have {robot.n_cables} entries, got shape {arr.shape}"
        )
    if not np.isfinite(arr).all() or (arr <= 0).any():
        raise TautError(f"{robot.name}: commanded cable lengths must be positive and finite, got {arr.tolist()}")
    return np.ascontiguousarray(np.broadcast_to(arr, (N, robot.n_cables)))


def rk4_step(
    robot: Robot,
    q: npt.ArrayLike,
    qd: npt.ArrayLike,
    tensions: npt.ArrayLike,
    dt: float,
    *,
    wrench: npt.ArrayLike | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """One classical Runge–Kutta (RK4) step from each state, the inputs held over the step.

    The tensions and the external wrench are held (a zero-order hold, as a controller applies
    them).

    Parameters
    ----------
    robot : Robot
    q, qd : array_like, shape (N, dof) or (dof,)
        Poses and pose rates.
    tensions : array_like, shape (N, n) or (n,)
        Cable tensions [N].
    dt : float
        The step [s], positive.
    wrench : array_like, shape (N, dof) or (dof,), optional
        External wrench besides the robot's weight.

    Returns
    -------
    q, qd : ndarray, shape (N, dof) or (dof,) for one state
        The state after the step.

    Raises
    ------
    TautError
        Bad shapes or values, a step that is not a positive number.
    SingularConfigurationError, InfeasiblePoseError
        When a stage reaches a singular configuration (as :func:`acceleration`).

    References
    ----------
    .. [1] E. Hairer, S. P. Nørsett, G. Wanner, "Solving Ordinary Differential Equations I",
       2nd ed., Springer, 1993, §II.1. (docs/references.bib: hairer1993)

    Examples
    --------
    Slack cables: the platform falls ``g t²/2`` in ``t = 0.1`` s (RK4 is exact on a constant
    acceleration):

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import rk4_step
    >>> rk4_step(example("planar-4cable"), np.zeros(3), np.zeros(3), np.zeros(4), 0.1)
    (array([ 0.     , -0.04905,  0.     ]), array([ 0.   , -0.981,  0.   ]))
    """
    h = positive(dt, "the time step dt")
    model = kernel_model(robot)
    arr, vel, tau, w, single = _inputs(robot, q, qd, tensions, wrench, "tensions")
    qn, vn = _rk4(robot, model, arr, vel, tau, w, h, False)
    return (qn[0], vn[0]) if single else (qn, vn)


def _rk4(
    robot: Robot,
    model: KernelModel,
    q: np.ndarray,
    qd: np.ndarray,
    u: np.ndarray,
    w: np.ndarray,
    dt: float,
    elastic: bool,
) -> tuple[np.ndarray, np.ndarray]:
    from taut.dynamics._kernels import rk4_steps

    status = np.zeros(q.shape[0], np.int64)
    qn, vn = np.empty_like(q), np.empty_like(qd)
    rk4_steps(*model.args, elastic, q, qd, u, w, dt, qn, vn, status)
    if status.any():
        raise _status_error(robot, status, "state")
    return qn, vn


def sagging_accelerate(
    model: KernelModel, sag: SaggingCables, q: np.ndarray, qd: np.ndarray, u: np.ndarray, w: np.ndarray, elastic: bool
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """:func:`_accelerate` of one state ``(1, ·)`` of a robot with sagging cables: their inputs
    ``u`` (tensions at the platform, or with ``elastic`` unstrained lengths) go to their
    catenaries, whose pull joins the external wrench; the tensions returned are theirs at the
    platform.  Raises a :class:`~taut.errors.TautError` where a catenary has no solution."""
    from taut.dynamics._kernels import accelerations

    held = u[0, sag.which]
    straight = u.copy()
    # the kernels' sagging cables pull nothing: no tension, or a length with EA = 0
    straight[0, sag.which] = 1.0 if elastic else 0.0
    pull, tensions = sag.pull_lengths(q[0], held) if elastic else (sag.pull(q[0], held), held)
    qdd, status = np.empty_like(q), np.empty(1, np.int64)
    tau = np.empty((1, model.n))
    accelerations(*model.args, elastic, q, qd, straight, w + pull, qdd, tau, status)
    tau[0, sag.which] = tensions
    return qdd, tau, status


def sagging_rk4(
    robot: Robot,
    model: KernelModel,
    sag: SaggingCables,
    q: np.ndarray,
    qd: np.ndarray,
    u: np.ndarray,
    w: np.ndarray,
    dt: float,
    elastic: bool,
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`_rk4` of one state ``(1, ·)`` of a robot with sagging cables: the stages of
    :func:`taut.dynamics._kernels.rk4_steps`, the catenaries solved at each
    (:func:`sagging_accelerate`)."""

    def acceleration(x: np.ndarray, v: np.ndarray) -> np.ndarray:
        a, _, status = sagging_accelerate(model, sag, x, v, u, w, elastic)
        if status.any():
            raise _status_error(robot, status, "state")
        return a

    half = 0.5 * dt
    a1 = acceleration(q, qd)
    v2 = qd + half * a1
    a2 = acceleration(q + half * qd, v2)
    v3 = qd + half * a2
    a3 = acceleration(q + half * v2, v3)
    v4 = qd + dt * a3
    a4 = acceleration(q + dt * v3, v4)
    return q + dt / 6.0 * (qd + 2.0 * v2 + 2.0 * v3 + v4), qd + dt / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4)


def _call(f: Callable[[float], npt.ArrayLike], t: float, what: str, shape: tuple[int, ...]) -> np.ndarray:
    try:
        v = np.asarray(f(t), dtype=float)
    except TautError:
        raise
    except (TypeError, ValueError) as e:
        raise TautError(f"{what} at t = {t:g} s: not numbers ({e})") from None
    if v.shape != shape:
        raise TautError(f"{what} at t = {t:g} s: expected shape {shape}, got {v.shape}")
    if not np.isfinite(v).all():
        raise TautError(f"{what} at t = {t:g} s: not finite")
    return v


def forward_dynamics(
    robot: Robot,
    q0: npt.ArrayLike,
    qd0: npt.ArrayLike,
    duration: float,
    *,
    tensions: Callable[[float], npt.ArrayLike] | None = None,
    lengths: Callable[[float], npt.ArrayLike] | None = None,
    wrench: Callable[[float], npt.ArrayLike] | None = None,
    method: str = "DOP853",
    rtol: float = 1e-9,
    atol: float = 1e-12,
    step: float | None = None,
    times: npt.ArrayLike | None = None,
    progress: Callable[[int, int | None], None] | None = None,
) -> ForwardDynamicsResult:
    """The platform's motion from ``(q0, q̇0)`` at ``t = 0`` over ``duration`` seconds.

    Exactly one input drives the cables: ``tensions(t)``, or ``lengths(t)``, the commanded
    unstretched lengths of elastic cables (each cable's ``stiffness`` is its ``EA``; a slack
    cable pulls nothing).  A sagging cable (``cables[].weight``) is a quasi-static elastic
    catenary: its tension is the one at the platform end, along the catenary's tangent there,
    and its length gives its pull by :func:`taut.cables.catenary_forces` (inextensible without
    a ``stiffness``); both are solved at every stage of the integrator, and its mass is left
    out of the platform's inertia.

    A platform carrying jointed bodies (``platform.bodies``, prismatic and revolute joints in
    a tree) moves in its pose and joint coordinates under the tree's dynamics
    (:mod:`taut.dynamics._tree`; every body needs a mass and an inertia).  Its joints are
    passive unless ``wrench(t)`` gives joint forces after the platform wrench (joint
    actuators).  The model has no joint stops: a joint coordinate that leaves its ``limits``
    is reported in :attr:`ForwardDynamicsResult.beyond_limits`, not stopped.

    Parameters
    ----------
    robot : Robot
    q0, qd0 : array_like, shape (dof,)
        The initial pose and pose rates.
    duration : float
        [s], positive.
    tensions : callable, optional
        ``tensions(t) -> (n,)`` [N].
    lengths : callable, optional
        ``lengths(t) -> (n,)``: commanded unstretched lengths [m].
    wrench : callable, optional
        ``wrench(t) -> (dof,)``: an external wrench besides the robot's weight.
    method : str, optional
        One of :data:`INTEGRATORS`: a method of :func:`scipy.integrate.solve_ivp`, or
        ``"RK4"`` (fixed steps of ``step`` seconds, inputs evaluated at each step's start and
        held over it; output at every step).
    rtol, atol : float, optional
        The adaptive integrators' relative and absolute tolerances.
    step : float, optional
        ``RK4``: the step [s] (required); adaptive: the largest step.
    times : array_like, shape (K,), optional
        Adaptive: the output times, increasing, in ``[0, duration]``; default the
        integrator's own steps.
    progress : callable, optional
        ``progress(done, total)``.

    Returns
    -------
    ForwardDynamicsResult

    Raises
    ------
    TautError
        Bad input (no or two drives, an unknown method, a callable returning the wrong shape
        or non-finite values, a non-positive duration, step or tolerance).
    UnsupportedRobotError
        Sagging cables on a platform with jointed bodies.
    IntegrationError
        When the integrator fails or the motion reaches a singular configuration.  A trial
        stage of an adaptive step that leaves the representable range (a coordinate beyond
        :data:`~taut.kinematics._pose.MAX_MAGNITUDE`) or reaches a singular configuration
        only makes the step controller reject that step; the range is checked on the
        accepted steps.

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
    .. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eq. 2.15. (docs/references.bib: rushton2022)
    .. [3] E. Hairer, S. P. Nørsett, G. Wanner, "Solving Ordinary Differential Equations I",
       2nd ed., Springer, 1993 (the DOP853 code). (docs/references.bib: hairer1993)
    .. [4] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic
       catenary). (docs/references.bib: irvine1981)

    Examples
    --------
    Slack cables: the platform falls ``g t²/2 = 0.04905`` m in 0.1 s.

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import forward_dynamics
    >>> robot = example("planar-4cable")
    >>> res = forward_dynamics(robot, np.zeros(3), np.zeros(3), 0.1, tensions=lambda t: np.zeros(4), times=[0.1])
    >>> res.poses.round(6) + 0.0
    array([[ 0.     , -0.04905,  0.     ]])
    """
    if (tensions is None) == (lengths is None):
        raise TautError("forward dynamics needs exactly one of tensions(t) and lengths(t)")
    for f, what in ((tensions, "tensions"), (lengths, "lengths"), (wrench, "wrench"), (progress, "progress")):
        check_callable(f, what)
    if not isinstance(method, str) or method not in INTEGRATORS:
        raise TautError(f"unknown integrator {method!r}; valid methods: {', '.join(INTEGRATORS)}")
    duration = positive(duration, "duration")
    step = None if step is None else positive(step, "step")
    rtol, atol = positive(rtol, "rtol"), positive(atol, "atol")
    sag = SaggingCables(robot) if robot.sagging_cables else None
    model = kernel_model(robot, sagging=sag is not None)
    elastic = lengths is not None
    if elastic and sag is None:
        robot_stiffness(robot)
    elif elastic:
        rigid = [i + 1 for i, c in enumerate(robot.cables) if not c.weight and c.stiffness is None]
        if rigid:
            raise TautError(f"{robot.name}: commanded lengths need the stiffness of the straight cables {rigid}")
    n, dof = robot.n_cables, robot.pose_size
    drive = lengths if lengths is not None else tensions
    assert drive is not None
    what = "commanded cable lengths" if elastic else "tensions"

    def inputs(t: float) -> tuple[np.ndarray, np.ndarray]:
        u = _call(drive, t, what, (n,))
        if elastic:
            u = _unstretched(robot, u, 1)[0]
        w = np.zeros(dof) if wrench is None else _call(wrench, t, "external wrench", (dof,))
        return u[None], w[None]

    x0, v0, _, _, _ = _inputs(robot, q0, qd0, np.zeros(n), None, "tensions")
    if x0.shape[0] != 1:
        raise TautError(f"{robot.name}: one initial pose, got {x0.shape[0]}")
    started = perf_counter()
    if method == "RK4":
        res = _fixed_steps(robot, (model, sag), x0[0], v0[0], float(duration), step, inputs, elastic, progress)
    else:
        res = _adaptive(
            robot,
            (model, sag),
            x0[0],
            v0[0],
            float(duration),
            inputs,
            elastic,
            method,
            rtol,
            atol,
            step,
            times,
            progress,
        )
    return replace(res, elapsed_s=perf_counter() - started)


def _fixed_steps(
    robot: Robot,
    models: tuple[KernelModel, SaggingCables | None],
    q: np.ndarray,
    qd: np.ndarray,
    duration: float,
    step: float | None,
    inputs: Callable[[float], tuple[np.ndarray, np.ndarray]],
    elastic: bool,
    progress: Callable[[int, int | None], None] | None,
) -> ForwardDynamicsResult:
    if step is None:
        raise TautError("method 'RK4' needs a step size (step=...)")
    model, sag = models
    K = int(np.ceil(duration / step - 1e-9))
    time = np.minimum(np.arange(K + 1) * step, duration)
    Q, V = np.empty((K + 1, q.size)), np.empty((K + 1, q.size))
    taus = np.zeros((K + 1, robot.n_cables))
    Q[0], V[0] = q, qd
    x, v = q[None], qd[None]
    for k in range(K + 1):
        u, w = inputs(float(time[k]))
        try:
            if sag is not None:
                taus[k] = sagging_accelerate(model, sag, x, v, u, w, elastic)[1][0, : robot.n_cables]
            elif elastic:
                taus[k] = cable_tensions(robot, x, u)[0]
            else:
                taus[k] = u[0]
            if k == K:
                break
            dt = float(time[k + 1] - time[k])
            x, v = (
                _rk4(robot, model, x, v, u, w, dt, elastic)
                if sag is None
                else sagging_rk4(robot, model, sag, x, v, u, w, dt, elastic)
            )
        except TautError as e:
            raise IntegrationError(f"RK4 failed at t = {time[k]:g} s: {e}") from None
        if not (np.isfinite(x).all() and np.isfinite(v).all()) or np.abs(x).max() > MAX_MAGNITUDE:
            raise IntegrationError(f"RK4 diverged at t = {time[k + 1]:g} s (step {step:g} s too large?)")
        Q[k + 1], V[k + 1] = x[0], v[0]
        if progress is not None:
            progress(k + 1, K)
    return _result(robot, time, Q, V, taus, elastic, "RK4", 4 * K)


def _adaptive(
    robot: Robot,
    models: tuple[KernelModel, SaggingCables | None],
    q: np.ndarray,
    qd: np.ndarray,
    duration: float,
    inputs: Callable[[float], tuple[np.ndarray, np.ndarray]],
    elastic: bool,
    method: str,
    rtol: float,
    atol: float,
    step: float | None,
    times: npt.ArrayLike | None,
    progress: Callable[[int, int | None], None] | None,
) -> ForwardDynamicsResult:
    from scipy import integrate

    model, sag = models
    dof = q.size
    t_eval = None
    if times is not None:
        try:
            t_eval = np.asarray(times, dtype=float)
        except (TypeError, ValueError):
            raise TautError(f"output times must be numbers, got {times!r}") from None
        if t_eval.ndim != 1 or not np.isfinite(t_eval).all() or (np.diff(t_eval) <= 0).any():
            raise TautError("output times must be finite and increasing")
        if t_eval.size and (t_eval[0] < 0 or t_eval[-1] > duration):
            raise TautError(f"output times must lie in [0, {duration:g}] s")
    failures: list[str] = []

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        # A trial stage of an adaptive step may leave the representable range or reach a
        # singular configuration; NaN makes the step controller reject the step (its error
        # norm is NaN), and only a failure of the integrator itself is reported.
        x, v = y[None, :dof], y[None, dof:]
        u, w = inputs(t)
        if not (np.isfinite(y).all() and np.abs(x).max() <= MAX_MAGNITUDE):
            failures.append(f"the motion left the representable range at t = {t:g} s")
            return np.full_like(y, np.nan)
        try:
            x, v = np.ascontiguousarray(x), np.ascontiguousarray(v)
            if sag is None:
                a, _, status = _accelerate(robot, model, x, v, u, w, elastic)
            else:
                a, _, status = sagging_accelerate(model, sag, x, v, u, w, elastic)
        except TautError as e:
            failures.append(f"at t = {t:g} s: {e}")
            return np.full_like(y, np.nan)
        if status[0]:
            failures.append(f"at t = {t:g} s: {_status_error(robot, status, 'state')}")
            return np.full_like(y, np.nan)
        return np.concatenate([v[0], a[0]])

    y0 = np.concatenate([q, qd])
    if not np.isfinite(rhs(0.0, y0)).all():
        raise IntegrationError(f"{method} failed: {failures[-1]}")
    options: dict[str, float] = {"rtol": rtol, "atol": atol}
    if step is not None:
        options["max_step"] = step
    solver = getattr(integrate, method)(rhs, 0.0, y0, duration, **options)
    out_t: list[float] = []
    out_y: list[np.ndarray] = []
    if t_eval is None or (t_eval.size and t_eval[0] == 0.0):
        out_t.append(0.0)
        out_y.append(y0)
    while solver.status == "running":
        t_old = solver.t
        message = solver.step()
        if solver.status == "failed":
            raise IntegrationError(f"{method} failed: {failures[-1] if failures else message}")
        t, y = float(solver.t), solver.y
        # the range is checked on accepted steps only
        if not (np.isfinite(y).all() and np.abs(y[:dof]).max() <= MAX_MAGNITUDE):
            raise IntegrationError(f"{method} failed: the motion left the representable range at t = {t:g} s")
        if t_eval is None:
            out_t.append(t)
            out_y.append(y.copy())
        else:
            inside = t_eval[(t_eval > t_old) & (t_eval <= t)]
            if inside.size:
                out_t.extend(inside.tolist())
                out_y.extend(np.atleast_2d(solver.dense_output()(inside).T))
        if progress is not None:
            progress(min(int(t / duration * 1000), 1000), 1000)
    Y = np.array(out_y, dtype=float).reshape(len(out_t), 2 * dof)
    if not np.isfinite(Y).all():
        raise IntegrationError(f"{method} failed: the solution is not finite")
    times_out = np.array(out_t, dtype=float)
    taus = np.array([inputs(float(t))[0][0] for t in times_out]).reshape(len(times_out), robot.n_cables)
    if sag is not None:
        for k, (t, y) in enumerate(zip(times_out, Y)):
            u, w = inputs(float(t))
            taus[k] = sagging_accelerate(model, sag, y[None, :dof], y[None, dof:], u, w, elastic)[1][0]
    elif elastic:
        taus = cable_tensions(robot, Y[:, :dof], taus) if len(times_out) else taus
    return _result(robot, times_out, Y[:, :dof], Y[:, dof:], taus, elastic, method, int(solver.nfev) + 1)


def _result(
    robot: Robot,
    time: np.ndarray,
    Q: np.ndarray,
    V: np.ndarray,
    taus: np.ndarray,
    elastic: bool,
    method: str,
    nfev: int,
) -> ForwardDynamicsResult:
    slack = taus <= 0 if elastic else np.zeros(taus.shape, dtype=bool)
    limits, joints = robot.joint_limits, Q[:, robot.wrench_dim :]
    beyond = (joints < limits[:, 0]) | (joints > limits[:, 1])
    t, q, v, tau, sl, out = (np.array(a) for a in (time, Q, V, taus, slack, beyond))
    return ForwardDynamicsResult(t, q, v, tau, sl, out, method=method, evaluations=nfev)
