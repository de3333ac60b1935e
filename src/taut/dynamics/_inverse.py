"""Inverse dynamics: the wrench the cables must apply along a sampled motion, and tensions.

At each sample ``(q, q̇, q̈)`` the platform's rate of momentum about ``p`` (Newton–Euler
through the centre of mass, ``r = R c``, ``ω = E φ̇``, ``α = E φ̈ + Ė φ̇``)

    ``F = m a_c``,  ``a_c = p̈ + α × r + ω × (ω × r)``,
    ``N = I_c α + ω × I_c ω + r × F``,  ``I_c = R I Rᵀ``

minus the applied loads (the robot's weight and constant wrench, and ``w_ext``) is the wrench
``W τ`` the cables must supply (Siciliano et al. 2009, §7.5; the same equations as
:mod:`taut.dynamics._platform`, in twist coordinates: no angle-rate inversion, so the gimbal
lock does not matter here).  The tensions then come from any tension distribution method of
:mod:`taut.statics._tension`, batched over the samples, with ``W τ + w = 0`` for
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

from taut._results import Result
from taut.dynamics._forward import KernelModel, kernel_model, quick_rows
from taut.dynamics._platform import as_rates, check_callable
from taut.errors import TautError
from taut.kinematics import as_poses, refuse_near_swivel_axis, refuse_wrapped
from taut.model import Robot

__all__ = ["InverseDynamicsResult", "required_wrench", "inverse_dynamics"]

#: Samples solved per call of the tension distribution (and per progress report).
CHUNK = 20_000

#: The status of a sample: admissible tensions found, proved infeasible, the method gave up,
#: or no structure matrix.
STATUSES = ("optimal", "infeasible", "not-found", "undefined")
_ORDER = np.argsort(STATUSES)

_WHY = {
    "infeasible": "no tensions within the bounds give the required wrench (proved)",
    "undefined": "a cable has zero length or no tangent point on its pulley: the structure matrix does not exist",
}


@dataclass(frozen=True)
class InverseDynamicsResult(Result):
    """Tensions along ``N`` samples of a motion of a robot with ``n`` cables
    (:func:`inverse_dynamics`).

    For a single sample the array fields have no batch axis (``docs/architecture.md`` §2.1):
    ``tensions (n,)``, ``wrench (dof,)``, and ``feasible``, ``status``, ``reasons`` and
    ``times`` are 0-d arrays.

    Attributes
    ----------
    times : ndarray, shape (N,), or None
        Sample times [s], when given.
    wrench : ndarray, shape (N, dof)
        The wrench ``W τ`` the cables must apply (:func:`required_wrench`).
    tensions : ndarray, shape (N, n)
        [N]; zeros where no admissible distribution was found.
    feasible : ndarray of bool, shape (N,)
    status : ndarray of str, shape (N,)
        ``"optimal"``, ``"infeasible"`` (proved), ``"not-found"`` (the method gave up) or
        ``"undefined"`` (no structure matrix: a cable of zero length).
    reasons : ndarray of str, shape (N,)
        Why a sample has no admissible tensions, ``""`` where feasible.
    method : str
        The tension distribution method.
    actuator_forces : ndarray, shape (N, n_actuators)
        The forces [N] or torques [N m] of the joint actuators of a jointed platform, in the
        order of :attr:`taut.model.Robot.actuated_joints` (no columns without actuators);
        zeros where no admissible distribution was found.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import inverse_dynamics
    >>> res = inverse_dynamics(example("planar-4cable"), np.zeros(3), np.zeros(3), [0.0, 400.0, 0.0], method="qp")
    >>> bool(res.feasible), str(res.status), res.failures()
    (False, 'infeasible', [(0, 'no tensions within the bounds give the required wrench (proved)')])
    """

    times: np.ndarray | None  #: ``(N,)`` sample times, when given
    wrench: np.ndarray  #: ``(N, dof)`` the wrench ``W τ`` the cables must apply
    tensions: np.ndarray  #: ``(N, n)``; zeros where no admissible distribution was found
    feasible: np.ndarray  #: ``(N,)`` bool
    #: ``(N,)`` ``"optimal"``, ``"infeasible"`` (proved), ``"not-found"`` (the method gave up)
    #: or ``"undefined"`` (no structure matrix: a cable of zero length)
    status: np.ndarray
    reasons: np.ndarray  #: ``(N,)`` str: why a sample has no admissible tensions, ``""`` where feasible
    method: str
    actuator_forces: np.ndarray  #: ``(N, n_actuators)`` the joint actuators' forces

    def failures(self) -> list[tuple[int, str]]:
        """The samples without admissible tensions.

        Returns
        -------
        list of (int, str)
            ``(index, reason)``, 0-based indices.
        """
        reasons = np.atleast_1d(self.reasons)
        return [(int(k), str(reasons[k])) for k in np.flatnonzero(~np.atleast_1d(self.feasible))]

    @property
    def first_failure(self) -> int | None:
        """The 0-based index of the first sample without admissible tensions, or None."""
        bad = np.flatnonzero(~np.atleast_1d(self.feasible))
        return int(bad[0]) if bad.size else None


def _motion(
    robot: Robot, q: npt.ArrayLike, qd: npt.ArrayLike, qdd: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    dof = robot.pose_size
    quick = quick_rows(robot, q, ((qd, dof), (qdd, dof)))
    if quick is not None:
        (arr, vel, acc), single = quick
        return arr, vel, acc, single
    arr, single = as_poses(robot, q)
    N = arr.shape[0]
    return arr, as_rates(robot, qd, N), as_rates(robot, qdd, N, "pose accelerations"), single


def required_wrench(
    robot: Robot,
    q: npt.ArrayLike,
    qd: npt.ArrayLike,
    qdd: npt.ArrayLike,
    *,
    wrench: npt.ArrayLike | None = None,
) -> np.ndarray:
    """The wrench ``W τ`` the cables must apply for a motion: Newton–Euler through the centre of
    mass, minus the robot's own load and an external wrench.

    Parameters
    ----------
    robot : Robot
    q, qd, qdd : array_like, shape (N, dof) or (dof,)
        Poses, pose rates and pose accelerations.
    wrench : array_like, shape (N, dof) or (dof,), optional
        External wrench besides the robot's own weight.

    Returns
    -------
    ndarray, shape (N, dof) or (dof,) for one sample
        taut's wrench convention: forces, then moments about ``p``, fixed frame [N, N m].

    Raises
    ------
    TautError
        Bad shapes or values (:class:`~taut.errors.PoseError` for poses and rates).
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform; a jointed platform: any of its
        bodies, named).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)

    Examples
    --------
    The planar platform (1 kg) at rest needs its weight held; accelerating at 1 m/s² along x
    needs 1 N more:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import required_wrench
    >>> required_wrench(example("planar-4cable"), np.zeros((2, 3)), np.zeros((2, 3)), [[0, 0, 0], [1.0, 0, 0]])
    array([[0.  , 9.81, 0.  ],
           [1.  , 9.81, 0.  ]])
    """
    model = kernel_model(robot)
    arr, vel, acc, single = _motion(robot, q, qd, qdd)
    w = _ext(robot, wrench, arr.shape[0])
    need, _, _, _ = _samples(model, arr, vel, acc, w, robot.tension_bounds, closed_form=False, cables=False)
    return need[0] if single else need


def _ext(robot: Robot, wrench: npt.ArrayLike | None, N: int) -> np.ndarray:
    if wrench is None:
        return np.zeros((N, robot.pose_size))
    return np.ascontiguousarray(as_rates(robot, wrench, N, "external wrenches"))


def _samples(
    model: KernelModel,
    q: np.ndarray,
    qd: np.ndarray,
    qdd: np.ndarray,
    w: np.ndarray,
    bounds: tuple[np.ndarray, np.ndarray],
    closed_form: bool,
    cables: bool = True,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Compiled wrenches ``(N, dof)``, structure matrices ``(N, dof, n)``,
    closed-form tensions ``(N, n)`` and the kernel status ``(N,)`` (see
    :func:`taut.dynamics._kernels.inverse_samples`)."""
    from taut.dynamics._kernels import inverse_samples
    from taut.statics import EQUILIBRIUM_RTOL

    N, dof = q.shape
    ip, fp, cab = model.args
    if not cables:
        cab = cab[:0]
    n = cab.shape[0]
    wrench, W, tau = np.empty((N, dof)), np.zeros((N, dof, n)), np.zeros((N, n))
    status = np.empty(N, np.int64)
    c = np.ascontiguousarray
    inverse_samples(
        ip,
        fp,
        cab,
        closed_form,
        c(q),
        c(qd),
        c(qdd),
        c(w),
        bounds[0],
        bounds[1],
        EQUILIBRIUM_RTOL,
        wrench,
        W,
        tau,
        status,
    )
    return wrench, W, tau, status


def inverse_dynamics(
    robot: Robot,
    q: npt.ArrayLike,
    qd: npt.ArrayLike,
    qdd: npt.ArrayLike,
    *,
    method: str = "improved-closed-form",
    wrench: npt.ArrayLike | None = None,
    tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    times: npt.ArrayLike | None = None,
    progress: Callable[[int, int | None], None] | None = None,
) -> InverseDynamicsResult:
    """Cable tensions along a sampled motion ``(q, q̇, q̈)``.

    Samples without an admissible distribution get zero tensions, ``feasible = False`` and a
    reason.

    On a platform carrying jointed bodies the samples hold the joint coordinates too (within
    their ``limits``: :func:`taut.kinematics.as_poses` refuses a sample beyond them), the
    wrench is the generalized force ``A τ`` in the twist coordinates (a wrench about ``p``,
    then one force or torque per joint; :mod:`taut.dynamics._tree`) and the distribution
    solves it with the cable columns ``A`` of the jointed structure matrix
    (:func:`taut.kinematics.jointed_structure_matrix`) and, for each joint with an actuator
    (``joint.actuator``), a unit column with the actuator's bounds (its force in
    ``actuator_forces``); the other joints are passive, moved by the cables acting across them.  The wrenches, structure matrices and, for ``closed-form``, the tensions are
    computed by a compiled kernel; the samples it does not accept, and every sample of the
    other methods, go to :func:`taut.statics.solve_tensions`, so that ``feasible`` means what
    it means there.

    Parameters
    ----------
    robot : Robot
    q, qd, qdd : array_like, shape (N, dof) or (dof,)
        Poses, pose rates and pose accelerations; one sample gives a result without the
        batch axis.
    method : str, optional
        A tension distribution method of :data:`taut.statics.METHODS` (``lp``, ``qp``,
        ``inf``, ``closed-form``, ``improved-closed-form``, ``barycentric``).
    wrench : array_like, shape (N, dof) or (dof,), optional
        External wrench besides the robot's weight.
    tension_bounds : (tmin, tmax), optional
        Each a number or one per cable [N]; default the cables' own.
    times : array_like, shape (N,), optional
        The sample times [s], kept in the result (for plots).
    progress : callable, optional
        ``progress(done, total)``, with sample counts.

    Returns
    -------
    InverseDynamicsResult

    Raises
    ------
    TautError
        Bad shapes or values, an unknown method, bad tension bounds or times.
    UnsupportedRobotError
        A robot without mass (or inertia, for a rigid platform; a jointed platform: any of its
        bodies, named).
    WrappedCableError
        A sample where a cable of a variable-structure robot, taken as a straight line, meets
        one of its obstacles (its wrapped length depends on the motion).
    InfeasiblePoseError
        A sample where a cable's anchor is within its swivelling pulley's radius of the
        pulley's axis (:func:`taut.kinematics.refuse_near_swivel_axis`).

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
    .. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §2.1.2, Eqs. 2.11–2.13. (docs/references.bib: rushton2022)
    .. [3] A. Pott, T. Bruckmann, L. Mikelsons, "Closed-form force distribution for parallel
       wire robots", Computational Kinematics, Springer, 2009. (docs/references.bib: pott2009)

    Examples
    --------
    The planar platform at rest, accelerating along x, and far too fast upwards:

    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import inverse_dynamics
    >>> qdd = [[0, 0, 0], [1.0, 0, 0], [0, 400.0, 0]]
    >>> res = inverse_dynamics(example("planar-4cable"), np.zeros((3, 3)), np.zeros((3, 3)), qdd, method="qp")
    >>> res.tensions.round(3)
    array([[1.   , 1.   , 7.757, 7.757],
           [1.   , 1.727, 8.484, 7.757],
           [0.   , 0.   , 0.   , 0.   ]])
    >>> res.feasible, res.first_failure
    (array([ True,  True, False]), 2)
    """
    from taut.statics import METHODS, input_bounds, solve_inputs

    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    check_callable(progress, "progress")
    model = kernel_model(robot, actuators=True)
    arr, vel, acc, single = _motion(robot, q, qd, qdd)
    N, n, nc = arr.shape[0], model.n, robot.n_cables
    sample_times = None
    if times is not None:
        try:
            sample_times = np.array(times, dtype=float)
        except (TypeError, ValueError):
            raise TautError(f"sample times must be numbers, got {times!r}") from None
        sample_times = sample_times.reshape(-1) if single else sample_times
        if sample_times.shape != (N,) or not np.isfinite(sample_times).all():
            raise TautError(f"sample times must be {N} finite numbers, got shape {sample_times.shape}")
    refuse_wrapped(robot, arr, times=sample_times, what="of the motion")
    refuse_near_swivel_axis(robot, arr, times=sample_times, what="of the motion")
    from taut.dynamics._kernels import ZERO_LENGTH

    w = _ext(robot, wrench, N)
    bounds = input_bounds(robot, _tension_bounds(robot, tension_bounds))
    need, tensions = np.empty((N, robot.pose_size)), np.zeros((N, n))
    feasible = np.zeros(N, dtype=bool)
    code = np.full(N, STATUSES.index("undefined"), dtype=np.int64)
    for start in range(0, N, CHUNK):
        part = slice(start, min(start + CHUNK, N))
        closed = method == "closed-form"
        wr, W, tau, st = _samples(model, arr[part], vel[part], acc[part], w[part], bounds, closed)
        need[part] = wr
        ok = st != ZERO_LENGTH
        done = ok & (st == 0) if closed else np.zeros_like(ok)
        if closed:
            tensions[part][done], feasible[part][done], code[part][done] = tau[done], True, STATUSES.index("optimal")
        rest = np.flatnonzero(ok & ~done)
        if rest.size:
            x, ok_rest, status = solve_inputs(W[rest], wr[rest], *bounds, nc, method)
            idx = rest + start
            tensions[idx], feasible[idx] = x, ok_rest
            code[idx] = _ORDER[np.searchsorted(STATUSES, status, sorter=_ORDER)]
        if progress is not None:
            progress(part.stop, N)
    labels = np.array(STATUSES)[code]
    reasons = np.array([_reason(s, method) for s in STATUSES])[code]
    forces = tensions[:, nc:].copy()
    arrays = [need, tensions[:, :nc].copy(), feasible, labels, reasons, forces]
    arrays += [] if sample_times is None else [sample_times]
    if single:
        arrays = [np.array(a[0]) for a in arrays]
    w_, tau, ok, st, why, zeta = arrays[:6]
    return InverseDynamicsResult(None if sample_times is None else arrays[6], w_, tau, ok, st, why, method, zeta)


def _tension_bounds(
    robot: Robot, tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike] | None
) -> tuple[np.ndarray, np.ndarray]:
    """``(tmin, tmax)`` as C-contiguous ``(n,)`` arrays: the robot's own, or ``tension_bounds``
    (each a number or one per cable) checked."""
    if tension_bounds is None:
        return robot.tension_bounds
    n = robot.n_cables
    try:
        lo, hi = (np.ascontiguousarray(np.broadcast_to(np.asarray(b, dtype=float), (n,))) for b in tension_bounds)
    except (TypeError, ValueError):
        raise TautError(
            f"{robot.name}: tension_bounds must be (tmin, tmax), each a number or {n} numbers, got {tension_bounds!r}"
        ) from None
    if not np.isfinite(lo).all() or np.isnan(hi).any() or (lo < 0).any() or (hi < lo).any():
        raise TautError(
            f"{robot.name}: tension bounds need 0 <= tmin <= tmax and a finite tmin, got {lo.tolist()}, {hi.tolist()}"
        )
    return lo, hi


def _reason(status: str, method: str) -> str:
    if status == "optimal":
        return ""
    if status in _WHY:
        return _WHY[status]
    return f"method {method!r} found no admissible tensions (it may give up although some exist: try 'qp' or 'lp')"
