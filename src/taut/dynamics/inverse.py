"""Inverse dynamics: the wrench the cables must apply along a sampled motion, and tensions.

At each sample ``(q, q̇, q̈)`` the platform's rate of momentum about ``p`` (Newton–Euler
through the centre of mass, ``r = R c``, ``ω = E φ̇``, ``α = E φ̈ + Ė φ̇``)

    ``F = m a_c``,  ``a_c = p̈ + α × r + ω × (ω × r)``,
    ``N = I_c α + ω × I_c ω + r × F``,  ``I_c = R I Rᵀ``

minus the applied loads (the robot's weight and constant wrench, and ``w_ext``) is the wrench
``W τ`` the cables must supply (Siciliano et al. 2009, §7.5; the same equations as
:mod:`taut.dynamics.platform`, in twist coordinates: no angle-rate inversion, so the gimbal
lock does not matter here).  The tensions then come from any tension distribution method of
:mod:`taut.statics.tension`, batched over the samples, with ``W τ + w = 0`` for
``w = −(required wrench)`` (Rushton 2022, Eq. 2.11 with the inertial d'Alembert wrench in
``w``).  A sample without admissible tensions is a result, not an error: its index and the
reason are reported.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.2, Eqs. 2.11–2.13. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut.dynamics.platform import PLANAR, POINT_MASS, as_rates, frames, own_load, platform_dynamics
from taut.errors import TautError
from taut.geometry.rates import angular_acceleration, angular_velocity
from taut.geometry.vectors import cross
from taut.kinematics.pose import as_poses
from taut.model.robot import Robot

__all__ = ["InverseDynamicsResult", "required_wrench", "inverse_dynamics"]

#: Samples solved per call of the tension distribution (and per progress report).
CHUNK = 20_000

_WHY = {
    "infeasible": "no tensions within the bounds give the required wrench (proved)",
    "undefined": "a cable has zero length or no tangent point on its pulley: the structure matrix does not exist",
}


@dataclass(frozen=True)
class InverseDynamicsResult:
    """Tensions along ``N`` samples of a motion of a robot with ``n`` cables."""

    time: np.ndarray | None  #: ``(N,)`` sample times, when given
    wrench: np.ndarray  #: ``(N, dof)`` the wrench ``W τ`` the cables must apply
    tensions: np.ndarray  #: ``(N, n)``; zeros where no admissible distribution was found
    feasible: np.ndarray  #: ``(N,)`` bool
    #: ``(N,)`` ``"optimal"``, ``"infeasible"`` (proved), ``"not-found"`` (the method gave up)
    #: or ``"undefined"`` (no structure matrix: a cable of zero length)
    status: np.ndarray
    reasons: tuple[str, ...]  #: ``N`` reasons, ``""`` where feasible
    method: str

    def failures(self) -> list[tuple[int, str]]:
        """``(index, reason)`` of every sample without admissible tensions (0-based)."""
        return [(int(k), self.reasons[k]) for k in np.flatnonzero(~self.feasible)]

    @property
    def first_failure(self) -> int | None:
        """Index of the first sample without admissible tensions, or None."""
        bad = np.flatnonzero(~self.feasible)
        return int(bad[0]) if bad.size else None


def _motion(
    robot: Robot, q: npt.ArrayLike, qd: npt.ArrayLike, qdd: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    arr, single = as_poses(robot, q)
    N = arr.shape[0]
    return arr, as_rates(robot, qd, N), as_rates(robot, qdd, N, "pose accelerations"), single


def required_wrench(
    robot: Robot,
    q: npt.ArrayLike,
    qd: npt.ArrayLike,
    qdd: npt.ArrayLike,
    w_ext: npt.ArrayLike | None = None,
) -> np.ndarray:
    """The wrench ``W τ`` ``(N, dof)`` (``(dof,)`` for one sample) the cables must apply for
    the pose accelerations ``qdd`` at poses ``q`` with rates ``qd``, given an external wrench
    ``w_ext`` (``(dof,)`` or ``(N, dof)``) besides the robot's own weight; taut's wrench
    convention (forces, then moments about ``p``, fixed frame).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
    """
    platform_dynamics(robot)
    arr, vel, acc, single = _motion(robot, q, qd, qdd)
    w = _wrench(robot, arr, vel, acc)
    if w_ext is not None:
        w = w - as_rates(robot, w_ext, arr.shape[0], "external wrenches")
    return w[0] if single else w


def _wrench(robot: Robot, q: np.ndarray, qd: np.ndarray, qdd: np.ndarray) -> np.ndarray:
    pd = platform_dynamics(robot)
    d, m = pd.dimension, pd.mass
    if pd.kind == POINT_MASS:
        return m * qdd - own_load(pd, np.broadcast_to(np.eye(3), (q.shape[0], 3, 3)), np.zeros((q.shape[0], 3)))
    R, r = frames(pd, q)
    N = q.shape[0]
    omega, alpha = np.zeros((N, 3)), np.zeros((N, 3))
    if pd.kind == PLANAR:
        omega[:, 2], alpha[:, 2] = qd[:, 2], qdd[:, 2]
    else:
        omega = angular_velocity(q[:, 3:6], qd[:, 3:6], pd.orientation)
        alpha = angular_acceleration(q[:, 3:6], qd[:, 3:6], qdd[:, 3:6], pd.orientation)
    pdd = np.zeros((N, 3))
    pdd[:, :d] = qdd[:, :d]
    ac = pdd + cross(alpha, r) + cross(omega, cross(omega, r))
    F = m * ac
    Ic = R @ pd.inertia @ np.swapaxes(R, 1, 2)
    Ia, Iw = np.einsum("nij,nj->ni", Ic, alpha), np.einsum("nij,nj->ni", Ic, omega)
    moment = Ia + cross(omega, Iw) + cross(r, F)
    out = np.concatenate([F[:, :d], moment[:, 2:] if pd.kind == PLANAR else moment], axis=1)
    return out - own_load(pd, R, r)


def inverse_dynamics(
    robot: Robot,
    q: npt.ArrayLike,
    qd: npt.ArrayLike,
    qdd: npt.ArrayLike,
    *,
    method: str = "improved-closed-form",
    w_ext: npt.ArrayLike | None = None,
    time: npt.ArrayLike | None = None,
    progress: Callable[[int, int | None], None] | None = None,
) -> InverseDynamicsResult:
    """Cable tensions along a sampled motion ``(q, q̇, q̈)`` (each ``(N, dof)``, or one sample).

    ``method`` is a tension distribution method of :data:`taut.statics.tension.METHODS`
    (``lp``, ``qp``, ``inf``, ``closed-form``, ``improved-closed-form``, ``barycentric``); the
    bounds are ``robot.tension_bounds``.  ``w_ext`` is an external wrench besides the robot's
    weight, ``time (N,)`` the sample times (kept in the result for plots).  Samples without an
    admissible distribution get zero tensions, ``feasible = False`` and a reason.

    Raises
    ------
    TautError
        Bad shapes or values, an unknown method.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform), or a jointed platform.

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
    .. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.2, Eqs. 2.11–2.13. (docs/references.bib: rushton2022)
    """
    from taut.kinematics.batch import batch_structure_matrices
    from taut.statics.tension import METHODS, solve_tensions

    if method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    platform_dynamics(robot)
    arr, vel, acc, _ = _motion(robot, q, qd, qdd)
    N, n = arr.shape[0], robot.n_cables
    times = None
    if time is not None:
        times = np.array(time, dtype=float)
        if times.shape != (N,) or not np.isfinite(times).all():
            raise TautError(f"sample times must be {N} finite numbers, got shape {times.shape}")
    wrench = _wrench(robot, arr, vel, acc)
    if w_ext is not None:
        wrench = wrench - as_rates(robot, w_ext, N, "external wrenches")
    tmin, tmax = robot.tension_bounds
    tensions = np.zeros((N, n))
    feasible = np.zeros(N, dtype=bool)
    status = np.full(N, "undefined", dtype=object)
    for start in range(0, N, CHUNK):
        part = slice(start, min(start + CHUNK, N))
        _, W, ok = batch_structure_matrices(robot, arr[part])
        idx = np.flatnonzero(ok) + start
        if idx.size:
            res = solve_tensions(W[ok], -wrench[idx], tmin, tmax, method)
            tensions[idx], feasible[idx], status[idx] = res.tensions, res.feasible, res.status
        if progress is not None:
            progress(part.stop, N)
    reasons = tuple("" if s == "optimal" else _reason(str(s), method) for s in status)
    labels = status.astype(str)
    for a in [wrench, tensions, feasible, labels] + ([] if times is None else [times]):
        a.setflags(write=False)
    return InverseDynamicsResult(times, wrench, tensions, feasible, labels, reasons, method)


def _reason(status: str, method: str) -> str:
    if status in _WHY:
        return _WHY[status]
    return f"method {method!r} found no admissible tensions (it may give up although some exist: try 'qp' or 'lp')"
