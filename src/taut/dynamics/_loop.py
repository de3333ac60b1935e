"""The inner loop of a controller: one state at a time, as fast as the compiled kernels allow.

:func:`taut.dynamics.rk4_step` and :func:`taut.dynamics.inverse_dynamics`
check their input and build immutable results, which costs several times the arithmetic of
one state.  A control loop at 1 kHz calls them every millisecond with states it produced
itself, so :class:`LoopModel` checks the robot once and then runs the kernels on
preallocated buffers: :meth:`LoopModel.tensions` (the required wrench and a tension
distribution: the compiled closed form of Pott et al. 2009, or any method of
:mod:`taut.statics._tension` where it gives up; the joint actuators of a jointed platform as
extra columns with their bounds, :mod:`taut.statics`, :func:`~taut.statics.solve_inputs`) and :meth:`LoopModel.step` (one RK4 step with
the tensions held).  A singular configuration still raises.

References
----------
.. [1] A. Pott, T. Bruckmann, L. Mikelsons, "Closed-form force distribution for parallel wire
   robots", Computational Kinematics, Springer, 2009. (docs/references.bib: pott2009)
.. [2] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §7.5. (docs/references.bib: siciliano2009)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from taut.dynamics._forward import KernelModel, kernel_model
from taut.dynamics._sagging import LEAST_RTOL, Anderson, SaggingCables
from taut.errors import InfeasiblePoseError, SingularConfigurationError, TautError
from taut.model import Robot

__all__ = ["LoopModel", "loop_model"]


@dataclass(frozen=True)
class LoopModel:
    """A robot prepared for a control loop (:func:`loop_model`): the kernels' arguments and
    preallocated buffers, so that one state costs little more than its arithmetic.

    Not a result: its buffers are written at every call (the arrays it returns are new).

    Attributes
    ----------
    robot : Robot
    method : str
        The fallback tension distribution method where the compiled closed form gives up.
    kernels : KernelModel
        The compiled kernels' arguments.
    buffers : dict of str to ndarray
        One-row work arrays.
    sag : SaggingCables or None
        The sagging cables and their last catenaries (:mod:`taut.dynamics._sagging`), None
        without sagging cables.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.dynamics import loop_model
    >>> lm = loop_model(example("planar-4cable"))
    >>> lm.method, lm.buffers["tau"].shape
    ('qp', (1, 4))
    """

    robot: Robot
    method: str  #: fallback tension distribution method where the closed form gives up
    kernels: KernelModel = field(repr=False)
    buffers: dict[str, np.ndarray] = field(repr=False)
    sag: SaggingCables | None = field(default=None, repr=False)

    def tensions(
        self, q: npt.ArrayLike, qd: npt.ArrayLike, qdd: npt.ArrayLike, *, wrench: npt.ArrayLike | None = None
    ) -> tuple[np.ndarray, bool]:
        """Tensions for the pose accelerations ``qdd`` at the state ``(q, q̇)``: the required wrench
        and a tension distribution (the compiled closed form of Pott et al. 2009, else
        :attr:`method`).  Sagging cables pull along their catenaries' tangents at the platform
        with these tensions (their platform-end tensions): the distribution is iterated to
        consistency with the catenaries (:mod:`taut.dynamics._sagging`).

        Parameters
        ----------
        q, qd, qdd : array_like, shape (dof,)
            The pose, its rates and the commanded accelerations.
        wrench : array_like, shape (dof,), optional
            External wrench besides the weight.

        Returns
        -------
        tensions : ndarray, shape (n,) or (n + n_actuators,)
            [N]; zeros when not admissible.  A platform whose joints have actuators gets
            their forces [N or N m] after the tensions (:attr:`taut.model.Robot.actuated_joints`).
        admissible : bool
            Whether the tensions (and actuator forces) are within their bounds and give the wrench.

        Raises
        ------
        TautError
            Arrays of the wrong size or not numbers.
        InfeasiblePoseError
            Where a cable has zero length.

        Examples
        --------
        The weight of the planar platform at rest, held by the closed form:

        >>> import numpy as np
        >>> from taut.model import example
        >>> from taut.kinematics import structure_matrix
        >>> from taut.dynamics import loop_model
        >>> robot = example("planar-4cable")
        >>> tau, ok = loop_model(robot).tensions(np.zeros(3), np.zeros(3), np.zeros(3))
        >>> ok, (structure_matrix(robot, np.zeros(3)) @ tau).round(6) + 0.0
        (True, array([0.  , 9.81, 0.  ]))
        """
        from taut.dynamics._kernels import OK, ZERO_LENGTH, inverse_samples
        from taut.statics import EQUILIBRIUM_RTOL, solve_inputs

        b = self.buffers
        try:
            b["q"][0], b["qd"][0], b["qdd"][0] = q, qd, qdd
            b["w"][0] = 0.0 if wrench is None else wrench
        except (TypeError, ValueError):
            raise TautError(
                f"{self.robot.name}: q, qd, qdd and wrench must be {b['q'].shape[1]} numbers each"
            ) from None
        lo, hi = b["lo"], b["hi"]
        ip, fp, cab = self.kernels.args
        inverse_samples(
            ip,
            fp,
            cab,
            self.sag is None,
            b["q"],
            b["qd"],
            b["qdd"],
            b["w"],
            lo,
            hi,
            EQUILIBRIUM_RTOL,
            b["wrench"],
            b["W"],
            b["tau"],
            b["status"],
        )
        status = b["status"][0]
        if status == ZERO_LENGTH:
            raise InfeasiblePoseError(
                f"{self.robot.name}: a cable has no direction (zero length, or its anchor on a swivel axis or on "
                f"its pulley) at {np.asarray(q).tolist()}"
            )
        if self.sag is not None:
            return self._sagging_tensions(self.sag, b["q"][0], b["W"][0], b["wrench"][0])
        if status == OK:
            return b["tau"][0].copy(), True
        x, ok, _ = solve_inputs(b["W"][0], b["wrench"][0], lo, hi, self.robot.n_cables, self.method)
        return x, bool(ok)

    def _distribute(self, W: np.ndarray, wrench: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, bool]:
        """The compiled closed form, else :attr:`method` (as for straight cables)."""
        from taut.dynamics._kernels import closed_form_one
        from taut.statics import EQUILIBRIUM_RTOL, solve_inputs

        tau = np.empty(W.shape[1])
        if closed_form_one(W, wrench, lo, hi, EQUILIBRIUM_RTOL, tau, np.empty((W.shape[0], W.shape[0]))):
            return tau, True
        x, ok, _ = solve_inputs(W, wrench, lo, hi, self.robot.n_cables, self.method)
        return x, bool(ok)

    def _sagging_tensions(
        self, sag: SaggingCables, q: np.ndarray, W: np.ndarray, wrench: np.ndarray
    ) -> tuple[np.ndarray, bool]:
        """The distribution iterated with the catenaries' tangents, from the last update's
        catenaries: as :func:`taut.cables.sagging_ik`, the bounds of each sagging cable moved by
        its tension difference between its ends, and at least :data:`~taut.cables.TAUT_WEIGHTS`
        times its weight at its lower end."""
        from taut.cables import MAX_SAG_STEPS, SAG_TOL, TAUT_WEIGHTS, catenary_tensions
        from taut.errors import ArgumentError

        b, k = self.buffers, sag.which
        arms, span, rise, chord, level = sag.geometry(q)
        lo0, hi0 = b["lo"].copy(), b["hi"].copy()
        lo0[k] = np.maximum(lo0[k], TAUT_WEIGHTS * sag.weights * (chord + np.maximum(-rise, 0.0)))
        W = W.copy()
        # from the chords turned by the last update's sag angles (where the cables hardly sag, the
        # straight distribution first), but for a cable that was at its least tension: it sagged
        # as much as it does at any tension, and started so, it could stay there where the
        # distribution from its chord pulls it taut (two consistent answers; sagging_ik's is this)
        catenary = sag.controller
        phi, delta = np.arctan2(rise, span), np.zeros(k.size)
        if catenary is not None:
            turn = np.arctan2(catenary.vertical_forces, catenary.horizontal_forces)
            phi += np.where(sag.least, 0.0, turn - np.arctan2(catenary.rise, catenary.span))
            delta = catenary.exit_tensions - catenary.platform_tensions
        history = Anderson()
        failed = np.zeros(self.kernels.n), False
        for _ in range(MAX_SAG_STEPS):
            W[:, k] = sag.columns(arms, np.cos(phi)[:, None] * level + np.sin(phi)[:, None] * sag.up)
            lo, hi = lo0.copy(), hi0.copy()
            lo[k], hi[k] = np.maximum(lo0[k], lo0[k] - delta), np.minimum(hi0[k], hi0[k] - delta)
            if (lo > hi).any():
                return failed
            tau, ok = self._distribute(W, wrench, lo, hi)
            if not ok:
                return failed
            try:
                catenary = catenary_tensions(span, rise, tau[k], sag.weights, sag.stiffness, start=catenary)
            except ArgumentError:
                return failed
            g = np.arctan2(catenary.vertical_forces, catenary.horizontal_forces)
            delta = catenary.exit_tensions - catenary.platform_tensions
            if np.abs(g - phi).max() <= SAG_TOL:
                sag.controller = catenary
                sag.least = tau[k] <= lo[k] + LEAST_RTOL * np.maximum(lo[k], 1.0)
                return tau, True
            phi = history.step(phi, g)
        return failed

    def exit_tensions(self, q: npt.ArrayLike, tensions: npt.ArrayLike) -> np.ndarray:
        """The cables' tensions at their exits at the pose ``q`` under ``tensions``: a sagging
        cable's from its catenary (the plant's, solved from its last one), a straight cable's
        its tension.

        Parameters
        ----------
        q : array_like, shape (dof,)
        tensions : array_like, shape (n,) or (n + n_actuators,)
            [N], at the platform ends.

        Returns
        -------
        ndarray, shape (n,)
            [N].

        Raises
        ------
        TautError
            Arrays of the wrong size or not numbers.
        ArgumentError
            Where no catenary has a sagging cable's tension through its ends (too slack).

        Examples
        --------
        >>> import numpy as np
        >>> from taut.model import example
        >>> from taut.dynamics import loop_model
        >>> loop_model(example("planar-4cable")).exit_tensions(np.zeros(3), np.full(4, 5.0))
        array([5., 5., 5., 5.])
        """
        n, dof = self.robot.n_cables, self.robot.pose_size
        try:
            tau = np.array(tensions, dtype=float).reshape(self.kernels.n)[:n]
            x = np.array(q, dtype=float).reshape(dof)
        except (TypeError, ValueError):
            raise TautError(f"{self.robot.name}: q must be {dof} numbers and tensions {self.kernels.n}") from None
        if self.sag is not None:
            self.sag.pull(x, tau[self.sag.which])
            assert self.sag.plant is not None, "pull solves the plant's catenaries"
            tau[self.sag.which] = self.sag.plant.exit_tensions
        return tau

    def step(
        self,
        q: npt.ArrayLike,
        qd: npt.ArrayLike,
        tensions: npt.ArrayLike,
        dt: float,
        *,
        wrench: npt.ArrayLike | None = None,
    ) -> tuple[np.ndarray, np.ndarray]:
        """One RK4 step from ``(q, q̇)`` with the tensions and the external wrench held.

        Parameters
        ----------
        q, qd : array_like, shape (dof,)
            The state.
        tensions : array_like, shape (n,) or (n + n_actuators,)
            [N], then the joint actuators' forces where the platform has some.
        dt : float
            The step [s].
        wrench : array_like, shape (dof,), optional
            External wrench besides the weight.

        Returns
        -------
        q, qd : ndarray, shape (dof,)
            The state after the step.

        Raises
        ------
        TautError
            Arrays of the wrong size or not numbers, a ``dt`` that is not a number.
        SingularConfigurationError
            At the gimbal lock.
        InfeasiblePoseError
            Where a cable has zero length.

        Examples
        --------
        >>> import numpy as np
        >>> from taut.model import example
        >>> from taut.dynamics import loop_model
        >>> loop_model(example("planar-4cable")).step(np.zeros(3), np.zeros(3), np.zeros(4), 0.1)
        (array([ 0.     , -0.04905,  0.     ]), array([ 0.   , -0.981,  0.   ]))
        """
        from taut.dynamics._kernels import GIMBAL_LOCK, OK, rk4_steps
        from taut.dynamics._tree import SINGULAR_INERTIA

        if self.sag is not None:
            return self._sagging_step(self.sag, q, qd, tensions, dt, wrench)
        b = self.buffers
        try:
            b["q"][0], b["qd"][0], b["u"][0] = q, qd, tensions
            b["w"][0] = 0.0 if wrench is None else wrench
            h = float(dt)
        except (TypeError, ValueError):
            raise TautError(
                f"{self.robot.name}: q, qd and wrench must be {b['q'].shape[1]} numbers each, tensions "
                f"{b['u'].shape[1]} and dt a number"
            ) from None
        ip, fp, cab = self.kernels.args
        rk4_steps(ip, fp, cab, False, b["q"], b["qd"], b["u"], b["w"], h, b["q_next"], b["qd_next"], b["status"])
        status = b["status"][0]
        if status == GIMBAL_LOCK:
            raise SingularConfigurationError(
                f"{self.robot.name}: the step from {np.asarray(q).tolist()} reaches the gimbal lock"
            )
        if status == SINGULAR_INERTIA:
            raise SingularConfigurationError(
                f"{self.robot.name}: the step from {np.asarray(q).tolist()} reaches a singular mass matrix"
            )
        if status != OK:
            raise InfeasiblePoseError(
                f"{self.robot.name}: the step from {np.asarray(q).tolist()} reaches a zero-length cable"
            )
        return b["q_next"][0].copy(), b["qd_next"][0].copy()

    def _sagging_step(
        self,
        sag: SaggingCables,
        q: npt.ArrayLike,
        qd: npt.ArrayLike,
        tensions: npt.ArrayLike,
        dt: float,
        wrench: npt.ArrayLike | None,
    ) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`step` with the sagging cables' pull recomputed at every stage
        (:func:`taut.dynamics._forward.sagging_rk4`)."""
        from taut.dynamics._forward import sagging_rk4

        dof = self.robot.pose_size
        try:
            x0, v0 = (np.array(a, dtype=float).reshape(1, dof) for a in (q, qd))
            u = np.array(tensions, dtype=float).reshape(1, self.kernels.n)
            w = np.zeros((1, dof)) if wrench is None else np.array(wrench, dtype=float).reshape(1, dof)
            h = float(dt)
        except (TypeError, ValueError):
            raise TautError(
                f"{self.robot.name}: q, qd and wrench must be {dof} numbers each, tensions "
                f"{self.kernels.n} and dt a number"
            ) from None
        qn, vn = sagging_rk4(self.robot, self.kernels, sag, x0, v0, u, w, h, False)
        return qn[0], vn[0]


def loop_model(robot: Robot, *, method: str = "qp") -> LoopModel:
    """A robot prepared for :meth:`LoopModel.tensions` and :meth:`LoopModel.step`.

    Parameters
    ----------
    robot : Robot
    method : str, optional
        The distribution of :data:`taut.statics.METHODS` used where the compiled closed form
        gives up.

    Returns
    -------
    LoopModel

    Raises
    ------
    UnsupportedRobotError
        Robots the dynamics does not handle (without masses or inertias; sagging cables on
        a platform with jointed bodies).
    TautError
        An unknown method.

    References
    ----------
    .. [1] A. Pott, T. Bruckmann, L. Mikelsons, "Closed-form force distribution for parallel
       wire robots", Computational Kinematics, Springer, 2009. (docs/references.bib: pott2009)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.dynamics import loop_model
    >>> loop_model(example("planar-4cable"), method="lp").method
    'lp'
    """
    from taut.statics import METHODS, input_bounds

    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    sag = SaggingCables(robot) if robot.sagging_cables else None
    kernels = kernel_model(robot, actuators=True, sagging=True)
    dof, n = robot.pose_size, kernels.n
    rows = {"q": dof, "qd": dof, "qdd": dof, "w": dof, "u": n, "wrench": dof, "tau": n, "q_next": dof, "qd_next": dof}
    buffers: dict[str, np.ndarray] = {name: np.zeros((1, width)) for name, width in rows.items()}
    buffers["lo"], buffers["hi"] = input_bounds(robot, robot.tension_bounds)
    buffers["W"] = np.zeros((1, dof, n))
    buffers["status"] = np.zeros(1, np.int64)
    return LoopModel(robot, method, kernels, buffers, sag)
