"""Closed-loop control of the platform: a computed-torque controller with the tension
distribution in the loop, simulated against the robot's own dynamics.

At each control update ``t_k = k / rate`` the controller reads the state ``(q, q̇)`` and the
reference ``(q_r, q̇_r, q̈_r)`` of a :class:`~taut.motion.Motion` and commands

    ``q̈_cmd = q̈_r + K_d ė + K_p e``,  ``e = q_r − q``,
    ``W τ = M̂ q̈_cmd + Ĉ q̇ + ĝ`` (in generalized forces, ``Jᵀ W τ``),

the inverse-dynamics (computed-torque) law of Siciliano et al. 2009, §8.5.2, with the
pose as the generalized coordinates and ``M̂, Ĉ, ĝ`` the controller's model, which may differ
from the plant (:func:`with_mass_error`).  The wrench is turned into tensions by a tension
distribution (:meth:`taut.dynamics.LoopModel.tensions`: the compiled closed form, and
``method`` where it gives up).  The tensions are held over the control period (zero-order
hold) while the plant, with its exact model and an optional external wrench ``w_d(t)``, is
integrated by ``substeps`` RK4 steps (:meth:`~taut.dynamics.LoopModel.step`).

A hold delays the command by half a period on average, which leaves an error of first order
in the period even with an exact model.  With ``predict`` (the default) the law is evaluated
at the state predicted half a period ahead, ``q + (h/2) q̇ + (h²/8) a``, ``q̇ + (h/2) a``, with
``a`` the acceleration measured over the last period (velocity difference; the commanded one
at the start), against the reference at the middle of the period: the error becomes second
order (about 4 times smaller at twice the rate).  Measuring ``a`` rather than assuming the
commanded one keeps the loop's static gain: a constant disturbance is met by ``K_p e``
exactly.

A platform carrying jointed bodies (prismatic and revolute joints in a tree) is controlled
in its pose and joint coordinates alike: ``M̂``, ``ĥ`` are the tree's
(:mod:`taut.dynamics._tree`), the wrench is the generalized force in the twist coordinates
and the distribution solves it with the cable columns of the jointed structure matrix and,
for the joints with an actuator (``joint.actuator``), one unit column each with the
actuator's bounds (:func:`taut.statics.solve_inputs`); the other joints are passive, moved by
the cables acting across them.  The plant has no joint stops: an
update at which a joint coordinate is outside its limits is counted and its time reported.

Sagging cables (``cables[].weight``) are quasi-static elastic catenaries (Irvine 1981,
§1.3): the commanded tension of such a cable is its tension at the platform end, and it pulls
along the catenary's tangent at the anchor, which depends on that tension and on the pose
(:mod:`taut.dynamics._sagging`).  The distribution uses the structure matrix of those
tangents, iterated to consistency with the catenaries as :func:`taut.cables.sagging_ik` does
(both ends of the cable within its bounds), and the plant recomputes each catenary at every
stage of its RK4 steps, the tension held.  The cables' own inertia is neglected: their mass
does not join the platform's.

Angle errors take the short way: the orientation components of ``e`` are wrapped into
``[−π, π)``.  The error is thus measured in the pose coordinates the law is written in, so
that with an exact model and no disturbance it obeys ``ë + K_d ė + K_p e = 0`` (up to the
hold); the rotation error (the angle of ``R_rᵀ R``) is reported besides.

When the distribution finds no admissible tensions at an update, the last admissible
tensions are held and the update is counted (its time is reported), as CASPR's controllers
do (Lau et al. 2016).  A start without admissible tensions has nothing to hold and raises.

With the model scaled by ``1 + ε`` (``M̂ = (1 + ε) M``, ``ĥ = (1 + ε) h``: a mass and inertia
error, with no constant ``platform.wrench``) and an exact distribution, the error obeys

    ``ë + (1 + ε) K_d ė + (1 + ε) K_p e = −ε (q̈_r + M⁻¹ h) − M⁻¹ Jᵀ w_d``,

so where the gains leave it critically damped or overdamped (an impulse response without
sign change, of integral ``1 / ((1 + ε) K_p)``) each coordinate's error from rest is at
most ``sup |right-hand side| / ((1 + ε) K_p)`` (``tests/dynamics/test_control.py`` checks
this bound).

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §8.5.2 (inverse dynamics control). (docs/references.bib: siciliano2009)
.. [2] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
.. [3] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic catenary).
   (docs/references.bib: irvine1981)
"""

from __future__ import annotations

import math
import numbers
from collections.abc import Callable
from dataclasses import dataclass
from time import perf_counter
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.dynamics._forward import IntegrationError
from taut.dynamics._loop import LoopModel, loop_model
from taut.dynamics._platform import as_rates, check_callable, positive
from taut.dynamics._sagging import cable_model
from taut.errors import InfeasiblePoseError, TautError
from taut.model import MAX_MAGNITUDE, Robot
from taut.motion import Motion, angle_columns

__all__ = [
    "DEFAULT_KP",
    "DEFAULT_KD",
    "MAX_RESULT_BYTES",
    "MAX_STEPS",
    "ControlResult",
    "WrenchSteps",
    "simulate_control",
    "with_mass_error",
]

#: Default proportional gain ``K_p`` of :func:`simulate_control` [1/s²]: a natural frequency of
#: 20 rad/s.
DEFAULT_KP = 400.0
#: Default derivative gain ``K_d`` of :func:`simulate_control` [1/s]: damping ratio 1.1,
#: overdamped even with a 10 % heavier model
#: (``ζ = √(1 + ε) K_d / (2 √K_p)``).
DEFAULT_KD = 44.0

#: A commanded tension within this fraction (at least 1e-6 N) above its minimum counts as at
#: the minimum: a slack event.
SLACK_RTOL = 1e-6

#: Control updates between progress reports.
PROGRESS_EVERY = 2000
#: Control updates simulated per block: the reference and the disturbance of a block are
#: computed at once and its updates folded into the result, so that the memory does not
#: grow with the duration.
BLOCK_UPDATES = 1 << 15
#: Bytes of the samples a :class:`ControlResult` holds (the updates kept: every
#: ``decimate``-th and the last), checked before the simulation starts.
MAX_RESULT_BYTES = 1 << 26
#: Most control updates :func:`simulate_control` simulates (its time budget).
MAX_STEPS = 100_000_000


@dataclass(frozen=True)
class WrenchSteps(Result):
    """An external wrench made of steps, a function of time.

    ``steps[k] = (start, end, wrench)`` adds ``wrench`` (taut's convention: forces, then
    moments about ``p``, fixed frame) for ``start ≤ t < end`` (``end = inf``: from ``start``
    on).  Callable: ``steps(t) -> (dof,)``.

    Parameters
    ----------
    steps : tuple of (float, float, tuple of float)
        The steps; their values are stored as floats.

    Raises
    ------
    TautError
        Values that are not numbers, ``start < 0``, ``end ≤ start``, a wrench that is not
        finite, or wrenches of different sizes.

    Examples
    --------
    >>> from taut.dynamics import WrenchSteps
    >>> push = WrenchSteps.step(1.0, [5.0, 0.0, 0.0], end=2.0)
    >>> push(0.5), push(1.5)
    (array([0., 0., 0.]), array([5., 0., 0.]))
    """

    steps: tuple[tuple[float, float, tuple[float, ...]], ...]

    def __post_init__(self) -> None:
        try:
            steps = tuple((float(a), float(b), tuple(float(x) for x in w)) for a, b, w in self.steps)
        except (TypeError, ValueError):
            raise TautError(f"a wrench step is (start, end, wrench) of numbers, got {self.steps!r}") from None
        object.__setattr__(self, "steps", steps)
        sizes = {len(w) for _, _, w in self.steps}
        if len(sizes) > 1:
            raise TautError(f"every step of a wrench needs the same number of components, got {sorted(sizes)}")
        for start, end, w in self.steps:
            if not (math.isfinite(start) and start >= 0 and end > start) or not all(math.isfinite(x) for x in w):
                raise TautError(f"a wrench step needs 0 <= start < end and a finite wrench, got {start}, {end}, {w}")
        super().__post_init__()

    @classmethod
    def step(cls, start: float, wrench: npt.ArrayLike, *, end: float = math.inf) -> WrenchSteps:
        """One step of ``wrench`` from ``start`` (to ``end``).

        Parameters
        ----------
        start : float
            [s], non-negative.
        wrench : array_like, shape (dof,)
        end : float, optional
            [s]; default for ever.

        Returns
        -------
        WrenchSteps
        """
        return cls(((start, end, tuple(np.ravel(wrench))),))

    def __call__(self, t: float) -> np.ndarray:
        return self.at(np.array([t]))[0]

    def at(self, times: npt.ArrayLike) -> np.ndarray:
        """The wrench at each of ``times``.

        Parameters
        ----------
        times : array_like, shape (N,)
            [s].

        Returns
        -------
        ndarray, shape (N, dof)

        Raises
        ------
        TautError
            Times that are not numbers.
        """
        try:
            t = np.asarray(times, dtype=float).reshape(-1, 1)
        except (TypeError, ValueError):
            raise TautError(f"times must be numbers, got {times!r}") from None
        size = len(self.steps[0][2]) if self.steps else 0
        out = np.zeros((t.shape[0], size))
        for start, end, w in self.steps:
            out += ((start <= t) & (t < end)) * np.asarray(w)
        return out


@dataclass(frozen=True)
class ControlResult(Result):
    """A controlled motion: ``updates`` control updates, of which the kept ones (every
    ``decimate``-th and the last) are sampled at ``times``; the statistics (errors, margins,
    slack events, failures) cover every update (:func:`simulate_control`).

    At update ``k`` the controller saw ``poses[k]``, ``velocity[k]`` against ``reference[k]``,
    commanded ``command[k]`` (``q̈_cmd``) and applied ``tensions[k]`` until the next update
    (``feasible[k]`` False: the distribution failed and the last admissible tensions were
    held).

    Attributes
    ----------
    times : ndarray, shape (S,)
        The times of the ``S`` kept updates [s].
    reference : ndarray, shape (S, dof)
        The reference pose.
    poses : ndarray, shape (S, dof)
    velocity : ndarray, shape (S, dof)
    error : ndarray, shape (S, dof)
        ``q_r − q``, angles wrapped into ``[−π, π)``.
    position_error : ndarray, shape (S,)
        ``‖p_r − p‖`` [m].
    rotation_error : ndarray, shape (S,)
        The angle of ``R_rᵀ R`` [rad] (zeros for a point mass).
    command : ndarray, shape (S, dof)
        The commanded pose accelerations ``q̈_cmd``.
    tensions : ndarray, shape (S, n)
        The tensions applied from each update [N] (a sagging cable's at its platform end).
    exit_tensions : ndarray, shape (S, n)
        Each cable's tension at its exit at the update's pose [N] (``tensions`` for a
        straight cable).
    cable_model : str
        ``"straight"``, or ``"quasi-static elastic catenary"`` for a robot with sagging
        cables (its straight cables stay straight).
    sagging_cables : tuple of int
        The sagging cables (0-based).
    feasible : ndarray of bool, shape (S,)
        The distribution found admissible tensions.
    disturbance : ndarray, shape (S, dof)
        The external wrench at each update.
    tension_min, tension_max : ndarray, shape (n,)
        The bounds [N] (``inf`` where a cable has no upper limit).
    pose_names : tuple of str
    kp, kd : ndarray, shape (dof,)
        The gains.
    rate_hz : float
    substeps : int
    method : str
        The distribution used where the closed form gives up.
    elapsed_s : float
        Wall-clock seconds of the simulation.
    complete : bool
        The simulation reached the end of the motion.
    updates : int
        Control updates simulated, ``K + 1``.
    decimate : int
        Every ``decimate``-th update is kept (and the last).
    tracking_error_max : ndarray, shape (dof,)
        The largest ``|e|`` of each coordinate over every update.
    tracking_error_rms : ndarray, shape (dof,)
        The root mean square of ``e`` of each coordinate over every update.
    position_error_max : float
        The largest ``‖p_r − p‖`` [m].
    rotation_error_max : float
        The largest rotation error [rad].
    lower_margin : float
        The smallest ``τ − τ_min`` over updates and cables [N], at both ends of sagging cables.
    upper_margin : float
        The smallest ``τ_max − τ`` [N] (``inf`` without upper limits), at both ends.
    slack_events : int
        Updates at which some cable's commanded tension is at or below its minimum.
    failures : int
        Updates at which the distribution failed (the last admissible tensions were held).
    first_failure_time : float or None
        Time of the first failed update [s], or None.
    joint_limit_violations : int
        Updates at which a joint coordinate of the simulated motion is outside its
        ``limits`` (the plant has no joint stops: the violation is reported, not prevented).
    first_joint_limit_time : float or None
        Time of the first such update [s], or None.
    actuator_forces : ndarray, shape (S, n_actuators)
        The forces [N] or torques [N m] of the joint actuators applied from each update, in
        the order of :attr:`taut.model.Robot.actuated_joints` (no columns without actuators).
    actuator_min, actuator_max : ndarray, shape (n_actuators,)
        Their bounds (``±inf`` where unbounded).
    actuator_margin : ndarray, shape (n_actuators,)
        The smallest distance of each actuator's force to its bounds over every update
        (``inf`` for an unbounded actuator).
    actuator_peak : ndarray, shape (n_actuators,)
        The largest ``|ζ|`` of each actuator over every update.
    cable_margin : ndarray, shape (n,)
        Each cable's smallest distance to its tension bounds over every update [N]
        (``min(lower_margin, upper_margin)`` is their minimum).
    cable_slack_events : ndarray of int, shape (n,)
        The updates at which each cable's commanded tension is at or below its minimum.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.motion import trajectory_from_waypoints
    >>> from taut.dynamics import simulate_control
    >>> robot = example("planar-4cable")
    >>> run = simulate_control(robot, trajectory_from_waypoints(robot, [[0, 0, 0], [0.1, 0.05, 0]], duration=0.5), rate_hz=200)
    >>> run.times.shape, run.updates, run.all_feasible, run.failures
    ((101,), 101, True, 0)
    """

    times: np.ndarray  #: ``(S,)`` the times of the kept updates
    reference: np.ndarray  #: ``(S, dof)`` the reference pose
    poses: np.ndarray  #: ``(S, dof)``
    velocity: np.ndarray  #: ``(S, dof)``
    error: np.ndarray  #: ``(S, dof)`` ``q_r − q``, angles wrapped into ``[−π, π)``
    position_error: np.ndarray  #: ``(S,)`` ``‖p_r − p‖`` [m]
    rotation_error: np.ndarray  #: ``(S,)`` the angle of ``R_rᵀ R`` [rad] (zeros for a point mass)
    command: np.ndarray  #: ``(S, dof)`` the commanded pose accelerations ``q̈_cmd``
    tensions: np.ndarray  #: ``(S, n)`` the tensions applied from each update (sagging: at the platform)
    exit_tensions: np.ndarray  #: ``(S, n)`` the tensions at the exits (``tensions`` for straight cables)
    cable_model: str  #: ``"straight"`` or ``"quasi-static elastic catenary"``
    sagging_cables: tuple[int, ...]  #: the sagging cables, 0-based
    feasible: np.ndarray  #: ``(S,)`` bool: the distribution found admissible tensions
    disturbance: np.ndarray  #: ``(S, dof)`` the external wrench at each update
    tension_min: np.ndarray  #: ``(n,)``
    tension_max: np.ndarray  #: ``(n,)`` (``inf`` where a cable has no upper limit)
    pose_names: tuple[str, ...]
    kp: np.ndarray  #: ``(dof,)``
    kd: np.ndarray  #: ``(dof,)``
    rate_hz: float
    substeps: int
    method: str  #: the distribution used where the closed form gives up
    updates: int  #: control updates simulated, ``K + 1``
    decimate: int  #: every ``decimate``-th update is kept (and the last)
    tracking_error_max: np.ndarray  #: ``(dof,)`` the largest ``|e|`` of each coordinate
    tracking_error_rms: np.ndarray  #: ``(dof,)`` the root mean square of ``e`` over the updates
    position_error_max: float  #: the largest ``‖p_r − p‖`` [m]
    rotation_error_max: float  #: the largest rotation error [rad]
    lower_margin: float  #: the smallest ``τ − τ_min`` over updates and cables [N]
    upper_margin: float  #: the smallest ``τ_max − τ`` [N] (``inf`` without upper limits)
    slack_events: int  #: updates at which some commanded tension is at or below its minimum
    failures: int  #: updates at which the distribution failed (the last tensions were held)
    first_failure_time: float | None  #: time of the first failed update [s], or None
    joint_limit_violations: int  #: updates at which a joint coordinate is outside its limits
    first_joint_limit_time: float | None  #: time of the first such update [s], or None
    actuator_forces: np.ndarray  #: ``(S, n_actuators)`` the joint actuators' forces from each update
    actuator_min: np.ndarray  #: ``(n_actuators,)``
    actuator_max: np.ndarray  #: ``(n_actuators,)``
    actuator_margin: np.ndarray  #: ``(n_actuators,)`` the smallest distance to a bound (``inf``: unbounded)
    actuator_peak: np.ndarray  #: ``(n_actuators,)`` the largest ``|ζ|`` over every update
    cable_margin: np.ndarray  #: ``(n,)`` each cable's smallest distance to its tension bounds [N]
    cable_slack_events: np.ndarray  #: ``(n,)`` int: updates at which each cable is at or below its minimum
    elapsed_s: float = 0.0  #: wall-clock seconds of the simulation
    complete: bool = True  #: the simulation reached the end of the motion

    @property
    def min_tension_margin(self) -> float:
        """``min(lower_margin, upper_margin)``: how close the tensions came to a limit [N]."""
        return min(self.lower_margin, self.upper_margin)

    @property
    def slack(self) -> np.ndarray:
        """``(S, n)`` bool, at the kept updates: the commanded tension is at or below its
        minimum (the cable has no margin left to stay taut; at a minimum of 0, it is slack), at
        either end of a sagging cable."""
        return _slack(np.minimum(self.tensions, self.exit_tensions), self.tension_min)

    @property
    def all_feasible(self) -> bool:
        """Every update found admissible tensions."""
        return self.failures == 0

    def as_dict(self) -> dict[str, Any]:
        """The fields and the summary properties ``min_tension_margin`` and ``all_feasible``
        in plain JSON types (an infinite bound or margin is ``None``).

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        names = ("min_tension_margin", "all_feasible")
        return super().as_dict() | {name: jsonable(getattr(self, name)) for name in names}


def _slack(tensions: np.ndarray, tmin: np.ndarray) -> np.ndarray:
    tol = SLACK_RTOL * np.maximum(1.0, np.abs(tmin))
    return tensions <= tmin + tol


def with_mass_error(robot: Robot, error: float) -> Robot:
    """``robot`` with its platform's mass and inertia scaled by ``1 + error``, and those of its
    jointed bodies: a controller's model with a mass error (``error = 0.1``: a model 10 % too
    heavy).

    Parameters
    ----------
    robot : Robot
    error : float
        Finite, greater than −1.

    Returns
    -------
    Robot

    Raises
    ------
    TautError
        ``error`` not a finite number greater than −1, or a robot without mass.

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import with_mass_error
    >>> with_mass_error(example("planar-4cable"), 0.1).platform.mass
    1.1
    """
    if isinstance(error, bool) or not isinstance(error, numbers.Real) or not (math.isfinite(error) and error > -1):
        raise TautError(f"the mass error must be a finite number > -1, got {error!r}")
    plat = robot.platform
    if plat.mass is None:
        raise TautError(f"{robot.name}: no platform.mass to scale")
    scale = 1.0 + float(error)
    fields: dict[str, object] = {"mass": plat.mass * scale}
    if plat.inertia is not None:
        fields["inertia"] = tuple(x * scale for x in plat.inertia)
    bodies = []
    for body in plat.bodies:
        scaled: dict[str, object] = {}
        if body.mass is not None:
            scaled["mass"] = body.mass * scale
        if body.inertia is not None:
            scaled["inertia"] = tuple(x * scale for x in body.inertia)
        bodies.append(body.model_copy(update=scaled))
    fields["bodies"] = tuple(bodies)
    return robot.model_copy(update={"platform": plat.model_copy(update=fields)})


def _gains(value: npt.ArrayLike, dof: int, what: str) -> np.ndarray:
    try:
        g = np.array(np.broadcast_to(np.asarray(value, dtype=float), (dof,)))
    except (TypeError, ValueError):
        raise TautError(f"{what}: expected one number or {dof}, got {value!r}") from None
    if not (np.isfinite(g).all() and (g >= 0).all()):
        raise TautError(f"{what} must be finite and >= 0, got {g.tolist()}")
    return g


def _tabulate(f: Callable[[float], npt.ArrayLike] | None, time: np.ndarray, substeps: int, dof: int) -> np.ndarray:
    """The disturbance at the start of every RK4 step, ``(K + 1, substeps, dof)`` (the last
    update's row: at its time)."""
    K = time.size - 1
    D = np.zeros((K + 1, substeps, dof))
    if f is None:
        return D
    if isinstance(f, WrenchSteps):
        if f.steps and len(f.steps[0][2]) != dof:
            raise TautError(f"disturbance: expected {dof} components, got {len(f.steps[0][2])}")
        step = np.append(np.diff(time), 0.0) / substeps
        starts = time[:, None] + np.arange(substeps)[None, :] * step[:, None]
        return f.at(starts.ravel()).reshape(K + 1, substeps, dof) if f.steps else D
    for k in range(K + 1):
        h = float(time[k + 1] - time[k]) / substeps if k < K else 0.0
        for s in range(substeps):
            t = float(time[k] + s * h)
            try:
                w = np.asarray(f(t), dtype=float)
            except TautError:
                raise
            except (TypeError, ValueError) as e:
                raise TautError(f"disturbance at t = {t:g} s: not numbers ({e})") from None
            if w.shape != (dof,) or not np.isfinite(w).all():
                raise TautError(f"disturbance at t = {t:g} s: expected {dof} finite numbers, got {w.tolist()}")
            D[k, s] = w
    return D


def _update(
    robot: Robot,
    models: tuple[LoopModel, LoopModel],
    k: int,
    time: np.ndarray,
    refs: tuple[np.ndarray, np.ndarray],
    gains: np.ndarray,
    angles: slice,
    predict: bool,
    D: np.ndarray,
    state: np.ndarray,
    previous: np.ndarray,
    held: tuple[np.ndarray, np.ndarray],
) -> bool:
    """Update ``k`` as :func:`taut.dynamics._kernels.control_updates` does it, with the
    controller's fallback distribution and the checked RK4 step: ``state[2:6]`` get ``q, q̇,
    e, q̈_cmd`` at its start, ``state[:2]`` the state at the next update, ``held`` the held
    tensions and the cables' exit tensions (``previous``: ``q̇`` at update ``k − 1``); returns
    whether the distribution found admissible tensions."""
    plant, ctrl = models
    last, last_exit = held
    ref, ahead = refs
    K = time.size - 1
    t = float(time[k])
    q, qd = state[0].copy(), state[1].copy()
    e = ref[0, k] - q
    e[angles] = (e[angles] + math.pi) % (2 * math.pi) - math.pi
    cmd = ref[2, k] + gains[1] * (ref[1, k] - qd) + gains[0] * e
    qc, qdc, cmdc = q, qd, cmd
    if predict and k < K:
        h2 = 0.5 * (float(time[k + 1]) - t)
        a = cmd if k == 0 else (qd - previous) / (t - float(time[k - 1]))
        qc, qdc = q + h2 * qd + 0.5 * h2 * h2 * a, qd + h2 * a
        em = ahead[0, k] - qc
        em[angles] = (em[angles] + math.pi) % (2 * math.pi) - math.pi
        cmdc = ahead[2, k] + gains[1] * (ahead[1, k] - qdc) + gains[0] * em
    try:
        tau, ok = ctrl.tensions(qc, qdc, cmdc)
    except TautError as exc:
        raise IntegrationError(f"control update at t = {t:g} s: {exc}") from None
    if ok:
        last[:] = tau
    elif np.isnan(last).any():
        raise InfeasiblePoseError(
            f"{robot.name}: no admissible tensions at the start (t = {t:g} s, pose {q.tolist()}): nothing to hold"
        )
    try:
        last_exit[:] = plant.exit_tensions(q, last)
    except TautError as exc:
        raise IntegrationError(f"at t = {t:g} s: {exc}") from None
    state[2], state[3], state[4], state[5] = q, qd, e, cmd
    if k == K:
        return bool(ok)
    h = (float(time[k + 1]) - t) / D.shape[1]
    for s in range(D.shape[1]):
        try:
            q, qd = plant.step(q, qd, last, h, wrench=D[k, s])
        except TautError as exc:
            raise IntegrationError(f"RK4 failed at t = {t + s * h:g} s: {exc}") from None
    if not (np.isfinite(q).all() and np.isfinite(qd).all()) or np.abs(q).max() > MAX_MAGNITUDE:
        raise IntegrationError(
            f"the controlled motion diverged at t = {float(time[k + 1]):g} s from pose "
            f"{np.round(state[0], 6).tolist()} (an RK4 step of {h:g} s too large for the dynamics there?)"
        )
    state[0], state[1] = q, qd
    return bool(ok)


def simulate_control(
    robot: Robot,
    motion: Motion,
    *,
    kp: npt.ArrayLike = DEFAULT_KP,
    kd: npt.ArrayLike = DEFAULT_KD,
    rate_hz: float = 1000.0,
    substeps: int = 1,
    model: Robot | None = None,
    disturbance: Callable[[float], npt.ArrayLike] | None = None,
    method: str = "qp",
    predict: bool = True,
    q0: npt.ArrayLike | None = None,
    qd0: npt.ArrayLike | None = None,
    decimate: int = 1,
    progress: Callable[[int, int | None], None] | None = None,
) -> ControlResult:
    """Simulate ``robot`` tracking ``motion`` under computed-torque control with the tension
    distribution in the loop, from ``t = 0`` to ``motion.duration``.

    Sagging cables (``cables[].weight``) are quasi-static elastic catenaries: each pulls along
    its tangent at the anchor with its commanded (platform-end) tension; the distribution is
    iterated to consistency with the catenaries and the plant recomputes them at every RK4
    stage (module docstring; the cables' mass is neglected in the platform's inertia).

    Cables may leave through swivelling pulleys: their lengths hold the wound arc and they
    pull along the tangent from the moving tangent point (Pott 2018), in the controller's
    model and in the plant; the pulleys' own inertia and friction are neglected.

    Parameters
    ----------
    robot : Robot
        The plant.
    motion : taut.motion.Motion
        The reference, a trajectory of a robot with the same pose coordinates.
    kp, kd : float or array_like, shape (dof,), optional
        Gains [1/s², 1/s], one number or one per pose coordinate (zero gains: pure
        feed-forward); default :data:`DEFAULT_KP`, :data:`DEFAULT_KD`.
    rate_hz : float, optional
        Control updates per second (the tensions are held between them).
    substeps : int, optional
        RK4 steps of the plant per control period.
    model : Robot, optional
        The controller's robot, with the same cables (default ``robot``: an exact model;
        :func:`with_mass_error` makes one with a mass error).
    disturbance : callable, optional
        ``disturbance(t) -> (dof,)``: an external wrench on the plant, unknown to the
        controller (e.g. :class:`WrenchSteps`), held over each RK4 step.
    method : str, optional
        The distribution where the closed form gives up (a method of
        :data:`taut.statics.METHODS`).
    predict : bool, optional
        Evaluate the law half a period ahead (see the module's docstring; False: at the
        sampled state).
    q0, qd0 : array_like, shape (dof,), optional
        The initial state (default the reference's).
    decimate : int, optional
        Every ``decimate``-th update is kept in the result (and the last); the statistics
        cover all of them.  The updates are simulated in blocks of :data:`BLOCK_UPDATES`, so
        that the memory is that of the kept samples, at most :data:`MAX_RESULT_BYTES`.
    progress : callable, optional
        ``progress(done, total)``, with the updates done.

    Returns
    -------
    ControlResult

    Raises
    ------
    TautError
        Bad gains, rate, substeps, motion, model, disturbance, decimate or progress; more than
        :data:`MAX_STEPS` updates; kept samples beyond :data:`MAX_RESULT_BYTES` (a larger
        ``decimate`` keeps fewer).
    UnsupportedRobotError
        A robot without mass or inertia (a jointed platform: any of its bodies, named).
    InfeasiblePoseError
        No admissible tensions at the start (nothing to hold).
    IntegrationError
        The motion reaches a singular configuration (gimbal lock, a zero-length cable) or
        diverges.
    WrappedCableError
        The reference or the simulated motion reaches a pose where a cable of a
        variable-structure robot, as a straight line, meets one of its obstacles
        (:func:`taut.kinematics.obstacles_met`): the loop models straight cables, and the
        wrapped cable's length and direction are not theirs.
    InfeasiblePoseError
        Also where the reference or the simulated motion brings a cable's anchor within its
        swivelling pulley's radius of the pulley's axis
        (:func:`taut.kinematics.refuse_near_swivel_axis`), named with the time.

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §8.5.2. (docs/references.bib: siciliano2009)
    .. [2] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis
       and simulation platform for the research of cable-driven parallel robots", IROS, 2016.
       (docs/references.bib: lau2016)
    .. [3] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
    .. [4] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic
       catenary). (docs/references.bib: irvine1981)

    Examples
    --------
    With an exact model the planar platform tracks a quintic move of 0.11 m in 0.5 s to
    within a few hundredths of a millimetre:

    >>> from taut.model import example
    >>> from taut.motion import trajectory_from_waypoints
    >>> from taut.dynamics import simulate_control
    >>> robot = example("planar-4cable")
    >>> motion = trajectory_from_waypoints(robot, [[0, 0, 0], [0.1, 0.05, 0]], duration=0.5)
    >>> run = simulate_control(robot, motion, rate_hz=200)
    >>> run.all_feasible, bool(run.position_error.max() < 5e-5)
    (True, True)
    """
    from taut.dynamics._kernels import control_updates
    from taut.geometry import rotation_matrix
    from taut.kinematics import as_poses, refuse_near_swivel_axis, refuse_wrapped
    from taut.statics import EQUILIBRIUM_RTOL

    started = perf_counter()
    if not isinstance(motion, Motion):
        raise TautError(f"motion must be a taut.motion.Motion (a timed trajectory), got {type(motion).__name__}")
    if motion.robot.pose_size != robot.pose_size or motion.robot.orientation != robot.orientation:
        raise TautError(f"the motion is a trajectory of {motion.robot.name}, whose poses are not those of {robot.name}")
    rate_hz = positive(rate_hz, "the control rate rate_hz")
    if isinstance(substeps, bool) or not isinstance(substeps, numbers.Integral) or substeps < 1:
        raise TautError(f"substeps must be a whole number >= 1, got {substeps!r}")
    if model is not None and not isinstance(model, Robot):
        raise TautError(f"model must be a Robot (the controller's model), got {type(model).__name__}")
    check_callable(disturbance, "disturbance")
    check_callable(progress, "progress")
    dof, nc = robot.pose_size, robot.n_cables
    kp_, kd_ = _gains(kp, dof, "kp"), _gains(kd, dof, "kd")
    plant = loop_model(robot, method=method)
    n = plant.kernels.n  # the cables, then the joint actuators
    if model is not None and (
        model.pose_size != dof
        or model.orientation != robot.orientation
        or not np.array_equal(model.exits, robot.exits)
        or not np.array_equal(model.anchors, robot.anchors)
        or not np.array_equal(model.actuated_joints, robot.actuated_joints)
        or not np.array_equal(model.cable_weights, robot.cable_weights)
        or not np.array_equal(model.axial_stiffness, robot.axial_stiffness)
    ):
        raise TautError(
            f"the controller's model {model.name} must have the cables, joint actuators and pose coordinates of "
            f"{robot.name}"
        )
    ctrl = plant if model is None else loop_model(model, method=method)
    duration = motion.duration
    K = max(1, math.ceil(duration * rate_hz - 1e-9))
    if K > MAX_STEPS:
        raise TautError(f"{K} control updates: at most {MAX_STEPS:.0e} are simulated")
    if isinstance(decimate, bool) or int(decimate) != decimate or decimate < 1:
        raise TautError(f"decimate must be a whole number >= 1, got {decimate!r}")
    every = int(decimate)
    kept = K // every + 1 + (K % every != 0)
    sagging = plant.sag is not None
    # the exit tensions of straight cables are their tensions: stored once
    per_sample = 8 * (1 + 6 * dof + n + nc * sagging + 2) + 1
    if kept * per_sample > MAX_RESULT_BYTES:
        need = math.ceil((K + 1) * per_sample / MAX_RESULT_BYTES)
        raise TautError(
            f"{K + 1:,} control updates keep {kept:,} samples of {per_sample} bytes with decimate={every}: "
            f"{kept * per_sample / 2**20:,.0f} MiB, more than {MAX_RESULT_BYTES / 2**20:,.0f} MiB; keep fewer: "
            f"decimate >= {need} (taut simulate: --sample-rate at most {rate_hz / need:.3g} Hz)"
        )
    first = motion.at([0.0])
    q = np.array(first.poses[0]) if q0 is None else np.array(as_poses(robot, q0)[0][0])
    qd = np.array(first.velocity[0]) if qd0 is None else np.array(as_rates(robot, qd0, 1)[0])
    angles = angle_columns(robot)
    d = robot.dimension
    lo, hi = plant.buffers["lo"], plant.buffers["hi"]
    gains = np.array([kp_, kd_])
    columns = np.array([angles.start, angles.stop], np.int64)
    # q, q̇ (advanced in place), then q, q̇, e, q̈_cmd at the start of an update done here
    state = np.array([q, qd, q, qd, q, q])
    last = np.full(n, np.nan)
    last_exit = np.full(nc, np.nan)
    out_t = np.empty(kept)
    out_ref, out_q, out_v, out_e, out_a, out_d = (np.empty((kept, dof)) for _ in range(6))
    out_pos, out_rot = np.empty(kept), np.empty(kept)
    out_tau = np.empty((kept, n))
    out_exit = np.empty((kept if sagging else 0, nc))
    out_ok = np.empty(kept, bool)
    stored = 0
    err_max, err_sq = np.zeros(dof), np.zeros(dof)
    pos_max = rot_max = 0.0
    lower = upper = math.inf
    act_margin, act_peak = np.full(n - nc, math.inf), np.zeros(n - nc)
    cable_margin, cable_slack = np.full(nc, math.inf), np.zeros(nc, dtype=np.int64)
    slack_events = failures = beyond = 0
    first_failure: float | None = None
    first_beyond: float | None = None
    limits, m = robot.joint_limits, robot.wrench_dim
    v_prev = np.zeros(dof)
    for k0 in range(0, K + 1, BLOCK_UPDATES):
        k1 = min(k0 + BLOCK_UPDATES, K + 1)
        # the block's rows: the update before it (its velocity: the measured acceleration),
        # its own, and the next one's time (the last step of the block)
        g0 = k0 - 1 if k0 else 0
        g = np.arange(g0, min(k1 + 1, K + 1))
        time = np.minimum(g / rate_hz, duration)
        samples = motion.at(time)
        mid = motion.at(0.5 * (time[1:] + time[:-1]))
        ref = np.array([samples.poses, samples.velocity, samples.acceleration])
        ahead = np.array([mid.poses, mid.velocity, mid.acceleration])
        D = _tabulate(disturbance, time, int(substeps), dof)
        refuse_wrapped(robot, samples.poses, times=time, what="of the reference")
        refuse_near_swivel_axis(robot, samples.poses, times=time, what="of the reference")
        Q, V, E, A = (np.zeros((g.size, dof)) for _ in range(4))
        T = np.zeros((g.size, n))
        X = np.zeros((g.size, nc))
        ok_all = np.ones(g.size, dtype=bool)
        V[0] = v_prev
        k, end = k0 - g0, k1 - g0
        while k < end:
            stop = min(k + PROGRESS_EVERY, end)
            # sagging cables' pull is the catenaries', outside the compiled loop: every update here
            k = (
                k
                if sagging
                else control_updates(
                    *plant.kernels.args[:2],
                    *ctrl.kernels.args,
                    k,
                    stop,
                    time,
                    ref,
                    ahead,
                    gains,
                    columns,
                    predict,
                    D,
                    lo,
                    hi,
                    EQUILIBRIUM_RTOL,
                    state,
                    last,
                    Q,
                    V,
                    E,
                    A,
                    T,
                )
            )
            if progress is not None:
                progress(g0 + k, K + 1)
            if k == stop:
                continue
            # the closed form gave up, a step failed, or cables sag: this update here, with the
            # fallback distribution, and the checked step that names a failure
            previous = V[k - 1] if k else V[0]
            ok_all[k] = _update(
                robot,
                (plant, ctrl),
                k,
                time,
                (ref, ahead),
                gains,
                angles,
                predict,
                D,
                state,
                previous,
                (last, last_exit),
            )
            Q[k], V[k], T[k], X[k] = state[2], state[3], last, last_exit
            E[k], A[k] = state[4], state[5]
            k += 1
        new = slice(k0 - g0, end)
        refuse_wrapped(robot, Q[new], times=time[new], what="of the simulated motion")
        refuse_near_swivel_axis(robot, Q[new], times=time[new], what="of the simulated motion")
        if not sagging:
            X = T[:, :nc]
        Eb, Tb, okb, tb = E[new], T[new], ok_all[new], time[new]
        # both ends of a sagging cable within its bounds: the lower and the higher of its tensions
        low, high = np.minimum(Tb[:, :nc], X[new]), np.maximum(Tb[:, :nc], X[new])
        pos = np.linalg.norm(Eb[:, :d], axis=1)
        rot = np.zeros(pos.size)
        if angles.stop > angles.start:
            if d == 2:
                rot = np.abs(Eb[:, 2])
            else:
                Rr = rotation_matrix(ref[0, new, 3:6], robot.orientation)
                R = rotation_matrix(Q[new, 3:6], robot.orientation)
                rot = np.arccos(np.clip((np.einsum("kij,kij->k", Rr, R) - 1.0) / 2.0, -1.0, 1.0))
        err_max = np.maximum(err_max, np.abs(Eb).max(axis=0))
        err_sq += (Eb**2).sum(axis=0)
        pos_max, rot_max = max(pos_max, float(pos.max())), max(rot_max, float(rot.max()))
        lower = min(lower, float((low - lo[:nc]).min()))
        upper = min(upper, float((hi[:nc] - high).min()))
        if n > nc:
            act_margin = np.minimum(act_margin, np.minimum(Tb[:, nc:] - lo[nc:], hi[nc:] - Tb[:, nc:]).min(axis=0))
            act_peak = np.maximum(act_peak, np.abs(Tb[:, nc:]).max(axis=0))
        slack = _slack(low, lo[:nc])
        slack_events += int(np.count_nonzero(slack.any(axis=1)))
        cable_slack += slack.sum(axis=0)
        cable_margin = np.minimum(cable_margin, np.minimum(low - lo[:nc], hi[:nc] - high).min(axis=0))
        bad = np.flatnonzero(~okb)
        failures += bad.size
        if first_failure is None and bad.size:
            first_failure = float(tb[bad[0]])
        joints = Q[new, m:]
        out = np.flatnonzero(((joints < limits[:, 0]) | (joints > limits[:, 1])).any(axis=1))
        beyond += out.size
        if first_beyond is None and out.size:
            first_beyond = float(tb[out[0]])
        keep = np.flatnonzero((g[new] % every == 0) | (g[new] == K))
        rows = keep + new.start
        at = slice(stored, stored + keep.size)
        out_t[at], out_ref[at], out_q[at], out_v[at] = time[rows], ref[0, rows], Q[rows], V[rows]
        out_e[at], out_a[at], out_d[at], out_tau[at] = E[rows], A[rows], D[rows, 0], T[rows]
        if sagging:
            out_exit[at] = X[rows]
        out_pos[at], out_rot[at], out_ok[at] = pos[keep], rot[keep], ok_all[rows]
        stored += keep.size
        v_prev = V[end - 1].copy()
    assert stored == kept, "every kept update is stored once"
    tensions, forces = out_tau[:, :nc].copy(), out_tau[:, nc:].copy()
    if not sagging:
        out_exit = tensions
    frozen = [out_t, out_ref, out_q, out_v, out_e, out_pos, out_rot, out_a, tensions, forces, out_ok, out_d, out_exit]
    frozen += [kp_, kd_]
    tmin, tmax = np.array(lo[:nc], float), np.array(hi[:nc], float)
    amin, amax = np.array(lo[nc:], float), np.array(hi[nc:], float)
    rms = np.sqrt(err_sq / (K + 1))
    for a in (*frozen, tmin, tmax, amin, amax, act_margin, act_peak, cable_margin, cable_slack, err_max, rms):
        a.setflags(write=False)
    return ControlResult(
        times=out_t,
        reference=out_ref,
        poses=out_q,
        velocity=out_v,
        error=out_e,
        position_error=out_pos,
        rotation_error=out_rot,
        command=out_a,
        tensions=tensions,
        exit_tensions=out_exit,
        cable_model=cable_model(robot),
        sagging_cables=tuple(robot.sagging_cables),
        feasible=out_ok,
        disturbance=out_d,
        tension_min=tmin,
        tension_max=tmax,
        pose_names=tuple(robot.pose_names),
        kp=kp_,
        kd=kd_,
        rate_hz=float(rate_hz),
        substeps=int(substeps),
        method=method,
        updates=K + 1,
        decimate=every,
        tracking_error_max=err_max,
        tracking_error_rms=rms,
        position_error_max=pos_max,
        rotation_error_max=rot_max,
        lower_margin=lower,
        upper_margin=upper,
        slack_events=slack_events,
        failures=failures,
        first_failure_time=first_failure,
        joint_limit_violations=beyond,
        first_joint_limit_time=first_beyond,
        actuator_forces=forces,
        actuator_min=amin,
        actuator_max=amax,
        actuator_margin=act_margin,
        actuator_peak=act_peak,
        cable_margin=cable_margin,
        cable_slack_events=cable_slack,
        elapsed_s=perf_counter() - started,
    )
