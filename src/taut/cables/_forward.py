"""Static forward kinematics of robots with sagging cables: for given unstrained lengths,
a pose of equilibrium of the platform and its stability.

The unknown is the pose ``q``; the equations are the platform's balance ``Σ f_i(q) + w(q) = 0``,
where each sagging cable's force ``f_i`` follows from its elastic catenary through its chord
with the given unstrained length (Irvine's equations solved for ``H, V``:
:mod:`taut.cables._catenary`), and each straight elastic cable pulls ``EA (l − L0)/L0`` along
its chord (none when slack).  Newton's method with a central-difference Jacobian and
backtracking starts from the straight-cable forward kinematics (the lengths taken as
straight cable lengths, :func:`taut.kinematics.forward_kinematics`), then from the guesses
themselves; where it fails, a
continuation in the cables' weight (``λ w``, ``λ`` from small to 1, Kozak, Zhou & Wang 2006,
§V) follows the equilibrium from nearly straight cables.  Lengths without an equilibrium
found that way are an answer (``found`` false), not an error; the search is local, not
certified: other equilibria may exist.

The equilibrium is stable when the stiffness ``K = −diag(I, Eᵀ) ∂w_net/∂q`` (the Hessian of
the potential energy in the pose coordinates at equilibrium, ``E`` the orientation's rate
matrix) is positive definite (Carricato & Merlet 2013).

References
----------
.. [1] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
   non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §V.
   (docs/references.bib: kozak2006)
.. [2] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3.
   (docs/references.bib: irvine1981)
.. [3] M. Carricato, J.-P. Merlet, "Stability analysis of underconstrained cable-driven
   parallel robots", IEEE Transactions on Robotics 29(1), 2013.
   (docs/references.bib: carricato2013)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut._results import Result
from taut.cables import _catenary as K
from taut.errors import TautError, UnreachableLengthsError, UnsupportedRobotError
from taut.geometry import cross, rate_matrix
from taut.kinematics import as_poses, default_guess, forward_kinematics, inverse_kinematics
from taut.model import MAX_MAGNITUDE, Robot
from taut.statics import external_wrench

#: Newton iterations at each weight of the continuation.
MAX_FK_STEPS = 30
#: Relative residual of the balance (to the largest force) at which Newton stops.
FK_RTOL = 1e-10
#: Where Newton starts without a guess: the exits' centroid, lowered along gravity by these
#: fractions of the exits' largest extent.
GUESS_DEPTHS = (0.0, 0.25, 0.5)
#: How much shorter than an inextensible sagging cable its straight stand-in of the start is.
START_SHRINK = 1e-3
#: The weights ``λ`` of the continuation, when Newton from the straight-cable pose fails.
CONTINUATION = (0.02, 0.05, 0.1, 0.2, 0.35, 0.5, 0.7, 0.85, 1.0)


@dataclass(frozen=True)
class SaggingFKResult(Result):
    """A pose of equilibrium of a robot with sagging cables for given unstrained lengths
    (:func:`sagging_fk`).

    Attributes
    ----------
    found : bool
        An equilibrium was found (else the other fields are zeros, ``None`` in :meth:`as_dict`).
    pose : ndarray, shape (pose_size,)
        The equilibrium pose.
    stable : bool
        The stiffness matrix is positive definite there.
    stiffness_eigenvalues : ndarray, shape (pose_size,)
        Eigenvalues of the symmetric part of the stiffness matrix [N/m, N, N m], ascending.
    platform_tensions, exit_tensions : ndarray, shape (n,)
        Tensions at the platform end and at the exit [N].
    sag : ndarray, shape (n,)
        The largest distance of each cable from its chord [m].
    within_bounds : bool
        Both ends of every cable are within its tension bounds.
    residual : float
        The largest component of the unbalanced wrench [N, N m].
    steps : int
        Newton iterations in all.

    Examples
    --------
    >>> from taut.model import example
    >>> robot = example("cogiro-sagging")
    >>> from taut.cables import sagging_ik
    >>> ik = sagging_ik(robot, [0.5, 0.2, 2.0, 0.0, 0.0, 0.0], method="qp")
    >>> fk = sagging_fk(robot, ik.unstrained_lengths)
    >>> fk.found, fk.stable, fk.pose.round(6) + 0.0
    (True, True, array([0.5, 0.2, 2. , 0. , 0. , 0. ]))
    """

    found: bool
    pose: np.ndarray
    stable: bool
    stiffness_eigenvalues: np.ndarray
    platform_tensions: np.ndarray
    exit_tensions: np.ndarray
    sag: np.ndarray
    within_bounds: bool
    residual: float
    steps: int

    def as_dict(self) -> dict[str, Any]:
        """The fields in plain JSON types, ``None`` for the pose and cable values when no
        equilibrium was found.

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        d = super().as_dict()
        if not self.found:
            for name in ("pose", "stiffness_eigenvalues", "platform_tensions", "exit_tensions", "sag", "residual"):
                d[name] = None
        return d


class _Balance:
    """The unbalanced wrench on the platform at a pose, for given unstrained lengths and the
    cables' weight scaled by ``λ``."""

    def __init__(self, robot: Robot, L0: np.ndarray, wrench: np.ndarray | None) -> None:
        self.robot, self.L0, self.wrench = robot, L0, wrench
        self.up = -robot.gravity / np.linalg.norm(robot.gravity)
        self.heavy = robot.cable_weights > 0
        self.ea = robot.axial_stiffness

    def __call__(self, q: np.ndarray, lam: float) -> tuple[np.ndarray, dict[str, np.ndarray]] | None:
        """``(net wrench, cable values)``, or None where a cable has no catenary or no length."""
        robot, d = self.robot, self.robot.dimension
        try:
            ik = inverse_kinematics(robot, q)
        except TautError:
            return None
        c = robot.exits - ik.anchors
        rise = c @ self.up
        hvec = c - rise[:, None] * self.up
        span = np.linalg.norm(hvec, axis=1)
        w = lam * robot.cable_weights
        heavy = self.heavy & (w > 0)
        forces = np.zeros((robot.n_cables, d))
        t0 = np.zeros(robot.n_cables)
        t1 = np.zeros(robot.n_cables)
        sag = np.zeros(robot.n_cables)
        if heavy.any():
            i = np.flatnonzero(heavy)
            chord = ik.lengths[i]
            if np.any(span[i] <= 1e-9 * chord) or np.any(np.isinf(self.ea[i]) & (self.L0[i] <= chord)):
                return None
            with np.errstate(all="ignore"):
                H, V, ok = K.solve_forward(span[i], rise[i], self.L0[i], w[i], self.ea[i])
            if not ok.all():
                return None
            forces[i] = H[:, None] * hvec[i] / span[i][:, None] + V[:, None] * self.up
            t0[i], t1[i] = np.hypot(H, V), np.hypot(H, V + w[i] * self.L0[i])
            sag[i] = K.largest_sag(span[i], rise[i], H, V, self.L0[i], w[i], self.ea[i])
        j = np.flatnonzero(~heavy)
        if j.size:
            ea = np.where(np.isinf(self.ea[j]), 0.0, self.ea[j])
            tau = np.maximum(ea * (ik.lengths[j] - self.L0[j]) / self.L0[j], 0.0)
            forces[j] = tau[:, None] * ik.directions[j]
            t0[j] = t1[j] = tau
        ext = external_wrench(robot, q) if self.wrench is None else self.wrench
        net = np.array(ext, dtype=float)
        net[:d] += forces.sum(axis=0)
        if not robot.is_point_mass:
            net[d:] += np.sum(cross(ik.anchors - q[:d], forces), axis=0)
        return net, {"t0": t0, "t1": t1, "sag": sag}


def _jacobian(balance: _Balance, q: np.ndarray, lam: float, scale: float) -> np.ndarray | None:
    """Central differences of the net wrench over the pose coordinates."""
    m = q.size
    J = np.empty((m, m))
    for k in range(m):
        h = 1e-6 * (scale if k < balance.robot.dimension else 1.0)
        up, down = q.copy(), q.copy()
        up[k] += h
        down[k] -= h
        a, b = balance(up, lam), balance(down, lam)
        if a is None or b is None:
            return None
        J[:, k] = (a[0] - b[0]) / (2 * h)
    return J


def _stiffness(balance: _Balance, q: np.ndarray, scale: float) -> tuple[np.ndarray, bool] | None:
    """The eigenvalues of the symmetric part of ``K = −diag(I, Eᵀ) ∂w_net/∂q`` at an
    equilibrium ``q``, ascending, and whether they are all positive (stable)."""
    J = _jacobian(balance, q, 1.0, scale)
    if J is None:
        return None
    robot = balance.robot
    G = np.eye(q.size)
    if not robot.is_point_mass and robot.dimension == 3:
        G[3:, 3:] = rate_matrix(q[3:], robot.orientation).T
    K = -G @ J
    eig = np.linalg.eigvalsh((K + K.T) / 2)
    return eig, bool(eig.min() > 0)


def _newton(balance: _Balance, q: np.ndarray, lam: float, scale: float, force: float) -> tuple[np.ndarray, bool, int]:
    """Damped Newton on the net wrench at weight ``λ``: ``(pose, converged, iterations)``."""
    state = balance(q, lam)
    if state is None:
        return q, False, 0
    r = state[0]
    for it in range(1, MAX_FK_STEPS + 1):
        if np.abs(r).max() <= FK_RTOL * force:
            return q, True, it - 1
        J = _jacobian(balance, q, lam, scale)
        if J is None:
            return q, False, it
        dq = np.linalg.lstsq(J, -r, rcond=None)[0]
        norm = np.linalg.norm(dq[: balance.robot.dimension])
        if norm > 0.1 * scale:  # a trust region: at most a tenth of the robot's size per step
            dq *= 0.1 * scale / norm
        step = 1.0
        while step > 1e-6:
            trial = balance(q + step * dq, lam)
            if trial is not None and np.linalg.norm(trial[0]) < np.linalg.norm(r):
                q, r = q + step * dq, trial[0]
                break
            step /= 2
        else:
            return q, False, it
    return q, bool(np.abs(r).max() <= FK_RTOL * force), MAX_FK_STEPS


def _refuse_unreachable(robot: Robot, L0: np.ndarray) -> None:
    """Raise :class:`UnreachableLengthsError` where two inextensible sagging cables ``i, j``
    cannot both be longer than their chords at any pose: ``‖a_i − a_j‖ ≥ L0_i + L0_j +
    ‖r_i − r_j‖`` (the triangle inequality through the anchors, ``‖r_i − r_j‖`` apart on the
    rigid platform); the pair that misses by most is named."""
    rigid = np.flatnonzero(np.isinf(robot.axial_stiffness) & (robot.cable_weights > 0))
    if rigid.size < 2:
        return
    exits, anchors = robot.exits[rigid], robot.anchors[rigid]
    apart = np.linalg.norm(exits[:, None] - exits[None], axis=-1)
    arms = np.linalg.norm(anchors[:, None] - anchors[None], axis=-1)
    gap = apart - (L0[rigid][:, None] + L0[rigid][None]) - arms
    i, j = np.unravel_index(int(np.argmax(gap)), gap.shape)
    if gap[i, j] >= 0:
        a, b = sorted((int(rigid[i]), int(rigid[j])))
        raise UnreachableLengthsError(
            f"{robot.name}: inextensible cables {a + 1} and {b + 1} of unstrained lengths {L0[a]:g} m and "
            f"{L0[b]:g} m cannot span their exits {apart[i, j]:.4g} m apart with their anchors {arms[i, j]:.4g} m "
            "apart: no pose fits the lengths (a cable would be shorter than its chord)"
        )


def sagging_fk(
    robot: Robot,
    unstrained_lengths: npt.ArrayLike,
    *,
    guess: npt.ArrayLike | None = None,
    wrench: npt.ArrayLike | None = None,
) -> SaggingFKResult:
    """A pose of equilibrium for given unstrained cable lengths, sagging cables as elastic
    catenaries, and its stability (module docstring).

    Parameters
    ----------
    robot : Robot
        A robot without jointed bodies whose straight cables (if any) are elastic.
    unstrained_lengths : array_like, shape (n,)
        ``L0`` of every cable [m], positive.
    guess : array_like, shape (pose_size,), optional
        Where the straight-cable forward kinematics starts; default
        :func:`taut.kinematics.default_guess` and, failing that, below it
        (:data:`GUESS_DEPTHS`).
    wrench : array_like, shape (m,), optional
        A constant external wrench on the platform; default the robot's own at each pose.

    Returns
    -------
    SaggingFKResult
        ``found`` false when no equilibrium was found: an answer, not an error.

    Raises
    ------
    TautError
        Lengths of the wrong number, not finite or not positive; a bad guess or wrench.
    UnsupportedRobotError
        A platform with jointed bodies, a straight inextensible cable (its tension is not a
        function of the pose), or no sagging cable.
    UnreachableLengthsError
        Lengths that no pose fits: two inextensible sagging cables whose lengths and the
        distance of their anchors on the platform do not span the distance of their exits,
        so that one of them would be shorter than its chord (a triangle inequality).

    References
    ----------
    .. [1] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
       non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §V.
       (docs/references.bib: kozak2006)

    Examples
    --------
    Inextensible cables of 8.5 m reach across the frame pairwise, but no pose leaves every one
    longer than its chord: no equilibrium, an answer; 5 m ones do not even reach pairwise,
    lengths no pose fits:

    >>> from taut.model import example
    >>> robot = example("cogiro-sagging")
    >>> rigid = robot.model_copy(update={"cables": tuple(c.model_copy(update={"stiffness": None}) for c in robot.cables)})
    >>> sagging_fk(rigid, [8.5] * 8).found
    False
    >>> sagging_fk(rigid, [5.0] * 8)
    Traceback (most recent call last):
    ...
    taut.errors.UnreachableLengthsError: CoGiRo with sagging cables: inextensible cables 3 and 8 of unstrained lengths 5 m and 5 m cannot span their exits 17.88 m apart with their anchors 1.001 m apart: no pose fits the lengths (a cable would be shorter than its chord)
    """
    if robot.n_joints:
        raise UnsupportedRobotError(f"{robot.name}: the sagging-cable statics handle platforms without joints")
    if not robot.sagging_cables:
        raise UnsupportedRobotError(f"{robot.name}: no sagging cables (cables[].weight)")
    rigid = [i + 1 for i, c in enumerate(robot.cables) if not c.weight and c.stiffness is None]
    if rigid:
        raise UnsupportedRobotError(
            f"{robot.name}: cables {rigid} are straight and inextensible: the forward statics with sagging "
            "cables needs their stiffness"
        )
    L0 = as_array(unstrained_lengths, "unstrained_lengths", shape=(robot.n_cables,))
    if np.any(L0 <= 0) or np.any(L0 > MAX_MAGNITUDE):
        raise TautError(f"unstrained_lengths: expected lengths in (0, {MAX_MAGNITUDE:g}] m, got {L0.tolist()}")
    _refuse_unreachable(robot, L0)
    ext = None if wrench is None else as_array(wrench, "wrench", shape=(robot.wrench_dim,))
    if guess is None:
        # the centroid of the exits, and below it: a suspended robot hangs under its exits
        depth = float(np.ptp(robot.exits, axis=0).max())
        down = robot.gravity / np.linalg.norm(robot.gravity)
        guesses = [default_guess(robot) for _ in GUESS_DEPTHS]
        for g, k in zip(guesses, GUESS_DEPTHS):
            g[: robot.dimension] += k * depth * down
    else:
        guesses = [as_poses(robot, guess)[0][0]]
    balance = _Balance(robot, L0, ext)
    scale = float(np.ptp(robot.exits, axis=0).max()) or 1.0
    # an inextensible sagging cable reaches no farther than its length: the straight cables of
    # the start are a little shorter than it, so that its catenary exists there
    straight = np.where(np.isinf(robot.axial_stiffness) & (robot.cable_weights > 0), L0 * (1 - START_SHRINK), L0)
    starts = []
    for g in guesses:
        try:
            starts.append(forward_kinematics(robot, straight, guess=g, tol=MAX_MAGNITUDE).pose)
        except TautError:
            starts.append(g)  # fewer cables than pose coordinates: Newton starts from the guess itself
    force = max(float(np.abs(external_wrench(robot, starts[0]) if ext is None else ext).max()), 1.0)
    # from each straight-cable pose, then from the guesses themselves (where elastic cables are
    # stretched, the straight pose at their unstrained lengths leaves them without tension)
    steps, ok, found = 0, False, None
    # a given guess first, then the straight-cable poses, then the default guesses themselves
    order = [*starts, *guesses] if guess is None else [*guesses, *starts]
    for start in order:
        q, ok, k = _newton(balance, start.copy(), 1.0, scale, force)
        steps += k
        stiff = _stiffness(balance, q, scale) if ok else None
        if stiff is not None and stiff[1]:
            break
        found = q if ok and found is None else found
    else:
        # no stable equilibrium: the first one found, unstable
        ok, q = found is not None, q if found is None else found
    if not ok:
        residuals = [balance(q, 1.0) for q in starts]
        q = starts[int(np.argmin([np.inf if v is None else float(np.linalg.norm(v[0])) for v in residuals]))].copy()
        for lam in CONTINUATION:
            q, ok, k = _newton(balance, q, lam, scale, force)
            steps += k
            if not ok:
                break
    n, m = robot.n_cables, robot.pose_size
    state = balance(q, 1.0) if ok else None
    stiff = _stiffness(balance, q, scale) if state is not None else None
    if state is None or stiff is None:
        z = np.zeros(n)
        return SaggingFKResult(False, np.zeros(m), False, np.zeros(m), z, z, z, False, 0.0, steps)
    eig, stable = stiff
    values = state[1]
    lo, hi = robot.tension_bounds
    slack = 1e-9 * max(float(values["t1"].max()), 1.0)
    within = bool(np.all((values["t0"] >= lo - slack) & (values["t1"] >= lo - slack)))
    within &= bool(np.all((values["t0"] <= hi + slack) & (values["t1"] <= hi + slack)))
    return SaggingFKResult(
        True,
        q,
        stable,
        eig,
        values["t0"],
        values["t1"],
        values["sag"],
        within,
        float(np.abs(state[0]).max()),
        steps,
    )
