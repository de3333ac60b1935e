"""Trajectories through waypoints in pose space (and joint space: the joint coordinates of a
jointed platform are part of its pose), timed by a time law, sampled at any rate.

:func:`trajectory_from_waypoints` joins ``N ≥ 2`` waypoints by ``N − 1`` segments, each with
its own duration (given, a total shared out, absolute times, or the shortest within velocity
and acceleration limits), the time law of :mod:`taut.motion._laws` and the velocities at the
via points of :mod:`taut.motion._vias`.  With ``via="stop"`` (the default) the time law is
applied to all coordinates of a segment together: each segment is a straight line in pose
coordinates.  The result, a :class:`Motion`, is immutable: a piecewise polynomial of degree
at most 5 whose :meth:`Motion.at` and :meth:`Motion.sample` give pose ``q``, velocity ``q̇``
and acceleration ``q̈`` in pose coordinates and, for a rigid platform, the angular velocity
``ω`` and acceleration ``α`` in the fixed frame (:class:`MotionSamples`).

Orientation.  With ``rotation="angles"`` (the default) the angles are interpolated as
coordinates, after :func:`~taut.motion._waypoints.unwrap_angles` has made each take the short
way between waypoints.  With ``rotation="axis"`` a spatial platform turns about one axis from
each waypoint's orientation to the next's, the short way, the time law timing the angle turned
(CASPR's spherical joints; :mod:`taut.motion._axis`).  ``ω = E(q) q̇`` and
``α = E(q) q̈ + Ė(q, q̇) q̇`` come from the rate matrix of the robot's convention
(:mod:`taut.geometry._rates`), never from angle differences; a planar platform has ``ω = θ̇``.
At a gimbal lock (``b = ±π/2`` in the ``xyz`` conventions, tilt ``θ = 0`` in
``tilt-torsion``) nothing special is done: the angles are polynomials of time, so ``R(q(t))``
stays smooth and ``ω``, ``α`` stay exact (``E`` is evaluated, never inverted), but there the
rotation does not fix the angles, so the path through or from such a waypoint depends on how
its angles were chosen, and near it small rotations need large angle rates.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §4.2 (joint-space trajectories), §3.6 (analytical Jacobian).
   (docs/references.bib: siciliano2009)
.. [2] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut.errors import TrajectoryError
from taut.geometry import rate_matrix, rate_matrix_derivative
from taut.model import Robot
from taut.motion._axis import AxisTurns, axis_turns
from taut.motion._laws import (
    DEGREE,
    LAWS,
    cubic_piece,
    linear_piece,
    minimum_duration,
    quintic_piece,
    trapezoidal_pieces,
)
from taut.motion._named import robot_trajectory
from taut.motion._vias import VIAS, average_velocities, spline_velocities
from taut.motion._waypoints import angle_columns, complete_waypoints, unwrap_angles, validate_waypoints

__all__ = [
    "DEFAULT_BLEND",
    "MAX_SAMPLES",
    "ROTATIONS",
    "Motion",
    "MotionSamples",
    "trajectory_from_robot",
    "trajectory_from_waypoints",
]

#: Blend fraction ``t_b / T`` of a trapezoidal segment timed by a duration: cruise at 1.5 times
#: the average velocity.
DEFAULT_BLEND = 1.0 / 3.0

#: How the orientation moves between waypoints: each angle as a coordinate, or about one axis.
ROTATIONS = ("angles", "axis")

#: Most samples :meth:`Motion.sample` and :meth:`Motion.at` give in one call.
MAX_SAMPLES = 10_000_000

#: Samples evaluated at once (bounds the memory of the gathered coefficients).
_CHUNK = 65_536

#: Relative slack on the ends of the time range and on joint limits (rounding).
_SLACK = 1e-9


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.ascontiguousarray(a, dtype=float)
    a.setflags(write=False)
    return a


@dataclass(frozen=True)
class MotionSamples:
    """A trajectory sampled at ``n`` times (read-only arrays).

    ``pose``, ``velocity``, ``acceleration`` are ``(n, pose_size)`` in pose coordinates;
    ``angular_velocity`` and ``angular_acceleration`` are ``(n, 3)`` in the fixed frame for a
    spatial rigid platform, ``(n, 1)`` (``θ̇``, ``θ̈``) for a planar one and ``(n, 0)`` for a
    point mass."""

    time: np.ndarray
    pose: np.ndarray
    velocity: np.ndarray
    acceleration: np.ndarray
    angular_velocity: np.ndarray
    angular_acceleration: np.ndarray
    pose_names: tuple[str, ...]

    def __post_init__(self) -> None:
        for name in ("time", "pose", "velocity", "acceleration", "angular_velocity", "angular_acceleration"):
            object.__setattr__(self, name, _frozen(getattr(self, name)))


@dataclass(frozen=True)
class Motion:
    """A timed trajectory of ``robot``: piecewise polynomials ``q(t) = Σ_j c_j (t − t_k)^j`` on
    ``[breaks[k], breaks[k+1]]`` with ``coefficients[k, j]`` (``(K, 6, pose_size)``), through
    ``waypoints`` ``(N, pose_size)`` (angles unwrapped) at ``times`` ``(N,)``, from 0 to
    :attr:`duration`, with the time ``law`` and the velocities at via points ``via`` (one of
    :data:`~taut.motion.VIAS`, or ``"given"`` when they were given).  At a break the
    piece that ends there is evaluated (as CASPR samples a segment up to its end), which
    matters only where the law's velocity or acceleration jumps.  With ``rotation="axis"``
    the angle columns of the polynomials hold the rotation vector turned since the segment's
    start, and ``turns`` (:class:`~taut.motion._axis.AxisTurns`) gives the angles.  Build it
    with :func:`trajectory_from_waypoints`."""

    robot: Robot
    law: str
    via: str
    times: np.ndarray
    waypoints: np.ndarray
    breaks: np.ndarray
    coefficients: np.ndarray
    rotation: str = "angles"
    turns: AxisTurns | None = None

    def __post_init__(self) -> None:
        for name in ("times", "waypoints", "breaks", "coefficients"):
            object.__setattr__(self, name, _frozen(getattr(self, name)))

    @property
    def duration(self) -> float:
        """Total duration [s]."""
        return float(self.times[-1])

    def at(self, times: npt.ArrayLike) -> MotionSamples:
        """The trajectory at ``times`` (any order, within ``[0, duration]``)."""
        try:
            t = np.array(times, dtype=float).ravel()
        except (TypeError, ValueError):
            raise TrajectoryError(f"sample times must be numbers, got {times!r}") from None
        if t.size > MAX_SAMPLES:
            raise TrajectoryError(f"{t.size} sample times; at most {MAX_SAMPLES} are evaluated at once")
        if not np.all(np.isfinite(t)):
            raise TrajectoryError("sample times must be finite")
        slack = _SLACK * max(1.0, self.duration)
        outside = (t < -slack) | (t > self.duration + slack)
        if outside.any():
            raise TrajectoryError(
                f"sample time {t[outside][0]:g} s is outside the trajectory's [0, {self.duration:g}] s"
            )
        t = np.clip(t, 0.0, self.duration)
        q, qd, qdd = self._evaluate(t)
        cols = angle_columns(self.robot)
        if self.turns is not None:
            segment = np.clip(np.searchsorted(self.times, t, side="left") - 1, 0, len(self.times) - 2)
            w, a = np.empty((len(t), 3)), np.empty((len(t), 3))
            for s in range(0, len(t), _CHUNK):
                part = slice(s, s + _CHUNK)
                q[part, cols], qd[part, cols], qdd[part, cols], w[part], a[part] = self.turns.evaluate(
                    self.robot.orientation, segment[part], q[part, cols], qd[part, cols], qdd[part, cols]
                )
        elif self.robot.dimension == 3 and not self.robot.is_point_mass:
            # ω = E q̇, α = E q̈ + Ė q̇: E built once for both
            angles, rates = q[:, cols], qd[:, cols]
            E = rate_matrix(angles, self.robot.orientation)
            Ed = rate_matrix_derivative(angles, rates, self.robot.orientation)
            w = np.einsum("nij,nj->ni", E, rates)
            a = np.einsum("nij,nj->ni", E, qdd[:, cols]) + np.einsum("nij,nj->ni", Ed, rates)
        else:
            w, a = qd[:, cols], qdd[:, cols]
        return MotionSamples(t, q, qd, qdd, w, a, tuple(self.robot.pose_names))

    def sample(self, rate_hz: float) -> MotionSamples:
        """The trajectory every ``1/rate_hz`` seconds from 0, and at its end (the last step is
        shorter when the duration is not a whole number of steps)."""
        if not (isinstance(rate_hz, (int, float, np.floating, np.integer)) and math.isfinite(rate_hz) and rate_hz > 0):
            raise TrajectoryError(f"the sampling rate must be a finite number > 0 Hz, got {rate_hz!r}")
        steps = self.duration * float(rate_hz)
        if steps + 2 > MAX_SAMPLES:
            raise TrajectoryError(
                f"{steps:.3g} samples at {rate_hz:g} Hz over {self.duration:g} s; at most {MAX_SAMPLES} are evaluated at once"
            )
        t = np.arange(math.floor(steps * (1 + 1e-12)) + 1) / float(rate_hz)
        if self.duration - t[-1] > _SLACK * max(1.0, self.duration):
            t = np.append(t, self.duration)
        return self.at(t)

    def _evaluate(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        K = len(self.coefficients)
        # at a break, the piece that ends there (as CASPR samples a segment to its end)
        idx = np.clip(np.searchsorted(self.breaks, t, side="left") - 1, 0, K - 1)
        tau = t - self.breaks[idx]
        j = np.arange(DEGREE + 1)
        out = [np.empty((len(t), self.coefficients.shape[2])) for _ in range(3)]
        for s in range(0, len(t), _CHUNK):
            part = slice(s, s + _CHUNK)
            powers = tau[part, None] ** j
            P1 = np.zeros_like(powers)
            P1[:, 1:] = j[1:] * powers[:, :-1]
            P2 = np.zeros_like(powers)
            P2[:, 2:] = (j[2:] * (j[2:] - 1)) * powers[:, :-2]
            C = self.coefficients[idx[part]]
            for o, P in zip(out, (powers, P1, P2)):
                o[part] = np.einsum("nj,njd->nd", P, C)
        return out[0], out[1], out[2]


def _positive_vector(value: npt.ArrayLike, n: int, what: str, *, upper: float = math.inf) -> np.ndarray:
    try:
        v = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise TrajectoryError(f"{what} must be numbers, got {value!r}") from None
    if v.ndim > 1 or (v.ndim == 1 and len(v) != n):
        raise TrajectoryError(f"{what}: expected one number or {n}, got an array of shape {v.shape}")
    v = np.broadcast_to(v, (n,))
    bad = ~(np.isfinite(v) & (v > 0) & (v <= upper))
    if bad.any():
        bound = f" and <= {upper:g}" if math.isfinite(upper) else ""
        raise TrajectoryError(f"{what} must be finite numbers > 0{bound}, got {v[bad][0]!r}")
    return v


def _state_array(robot: Robot, value: npt.ArrayLike, n: int, what: str) -> np.ndarray:
    try:
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise TrajectoryError(f"{what} must be numbers, got {value!r}") from None
    if a.shape != (n, robot.pose_size):
        raise TrajectoryError(f"{what}: expected one per waypoint, {(n, robot.pose_size)}, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise TrajectoryError(f"{what} must be finite")
    return a


def _segment_times(
    W: np.ndarray,
    durations: npt.ArrayLike | None,
    duration: float | None,
    times: npt.ArrayLike | None,
) -> np.ndarray:
    """Times ``(N,)`` of the waypoints from one of durations, duration, times."""
    n = len(W) - 1
    if times is not None:
        try:
            t = np.array(times, dtype=float)
        except (TypeError, ValueError):
            raise TrajectoryError(f"times must be numbers, got {times!r}") from None
        if t.shape != (n + 1,):
            raise TrajectoryError(f"times: expected one per waypoint ({n + 1}), got shape {t.shape}")
        if not np.all(np.isfinite(t)):
            raise TrajectoryError("times must be finite")
        if t[0] != 0:
            raise TrajectoryError(f"times must start at 0, got {t[0]:g}")
        steps = np.diff(t)
        if np.any(steps <= 0):
            k = int(np.argmax(steps <= 0))
            raise TrajectoryError(f"times must increase: waypoint {k + 2} at {t[k + 1]:g} s follows {t[k]:g} s")
        return t
    if durations is not None:
        h = _positive_vector(durations, n, "durations")
    else:
        assert duration is not None
        total = _positive_vector(duration, 1, "duration")[0]
        lengths = np.linalg.norm(np.diff(W, axis=0), axis=1)
        still = np.flatnonzero(lengths == 0)
        if len(still):
            k = int(still[0])
            raise TrajectoryError(
                f"waypoints {k + 1} and {k + 2} coincide: a total duration is shared in proportion to the "
                "segments' lengths, give durations to hold a pose"
            )
        h = total * lengths / lengths.sum()
    return np.concatenate([[0.0], np.cumsum(h)])


def _limited_times(W: np.ndarray, law: str, vmax: np.ndarray, amax: np.ndarray | None) -> tuple[np.ndarray, np.ndarray]:
    """Waypoint times and blend fractions of the shortest rest-to-rest segments within limits."""
    h, blends = [], []
    for k, d in enumerate(np.abs(np.diff(W, axis=0))):
        moving = d > 0
        if not moving.any():
            raise TrajectoryError(
                f"waypoints {k + 1} and {k + 2} coincide: a segment that does not move has no shortest duration, "
                "give durations to hold a pose"
            )
        with np.errstate(over="ignore"):
            V = float(np.min(vmax[moving] / d[moving]))
            A = float(np.min(amax[moving] / d[moving])) if amax is not None else math.inf
        T, blend = minimum_duration(law, V, A)
        if not 0 < T < math.inf:
            raise TrajectoryError(f"segment {k + 1}: the limits give it no finite positive duration ({T:g} s)")
        h.append(T)
        blends.append(blend)
    return np.concatenate([[0.0], np.cumsum(h)]), np.array(blends)


def trajectory_from_waypoints(
    robot: Robot,
    waypoints: npt.ArrayLike,
    durations: npt.ArrayLike | None = None,
    *,
    duration: float | None = None,
    times: npt.ArrayLike | None = None,
    law: str = "quintic",
    via: str = "stop",
    max_velocity: npt.ArrayLike | None = None,
    max_acceleration: npt.ArrayLike | None = None,
    blend: float | Sequence[float] | None = None,
    velocities: npt.ArrayLike | None = None,
    accelerations: npt.ArrayLike | None = None,
    unwrap: bool = True,
    rotation: str = "angles",
) -> Motion:
    """A trajectory of ``robot`` through ``waypoints`` ``(N ≥ 2, pose_size)`` (positions
    ``(N, dimension)`` are completed by :func:`~taut.motion.complete_waypoints`).

    Timing, exactly one of:

    - ``durations``: one per segment [s] (a number: the same for every segment);
    - ``duration``: the total [s], shared out in proportion to the segments' lengths
      ``‖Δq‖`` in pose coordinates (metres and radians counted alike: give ``durations``
      to choose);
    - ``times``: the time of each waypoint, from 0, increasing;
    - ``max_velocity`` and ``max_acceleration`` (one number, or one per pose coordinate, in
      its units per s and s²; ``linear`` needs only ``max_velocity``): the shortest duration
      of each segment whose every coordinate keeps within them (``via="stop"`` only).

    ``law`` is ``linear``, ``cubic``, ``quintic`` or ``trapezoidal`` (:mod:`taut.motion._laws`);
    ``via`` is ``stop``, ``average`` or ``spline`` (:mod:`taut.motion._vias`; ``spline`` is a
    cubic spline; ``linear`` keeps each segment's constant velocity and ``trapezoidal`` stops at
    every waypoint, so both take only ``stop``).  ``velocities`` and
    ``accelerations`` ``(N, pose_size)`` give the state at every waypoint instead (cubic:
    velocities; quintic: both, accelerations zero when not given), as CASPR's
    ``cubic_spline_trajectory`` and ``quintic_spline_trajectory`` do.  ``blend`` is the blend
    fraction ``t_b / T`` of each trapezoidal segment timed by a duration, in ``(0, 1/2]``
    (default :data:`DEFAULT_BLEND`).  ``unwrap=False`` keeps the angles as given (e.g. a full
    turn from 0 to 2π).

    ``rotation`` (one of :data:`ROTATIONS`): ``"angles"`` interpolates each orientation angle
    as a coordinate; ``"axis"`` turns a spatial rigid platform about one axis from each
    waypoint's orientation to the next's, the short way (at most π), the time law timing the
    angle turned — CASPR's spherical joints (:mod:`taut.motion._axis`).  The turn stops at
    every waypoint (``via="stop"``, the angles' columns of ``velocities`` and
    ``accelerations`` zero), is timed by ``durations``, ``duration`` or ``times``, and takes
    the short way whatever ``unwrap``; the motion's waypoints hold the angles the turns
    arrive with.

    Raises :class:`~taut.errors.TrajectoryError` for bad input, and when a joint coordinate
    leaves its limits between waypoints (a spline can overshoot).
    """
    if law not in LAWS:
        raise TrajectoryError(f"unknown time law {law!r}; expected one of {', '.join(LAWS)}")
    if via not in VIAS:
        raise TrajectoryError(f"unknown via-point velocities {via!r}; expected one of {', '.join(VIAS)}")
    if rotation not in ROTATIONS:
        raise TrajectoryError(f"unknown rotation {rotation!r}; expected one of {', '.join(ROTATIONS)}")
    axis = rotation == "axis"
    if axis and (robot.dimension != 3 or robot.is_point_mass):
        raise TrajectoryError("rotation='axis' turns a spatial rigid platform; this robot's angles are coordinates")
    W = validate_waypoints(robot, complete_waypoints(robot, waypoints))
    if unwrap and not axis:
        W = unwrap_angles(robot, W)
    N, n = len(W), len(W) - 1
    limited = max_velocity is not None or max_acceleration is not None
    chosen = [name for name, v in (("durations", durations), ("duration", duration), ("times", times)) if v is not None]
    if limited:
        chosen.append("max_velocity/max_acceleration")
    if len(chosen) != 1:
        raise TrajectoryError(
            "give exactly one of durations, duration, times, or max_velocity and max_acceleration"
            + (f"; got {', '.join(chosen)}" if chosen else "")
        )
    if law in ("linear", "trapezoidal") and via != "stop":
        own = "each segment's constant velocity" if law == "linear" else "at rest"
        raise TrajectoryError(
            f"the {law} law fixes the velocities at the waypoints ({own}): via={via!r} needs law cubic or quintic"
        )
    if via == "spline" and law != "cubic":
        raise TrajectoryError("via='spline' is the cubic spline: give law='cubic'")
    if velocities is not None and (law not in ("cubic", "quintic") or via != "stop"):
        raise TrajectoryError("velocities at the waypoints are given to the cubic or quintic law, without via")
    if accelerations is not None and law != "quintic":
        raise TrajectoryError("accelerations at the waypoints are given to the quintic law")
    if blend is not None and (law != "trapezoidal" or limited):
        raise TrajectoryError("blend is the blend fraction of a trapezoidal law timed by durations, duration or times")
    if axis and (via != "stop" or limited):
        raise TrajectoryError(
            "rotation='axis' stops the turn at every waypoint and is timed by durations, duration or times: "
            "give via='stop' and no velocity or acceleration limits"
        )

    blends = None
    if limited:
        if via != "stop" or velocities is not None or accelerations is not None:
            raise TrajectoryError("velocity and acceleration limits time segments that stop at every waypoint")
        if max_velocity is None or (max_acceleration is None and law != "linear"):
            raise TrajectoryError(f"the {law} law within limits needs max_velocity and max_acceleration")
        vmax = _positive_vector(max_velocity, robot.pose_size, "max_velocity")
        amax = (
            None
            if max_acceleration is None
            else _positive_vector(max_acceleration, robot.pose_size, "max_acceleration")
        )
        t, blends = _limited_times(W, law, vmax, amax)
    else:
        t = _segment_times(W, durations, duration, times)
    h = np.diff(t)
    if law == "trapezoidal" and blends is None:
        blends = _positive_vector(DEFAULT_BLEND if blend is None else blend, n, "blend", upper=0.5)

    zeros = np.zeros_like(W)
    if velocities is not None:
        V = _state_array(robot, velocities, N, "velocities")
    elif via == "average":
        V = average_velocities(t, W)
    elif via == "spline":
        V = spline_velocities(t, W)
    else:
        V = zeros
    Acc = zeros if accelerations is None else _state_array(robot, accelerations, N, "accelerations")
    begin, finish = W[:-1].copy(), W[1:].copy()
    turns = None
    if axis:
        cols = angle_columns(robot)
        for what, given in (("velocities", V), ("accelerations", Acc)):
            moving = np.flatnonzero(np.any(given[:, cols] != 0, axis=1))
            if len(moving):
                raise TrajectoryError(
                    f"{what} at waypoint {moving[0] + 1}: with rotation='axis' the turn stops at every waypoint, "
                    "the angles' velocities and accelerations are zero there"
                )
        W, rotvecs, turns = axis_turns(W, cols, robot.orientation)
        begin[:, cols], finish[:, cols] = 0.0, rotvecs

    starts: list[float] = []
    pieces: list[np.ndarray] = []
    # a segment too short for its move overflows: found below, with its number
    with np.errstate(over="ignore", divide="ignore", invalid="ignore"):
        for k in range(n):
            if law == "linear":
                segment = [(0.0, linear_piece(begin[k], finish[k], h[k]))]
            elif law == "cubic":
                segment = [(0.0, cubic_piece(begin[k], V[k], finish[k], V[k + 1], h[k]))]
            elif law == "quintic":
                segment = [(0.0, quintic_piece(begin[k], V[k], Acc[k], finish[k], V[k + 1], Acc[k + 1], h[k]))]
            else:
                assert blends is not None
                segment = trapezoidal_pieces(begin[k], finish[k], h[k], float(blends[k]))
            for start, c in segment:
                starts.append(t[k] + start)
                pieces.append(c)
    coefficients = np.stack(pieces)
    overflow = ~np.all(np.isfinite(coefficients), axis=(1, 2))
    if overflow.any():
        k = int(np.searchsorted(t, starts[int(np.argmax(overflow))], side="right")) - 1
        raise TrajectoryError(
            f"segment {k + 1} lasts {h[k]:g} s, too short for its change of pose (its polynomial overflows)"
        )
    motion = Motion(
        robot=robot,
        law=law,
        via="given" if velocities is not None else via,
        times=t,
        waypoints=W,
        breaks=np.append(starts, t[-1]),
        coefficients=coefficients,
        rotation=rotation,
        turns=turns,
    )
    _check_joint_limits(motion)
    return motion


def _check_joint_limits(motion: Motion) -> None:
    """Raise when a joint coordinate leaves its limits between waypoints (the extrema of each
    polynomial piece are at its ends or at real roots of its derivative)."""
    robot = motion.robot
    if not robot.n_joints:
        return
    j = np.arange(1, DEGREE + 1)
    for k, C in enumerate(motion.coefficients):
        h = motion.breaks[k + 1] - motion.breaks[k]
        for m in range(robot.n_joints):
            col = robot.wrench_dim + m
            c = C[:, col]
            roots = np.roots((j * c[1:])[::-1]) if np.any(c[1:] != 0) else np.array([])
            tau = np.concatenate(
                [[0.0, h], roots.real[(np.abs(roots.imag) < 1e-12) & (roots.real > 0) & (roots.real < h)]]
            )
            values = np.polyval(c[::-1], tau)
            lo, hi = robot.joint_limits[m]
            slack = _SLACK * max(1.0, abs(lo), abs(hi))
            worst = int(np.argmax(np.maximum(lo - values, values - hi)))
            if values[worst] < lo - slack or values[worst] > hi + slack:
                raise TrajectoryError(
                    f"joint {robot.pose_names[col]} reaches {values[worst]:g} at t = {motion.breaks[k] + tau[worst]:g} s, "
                    f"outside its limits [{lo:g}, {hi:g}] (via={motion.via!r} overshoots; try via='stop')"
                )


def trajectory_from_robot(
    robot: Robot,
    name: str,
    *,
    duration: float | None = None,
    law: str = "quintic",
    via: str = "stop",
) -> Motion:
    """The robot file's trajectory ``name`` (``trajectories:``) as a :class:`Motion`.

    With ``duration`` the moves share it in proportion to their ``steps`` (the samples per
    move of a pose sequence; by their lengths without steps) and ``speed``/``dwell`` are not
    used.  Without it the file's ``speed`` [m/s] times each move by the distance its position
    travels, and ``dwell`` holds the pose at every waypoint, the first included (as
    ``taut trajectory`` does); a trajectory without ``speed`` needs ``duration``.  The file's
    trajectory is read by :func:`~taut.motion._named.robot_trajectory`."""
    tr = robot_trajectory(robot, name)
    what = f"trajectory {name}"
    W = tr.waypoints
    if len(W) < 2:
        raise TrajectoryError(f"{what}: a trajectory needs at least 2 waypoints, got {len(W)}")
    if duration is not None:
        if tr.steps is not None:
            total = _positive_vector(duration, 1, "duration")[0]
            steps = np.asarray(tr.steps, dtype=float)
            return trajectory_from_waypoints(robot, W, total * steps / steps.sum(), law=law, via=via)
        return trajectory_from_waypoints(robot, W, duration=duration, law=law, via=via)
    if tr.speed is None:
        raise TrajectoryError(f"{what} gives no speed: give its duration")
    d = robot.dimension
    moves = np.linalg.norm(np.diff(W[:, :d], axis=0), axis=1) / tr.speed
    if np.any(moves == 0):
        k = int(np.argmax(moves == 0))
        raise TrajectoryError(
            f"{what}: move {k + 1} does not change the position, so speed cannot time it: give duration"
        )
    if tr.dwell == 0:
        return trajectory_from_waypoints(robot, W, moves, law=law, via=via)
    if via != "stop":
        raise TrajectoryError(f"{what} dwells at its waypoints: it stops there, via must be 'stop'")
    held = np.repeat(W, 2, axis=0)
    durations = np.empty(len(held) - 1)
    durations[0::2] = tr.dwell
    durations[1::2] = moves
    return trajectory_from_waypoints(robot, held, durations, law=law, via=via)
