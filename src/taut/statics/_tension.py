"""Tension distribution: cable tensions that hold the platform in equilibrium.

Given the structure matrix ``W`` (``m × n``) and the external wrench ``w`` at a pose, find
tensions ``τ`` with

    ``W τ + w = 0``,  ``τ_min ≤ τ ≤ τ_max``

(Rushton 2022 [1]_, §2.1.2, Eqs. 2.11 and 2.13; for ``n = m`` the source's
Eq. 2.12 must read ``τ = −W⁻¹ w_ext``: it drops the sign).  With ``n > m`` cables the
solutions form a polytope and a method picks one of them:

=========================  ===========================================================
``lp``                     minimum sum of tensions, a linear program (HiGHS)
``qp``                     minimum 2-norm, a quadratic program (active set from the
                           ``lp`` vertex; Hassan and Khajepour 2008 [2]_)
``inf``                    minimum ∞-norm, ``min t`` s.t. ``τ ≤ t`` (Hussein et al. 2021
                           [3]_)
``closed-form``            Pott, Bruckmann, Mikelsons 2009 [4]_
``improved-closed-form``   Pott 2014 [5]_
``barycentric``            centroid of the vertices of the polytope of feasible
                           tensions (Mikelsons, Bruckmann, Hiller, Schramm 2008 [6]_)
=========================  ===========================================================

``lp``, ``qp``, ``inf`` and ``barycentric`` are *exact*: they find a solution whenever
one exists and report ``"infeasible"`` when none does.  The two closed forms are fast
and sound but may give up (``"not-found"``) although the problem is feasible.

Every candidate is verified before it is reported (:func:`_verify`): it is clipped into
the bounds (only if it violates them by at most ``REPAIR_RTOL``, i.e. solver round-off),
its equilibrium residual is removed by a minimum-norm correction of the cables that are
strictly inside their bounds, and it is accepted only if ``‖W τ + w‖∞ ≤ EQUILIBRIUM_RTOL ×
max(‖w‖∞, maxᵢⱼ |Wᵢⱼ| · ‖τ‖∞)`` with the bounds holding exactly.  ``feasible`` is the result
of that check, so ``feasible ⇒`` the tensions truly balance the wrench whatever the method.

A method is one function ``f(W, w, tmin, tmax) -> (tensions, infeasible)`` over a batch
(``W (N, m, n)``, ``w (N, m)``, bounds ``(N, n)``) returning candidate tensions ``(N, n)``
(NaN where it has none) and a ``(N,)`` flag "proved infeasible" (to the tolerances above);
the status is ``"optimal"`` where the candidate passes verification, else ``"infeasible"``
where the flag is set, else ``"not-found"``.  Adding a method is adding such a function
and its entry in :data:`METHODS`.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.2, Eqs. 2.11–2.13. (docs/references.bib: rushton2022)
.. [2] M. Hassan, A. Khajepour, "Optimization of actuator forces in cable-based parallel
   manipulators using convex analysis", IEEE Transactions on Robotics 24(3), 2008.
   (docs/references.bib: hassan2008)
.. [3] H. Hussein, J. Cavalcanti Santos, J.-B. Izard, M. Gouttefarde, "Smallest maximum cable
   tension determination for cable-driven parallel robots", IEEE Transactions on Robotics, 2021.
   (docs/references.bib: hussein2021)
.. [4] A. Pott, T. Bruckmann, L. Mikelsons, "Closed-form force distribution for parallel wire
   robots", Computational Kinematics, Springer, 2009. (docs/references.bib: pott2009)
.. [5] A. Pott, "An improved force distribution algorithm for over-constrained cable-driven
   parallel robots", Computational Kinematics, Springer, 2014. (docs/references.bib: pott2014)
.. [6] L. Mikelsons, T. Bruckmann, M. Hiller, D. Schramm, "A real-time capable force calculation
   algorithm for redundant tendon-based parallel manipulators", IEEE ICRA, 2008.
   (docs/references.bib: mikelsons2008)
.. [7] M. Gouttefarde, J. Lamaury, C. Reichert, T. Bruckmann, "A Versatile Tension Distribution
   Algorithm for n-DOF Parallel Robots Driven by n+2 Cables", IEEE Transactions on Robotics
   31(6), 2015. (docs/references.bib: gouttefarde2015)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import highspy
import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.errors import TautError
from taut.statics._highs import QuietHighs
from taut.statics._wrench import bounds_pair

#: Relative equilibrium tolerance of a reported solution.
EQUILIBRIUM_RTOL = 1e-9
#: Largest relative bound violation or residual of a candidate that verification repairs.
REPAIR_RTOL = 1e-6
#: Relative size below which a feasible polytope counts as flat (no interior).
FLAT_RTOL = 1e-9

_EPS = np.finfo(float).eps


@dataclass(frozen=True)
class TensionResult(Result):
    """Tensions at ``N`` poses of a robot with ``n`` cables (a frozen result, read-only arrays).

    For a single pose the fields have no batch axis: ``tensions (n,)``, ``feasible`` a
    ``bool`` and ``status`` a ``str``.

    Attributes
    ----------
    tensions : ndarray, shape (N, n) or (n,)
        Cable tensions [N]; zeros where no solution was found (never NaN; ``None`` in
        :meth:`as_dict`).
    feasible : ndarray of bool, shape (N,), or bool
        The tensions balance the wrench (``‖W τ + w‖∞`` within :data:`EQUILIBRIUM_RTOL` of
        its scale) and lie within the bounds.
    status : ndarray of str, shape (N,), or str
        ``"optimal"`` (feasible), ``"infeasible"`` (no tensions within the bounds balance the
        wrench, proved) or ``"not-found"`` (a closed-form method gave up).
    method : str
        The method of :data:`METHODS` that computed them.
    actuator_forces : ndarray, shape (N, n_actuators) or (n_actuators,)
        The forces [N] or torques [N m] of a jointed platform's joint actuators, in the order
        of :attr:`taut.model.Robot.actuated_joints` (empty without them; zeros where no
        solution was found, ``None`` in :meth:`as_dict`).

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.statics import distribute_tensions
    >>> res = distribute_tensions(example("planar-4cable"), [0.0, 0.0, 0.0])
    >>> res.status, bool(res.feasible)
    ('optimal', True)
    >>> res.as_dict()["tensions"]
    [1.0, 1.0, 7.75..., 7.75...]
    """

    tensions: np.ndarray  #: ``(N, n)``; zeros where no solution was found (never NaN)
    feasible: np.ndarray | bool  #: ``(N,)`` bool: equilibrium (to 1e-9 relative) and bounds hold
    status: np.ndarray | str  #: ``(N,)`` str: ``"optimal"``, ``"infeasible"`` (proved) or ``"not-found"``
    method: str
    actuator_forces: np.ndarray  #: ``(N, n_actuators)``; zeros where no solution was found

    def as_dict(self) -> dict[str, Any]:
        """The fields in plain JSON types, with ``tensions`` ``None`` (for one pose) or a row
        ``None`` (for several) where no solution was found: zeros would read as tensions.

        Returns
        -------
        dict
            ``tensions``, ``feasible``, ``status``, ``method`` and ``actuator_forces``;
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        d = super().as_dict()
        for key in ("tensions", "actuator_forces"):
            if isinstance(self.feasible, np.ndarray):
                d[key] = [row if ok else None for row, ok in zip(d[key], self.feasible.tolist())]
            elif not self.feasible:
                d[key] = None
        return d


# ---- shared numerics ---------------------------------------------------------------------


def _svd_pinv(A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Batched pseudo-inverse and numerical rank of ``A (K, m, n)``."""
    U, S, Vt = np.linalg.svd(A, full_matrices=False)
    tol = S.max(axis=-1, initial=0.0) * max(A.shape[-2:]) * _EPS
    keep = S > tol[:, None]
    Sinv = np.divide(1.0, S, out=np.zeros_like(S), where=keep)
    P = np.einsum("kji,kj,klj->kil", Vt, Sinv, U)
    return P, keep.sum(axis=-1)


def _eq_scale(W: np.ndarray, w: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """Scale of ``W τ + w`` per pose: ``max(‖w‖∞, maxᵢⱼ |Wᵢⱼ| · ‖τ‖∞)``."""
    terms = np.abs(W).max(axis=(-2, -1), initial=0.0) * np.abs(tau).max(axis=-1, initial=0.0)
    return np.maximum(terms, np.abs(w).max(axis=-1, initial=0.0))


def _residual(W: np.ndarray, w: np.ndarray, tau: np.ndarray) -> np.ndarray:
    return np.abs(np.einsum("kij,kj->ki", W, tau) + w).max(axis=-1, initial=0.0)


def _tension_scale(tau: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> np.ndarray:
    fin = np.where(np.isfinite(tmax), tmax, 0.0)
    return np.maximum.reduce([np.abs(tau).max(-1, initial=0.0), tmin.max(-1, initial=0.0), fin.max(-1, initial=0.0)])


def _violation(tau: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> np.ndarray:
    """Largest bound violation per pose (≤ 0 when within bounds)."""
    return np.maximum(tmin - tau, tau - tmax).max(axis=-1, initial=-np.inf)


def _verify(
    W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, tau: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Repair round-off in candidate tensions and check them: ``(tensions, feasible)``.

    Candidates that are not finite, violate a bound by more than ``REPAIR_RTOL`` times the
    tension scale or have a residual larger than ``REPAIR_RTOL`` times the wrench scale
    (``‖W‖`` × tension scale) are rejected.  The others are clipped into the bounds and
    their residual is removed by the minimum-norm change of the cables strictly inside
    their bounds (alternating with all cables, at most four rounds)."""
    tau = np.array(tau, dtype=float)
    ok = np.isfinite(tau).all(axis=-1)
    tau[~ok] = 0.0
    tscale = _tension_scale(tau, tmin, tmax)
    ok &= _violation(tau, tmin, tmax) <= REPAIR_RTOL * tscale
    wscale = np.maximum(_eq_scale(W, w, tau), np.abs(W).max(axis=(1, 2), initial=0.0) * tscale)
    ok &= _residual(W, w, tau) <= REPAIR_RTOL * wscale
    tau = np.clip(tau, tmin, tmax)
    for round_ in range(4):
        eq = _residual(W, w, tau) <= EQUILIBRIUM_RTOL * _eq_scale(W, w, tau)
        todo = np.flatnonzero(ok & ~eq)
        if todo.size == 0:
            break
        t = tau[todo]
        free = (t > tmin[todo]) & (t < tmax[todo]) if round_ % 2 == 0 else np.ones_like(t, dtype=bool)
        r = np.einsum("kij,kj->ki", W[todo], t) + w[todo]
        P, _ = _svd_pinv(W[todo] * free[:, None, :])
        tau[todo] = np.clip(t - np.einsum("kji,ki->kj", P, r), tmin[todo], tmax[todo])
    ok &= _residual(W, w, tau) <= EQUILIBRIUM_RTOL * _eq_scale(W, w, tau)
    tau[~ok] = 0.0
    return tau, ok


# ---- HiGHS programs (lp, qp, inf) --------------------------------------------------------

_S = highspy.HighsModelStatus


def _new_highs() -> highspy.Highs:
    h = QuietHighs()
    h.setOptionValue("presolve", "off")
    h.setOptionValue("primal_feasibility_tolerance", 1e-9)  # programs are scaled to order one
    return h


def _pass_lp(
    h: highspy.Highs,
    cost: np.ndarray,
    col_lo: np.ndarray,
    col_hi: np.ndarray,
    A: np.ndarray,
    row_lo: np.ndarray,
    row_hi: np.ndarray,
) -> None:
    """Load ``min costᵀx`` s.t. ``row_lo ≤ A x ≤ row_hi``, ``col_lo ≤ x ≤ col_hi`` (A dense)."""
    nrow, ncol = A.shape
    lp = highspy.HighsLp()
    lp.num_col_, lp.num_row_ = ncol, nrow
    lp.col_cost_ = np.asarray(cost, float)
    lp.col_lower_, lp.col_upper_ = np.asarray(col_lo, float), np.asarray(col_hi, float)
    lp.row_lower_, lp.row_upper_ = np.asarray(row_lo, float), np.asarray(row_hi, float)
    lp.a_matrix_.format_ = highspy.MatrixFormat.kRowwise
    lp.a_matrix_.num_col_, lp.a_matrix_.num_row_ = ncol, nrow
    lp.a_matrix_.start_ = np.arange(0, nrow * ncol + 1, max(ncol, 1), dtype=np.int32)[: nrow + 1]
    lp.a_matrix_.index_ = np.tile(np.arange(ncol, dtype=np.int32), nrow)
    lp.a_matrix_.value_ = np.ascontiguousarray(A, dtype=float).ravel()
    h.passModel(lp)


def _solve(h: highspy.Highs) -> tuple[str, np.ndarray]:
    """Run the loaded program: ``(status, solution)``, the solution empty unless ``"optimal"``."""
    h.run()
    st = h.getModelStatus()
    if st == _S.kOptimal:
        return "optimal", np.array(h.getSolution().col_value)
    if st in (_S.kInfeasible, _S.kUnboundedOrInfeasible):
        return "infeasible", np.zeros(0)
    return "not-found", np.zeros(0)


def _load_program(
    h: highspy.Highs, objective: str, W: np.ndarray, w: np.ndarray, lo: np.ndarray, hi: np.ndarray
) -> int:
    """Load the program of one pose into ``h``; returns the index of its first
    equilibrium row.  Variables ``x = [τ, t]`` (``t`` only for ``inf``); rows: ``τᵢ − t ≤ 0``
    (``inf``), then the equilibrium rows ``W τ = −w``."""
    m, n = W.shape
    extra = 1 if objective == "inf" else 0
    if objective == "inf":
        cost = np.r_[np.zeros(n), 1.0]
        A0 = np.hstack([np.eye(n), -np.ones((n, 1))])
        lo0, hi0 = np.full(n, -np.inf), np.zeros(n)
    else:
        cost = np.ones(n)
        A0, lo0, hi0 = np.zeros((0, n)), np.zeros(0), np.zeros(0)
    A = np.vstack([A0, np.hstack([W, np.zeros((m, extra))])])
    _pass_lp(h, cost, np.r_[lo, np.zeros(extra)], np.r_[hi, np.full(extra, np.inf)], A, np.r_[lo0, -w], np.r_[hi0, -w])
    return A0.shape[0]


def _in_range(W: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Whether ``W τ = −w`` has a solution, ignoring bounds (least-squares residual within
    ``EQUILIBRIUM_RTOL``), per pose."""
    P, _ = _svd_pinv(W)
    t = -np.einsum("kji,ki->kj", P, w)
    return _residual(W, w, t) <= EQUILIBRIUM_RTOL * _eq_scale(W, w, t)


def _program_scaling(
    W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Scale each program to order one, because HiGHS's tolerances are absolute
    and it drops matrix entries below 1e-9: every equilibrium row is divided by its
    largest entry (forces and moments have different units) and the tensions by a per-pose
    scale ``s``.  Returns the scaled ``W``, ``w`` and ``s (N,)``."""
    rows = np.abs(W).max(axis=-1, keepdims=True)
    rows = np.where(rows > 0, rows, 1.0)
    W, w = W / rows, w / rows[..., 0]
    fin = np.where(np.isfinite(tmax), tmax, 0.0)
    s = np.maximum.reduce([tmin.max(-1, initial=0.0), fin.max(-1, initial=0.0), np.abs(w).max(-1, initial=0.0)])
    return W, w, np.where(s > 0, s, 1.0)


def _program(
    W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, objective: str
) -> tuple[np.ndarray, np.ndarray]:
    """Solve one HiGHS program per pose, reusing one model whose equilibrium rows are
    replaced pose by pose (the previous basis warm-starts the next pose).  Each pose is
    solved scaled (:func:`_program_scaling`)."""
    N, m, n = W.shape
    ncol = n + (objective == "inf")
    starts = np.arange(0, m * ncol, ncol, dtype=np.int32)
    index = np.tile(np.arange(ncol, dtype=np.int32), m)
    cols = np.arange(n, dtype=np.int32)
    infeasible = ~_in_range(W, w)
    W, w, scales = _program_scaling(W, w, tmin, tmax)
    tau = np.full((N, n), np.nan)
    h = None
    for k in np.flatnonzero(~infeasible):
        sk = scales[k]
        lo, hi, wk = tmin[k] / sk, tmax[k] / sk, w[k] / sk
        if h is None:
            h = _new_highs()
            first = _load_program(h, objective, W[k], wk, lo, hi)
            rows = np.arange(first, first + m, dtype=np.int32)
        else:
            h.deleteRows(m, rows)
            Weq = np.hstack([W[k], np.zeros((m, ncol - n))])
            h.addRows(m, -wk, -wk, m * ncol, starts, index, Weq.ravel())
            h.changeColsBounds(n, cols, lo, hi)
        status, x = _solve(h)
        if status == "not-found":  # a solver failure is no verdict: "not-found"; start afresh
            h = None
        if status == "optimal":
            tau[k] = x[:n] * sk
        infeasible[k] = status == "infeasible"
    return tau, infeasible


def _lp(W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimum sum of tensions ``min Σ τᵢ`` — a linear program solved by HiGHS (dual
    simplex, warm-started from the previous pose); Rushton (2022), §2.1.2 and §6 (the LP
    tension distribution used for the experiments)."""
    return _program(W, w, tmin, tmax, "lp")


def _null_basis(A: np.ndarray) -> np.ndarray:
    """Orthonormal basis ``(k, d)`` of the null space of ``A (m, k)`` (SVD, numerical rank)."""
    if A.shape[1] == 0:
        return np.zeros((0, 0))
    _, S, Vt = np.linalg.svd(A, full_matrices=True)
    rank = int((S > S.max(initial=0.0) * max(A.shape) * _EPS).sum())
    return Vt[rank:].T


def _min_norm_active_set(W: np.ndarray, w: np.ndarray, lo: np.ndarray, hi: np.ndarray, tau: np.ndarray) -> np.ndarray:
    """``argmin ‖τ‖`` s.t. ``W τ + w = 0``, ``lo ≤ τ ≤ hi`` from a feasible ``tau``: the
    primal active-set method for convex QPs (Nocedal and Wright, *Numerical Optimization*,
    2nd ed., Alg. 16.3) with the identity Hessian.  The working set starts empty and
    grows one blocking bound at a time, so it stays linearly independent and the bound
    multipliers are unique.  Cables with ``lo = hi`` are eliminated first."""
    n = tau.size
    fixed = lo >= hi
    tau = np.where(fixed, lo, np.clip(tau, lo, hi))
    active = fixed.copy()
    side = np.zeros(n)  # +1 at a lower bound, −1 at an upper bound (working set)
    scale = max(float(_tension_scale(tau[None], lo[None], hi[None])[0]), 1e-300)
    for _ in range(10 * n + 10):
        F = ~active
        Z = _null_basis(W[:, F])
        p = np.zeros(n)
        p[F] = -Z @ (Z.T @ tau[F])
        if np.abs(p).max(initial=0.0) <= 1e-13 * scale:
            # stationarity τ + Wᵀν = g with g = 0 on the free cables
            nu = -np.linalg.lstsq(W[:, F].T, tau[F], rcond=None)[0] if F.any() else np.zeros(W.shape[0])
            g = (tau + W.T @ nu) * side
            g[fixed | ~active] = np.inf
            j = int(np.argmin(g))
            if g[j] >= -1e-11 * scale:
                return tau
            active[j], side[j] = False, 0.0
            continue
        with np.errstate(divide="ignore", invalid="ignore"):
            to_lo = np.where(F & (p < 0), (lo - tau) / p, np.inf)
            to_hi = np.where(F & (p > 0), (hi - tau) / p, np.inf)
        steps = np.minimum(to_lo, to_hi)
        j = int(np.argmin(steps))
        alpha = max(min(1.0, steps[j]), 0.0)
        tau = tau + alpha * p
        if alpha < 1.0:
            at_lo = to_lo[j] <= to_hi[j]
            tau[j] = lo[j] if at_lo else hi[j]
            active[j], side[j] = True, (1.0 if at_lo else -1.0)
    return tau


def _qp(W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimum 2-norm ``min ½‖τ‖²`` (Hassan and Khajepour 2008, ref. [23] of Rushton 2022),
    a strictly convex QP: the ``lp`` program decides feasibility and gives a feasible
    vertex, from which :func:`_min_norm_active_set` descends to the exact minimiser.
    (HiGHS's own QP solver was tried and rejected: on some problems with tiny bounds it
    reports solve errors or false infeasibility.)"""
    tau, infeasible = _program(W, w, tmin, tmax, "lp")
    for k in np.flatnonzero(np.isfinite(tau).all(axis=-1)):
        tau[k] = _min_norm_active_set(W[k], w[k], tmin[k], tmax[k], tau[k])
    return tau, infeasible


def _inf(W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Minimum ∞-norm ``min t`` s.t. ``τᵢ ≤ t`` — a linear program solved by HiGHS
    (Hussein, Cavalcanti Santos, Izard, Gouttefarde 2021, ref. [24] of Rushton 2022).  Only
    the largest tension is minimised: the others are those of one optimal vertex."""
    return _program(W, w, tmin, tmax, "inf")


# ---- closed forms ------------------------------------------------------------------------


def _reference_tensions(tmin: np.ndarray, tmax: np.ndarray) -> np.ndarray:
    """``τm = (τ_min + τ_max)/2``; ``τ_min`` for a cable without upper bound."""
    fin = np.isfinite(tmax)
    return np.where(fin, (tmin + np.where(fin, tmax, 0.0)) / 2, tmin)


def _pott(
    W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray, iterations: int
) -> tuple[np.ndarray, np.ndarray]:
    """Pott's closed form, iterated: ``τ = τm − W⁺(w + W τm)``; while a tension violates
    its bounds and redundancy is left, fix the most violating cable at the bound it
    violates, remove its column and repeat.  Vectorised over poses."""
    N, m, n = W.shape
    tm = _reference_tensions(tmin, tmax)
    free = np.ones((N, n), dtype=bool)
    fixed = np.zeros((N, n))
    tau = np.full((N, n), np.nan)
    active = np.arange(N)
    for _ in range(iterations):
        if active.size == 0:
            break
        Wa, fa, lo, hi = W[active], free[active], tmin[active], tmax[active]
        t0 = np.where(fa, tm[active], fixed[active])
        r = np.einsum("kij,kj->ki", Wa, t0) + w[active]
        P, rank = _svd_pinv(Wa * fa[:, None, :])
        t = t0 - np.einsum("kji,ki->kj", P, r)
        eq = _residual(Wa, w[active], t) <= EQUILIBRIUM_RTOL * _eq_scale(Wa, w[active], t)
        viol = np.where(fa, np.maximum(lo - t, t - hi), -np.inf)
        worst = viol.max(axis=-1)
        within = worst <= EQUILIBRIUM_RTOL * _tension_scale(t, lo, hi)
        done = eq & within
        tau[active[done]] = t[done]
        go = eq & ~within & (fa.sum(axis=-1) > rank)
        k, j = active[go], viol[go].argmax(axis=-1)
        fixed[k, j] = np.where(t[go, j] < tmin[k, j], tmin[k, j], tmax[k, j])
        free[k, j] = False
        active = k
    return tau, np.zeros(N, dtype=bool)


def _closed_form(W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Closed-form force distribution of Pott, Bruckmann and Mikelsons (2009, ref. [27] of
    Rushton 2022): ``τ = τm − W⁺(w + W τm)`` with ``τm = (τ_min + τ_max)/2``, the tensions
    nearest to the middle of the bounds in the 2-norm, ignoring the bounds; accepted only
    if they satisfy them, else ``"not-found"``.  A cable without upper bound (``τ_max =
    ∞``) uses ``τm = τ_min``.  Batched pseudo-inverse over all poses."""
    return _pott(W, w, tmin, tmax, iterations=1)


def _improved_closed_form(
    W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Improved closed-form force distribution of Pott (2014, ref. [28] of Rushton 2022): the
    closed form of :func:`_closed_form`; while a tension violates its bounds and ``W`` of
    the remaining cables keeps redundancy (more cables than its rank), fix the cable with
    the largest violation at that bound, move its wrench to the right-hand side, drop its
    column and recompute.  Gives up (``"not-found"``) when no redundancy is left.  ``τm``
    as in :func:`_closed_form`.  Vectorised over poses, one round per removed cable."""
    return _pott(W, w, tmin, tmax, iterations=W.shape[2] + 1)


# ---- barycentric -------------------------------------------------------------------------


def _segment_centres(tp: np.ndarray, v: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Midpoints of ``{λ : lo ≤ tp + v λ ≤ hi}`` for ``K`` one-dimensional problems
    (``tp, v, lo, hi (K, n)``): ``(tensions (K, n), empty (K,))``."""
    scale = _tension_scale(tp, lo, hi)
    nz = np.abs(v) > 1e-12
    vs = np.where(nz, v, 1.0)
    a, b = (lo - tp) / vs, (hi - tp) / vs
    lower = np.where(nz, np.minimum(a, b), -np.inf).max(axis=-1)
    upper = np.where(nz, np.maximum(a, b), np.inf).min(axis=-1)
    slack = FLAT_RTOL * scale[:, None]
    fixed_ok = (nz | ((tp >= lo - slack) & (tp <= hi + slack))).all(axis=-1)
    empty = ~fixed_ok | (lower > upper + FLAT_RTOL * scale)
    # with finite bounds λ is bounded unless v = 0 (then λ is irrelevant: take 0)
    bounded = np.isfinite(lower) & np.isfinite(upper)
    lam = np.where(bounded, (np.where(bounded, lower, 0.0) + np.where(bounded, upper, 0.0)) / 2, 0.0)
    return tp + v * lam[:, None], empty


def _distinct(V: np.ndarray, tol: float) -> np.ndarray:
    """The points of ``V`` without near-duplicates (closer than ``tol``): Qhull reports a
    degenerate vertex, where more than ``r`` bounds are active, once per facet of the dual
    hull."""
    from scipy.spatial import cKDTree

    drop = {j for _, j in cKDTree(V).query_pairs(tol)}
    return V[[i for i in range(len(V)) if i not in drop]]


def _polytope_centre(
    h: highspy.Highs, tp: np.ndarray, Z: np.ndarray, lo: np.ndarray, hi: np.ndarray, depth: int = 0
) -> tuple[np.ndarray | None, bool]:
    """Centroid of the vertices of ``{tp + Z λ : lo ≤ tp + Z λ ≤ hi}`` (``Z (n, r)``
    orthonormal): ``(tensions (n,) or None, empty)``."""
    from scipy.spatial import HalfspaceIntersection, QhullError

    n, r = Z.shape
    scale = max(float(_tension_scale(tp[None], lo[None], hi[None])[0]), 1e-300)
    if r <= 1:
        v = Z[:, 0] if r else np.zeros(n)
        t, empty = _segment_centres(tp[None], v[None], lo[None], hi[None])
        return t[0], bool(empty[0])
    norms = np.linalg.norm(Z, axis=1)
    nz = norms > 1e-12
    if np.any((tp[~nz] < lo[~nz] - FLAT_RTOL * scale) | (tp[~nz] > hi[~nz] + FLAT_RTOL * scale)):
        return None, True
    # rows A λ ≤ b with unit normals: Z_i λ ≤ hi_i − tp_i and −Z_i λ ≤ tp_i − lo_i
    Zu = Z[nz] / norms[nz, None]
    A = np.vstack([Zu, -Zu])
    b = np.r_[(hi - tp)[nz], (tp - lo)[nz]] / np.r_[norms[nz], norms[nz]]
    # Chebyshev centre: max ρ s.t. A λ + ρ ≤ b (ρ free: its sign tells emptiness)
    ones = np.ones((A.shape[0], 1))
    _pass_lp(
        h,
        np.r_[np.zeros(r), -1.0],
        np.full(r + 1, -np.inf),
        np.full(r + 1, np.inf),
        np.hstack([A, ones]),
        np.full(A.shape[0], -np.inf),
        b / scale,
    )
    status, x = _solve(h)
    if status != "optimal":
        return None, False
    lam, rho = x[:r] * scale, x[r] * scale
    if rho < -FLAT_RTOL * scale:
        return None, True
    if rho <= FLAT_RTOL * scale:
        return _flat_centre(h, tp, Z, lo, hi, A, b, lam, scale, depth), False
    try:
        vertices = HalfspaceIntersection(np.hstack([A, -b[:, None]]), lam).intersections
    except (QhullError, ValueError):
        return tp + Z @ lam, False
    return tp + Z @ _distinct(vertices, FLAT_RTOL * scale).mean(axis=0), False


def _flat_centre(
    h: highspy.Highs,
    tp: np.ndarray,
    Z: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    A: np.ndarray,
    b: np.ndarray,
    lam0: np.ndarray,
    scale: float,
    depth: int,
) -> np.ndarray:
    """Centre of a polytope without interior: find its implicit equalities (the rows that
    no feasible point satisfies strictly: ``max Σ sᵢ`` s.t. ``A λ + s ≤ b``, ``0 ≤ sᵢ ≤
    scale``), restrict to their affine hull and take the centroid of the vertices there.
    Falls back to the Chebyshev centre when no implicit equality is found."""
    k, r = A.shape
    if depth < 4:
        _pass_lp(
            h,
            np.r_[np.zeros(r), -np.ones(k)],
            np.r_[np.full(r, -np.inf), np.zeros(k)],
            np.r_[np.full(r, np.inf), np.ones(k)],
            np.hstack([A, np.eye(k)]),
            np.full(k, -np.inf),
            b / scale,
        )
        status, x = _solve(h)
        if status == "optimal":
            x = x * scale
            tight = x[r:] <= FLAT_RTOL * scale
            if tight.any():
                lam = x[:r]
                _, s, vt = np.linalg.svd(A[tight])
                rank = int((s > s.max() * max(A.shape) * _EPS).sum())
                Z2 = vt[rank:].T
                t, empty = _polytope_centre(h, tp + Z @ lam, Z @ Z2, lo, hi, depth + 1)
                if t is not None:
                    return t
    return tp + Z @ lam0


def _barycentric(W: np.ndarray, w: np.ndarray, tmin: np.ndarray, tmax: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Barycentric tension distribution (Mikelsons, Bruckmann, Hiller, Schramm, "A
    real-time capable force calculation algorithm for redundant tendon-based parallel
    manipulators", ICRA 2008).  The solutions are ``τ = τp + Z λ`` with ``τp = −W⁺ w`` and
    ``Z`` an orthonormal basis of the null space of ``W`` (redundancy ``r = n − rank W``,
    from the SVD); the bounds cut out a polytope in ``λ``:

    - ``r = 0``: the unique solution, if within bounds;
    - ``r = 1``: the midpoint of the segment (vectorised over poses);
    - ``r ≥ 2``: a Chebyshev-centre LP (HiGHS) proves emptiness or gives an interior point,
      :class:`scipy.spatial.HalfspaceIntersection` the vertices, and the result is the mean
      of the distinct vertices (Qhull reports a degenerate vertex several times; copies
      closer than ``FLAT_RTOL`` × the tension scale are merged).  A polytope without
      interior (e.g. ``τ_min = τ_max`` for a cable) is reduced to its affine hull first.

    This is the vertex centroid of Mikelsons et al., not the centre of volume (the area
    centroid of Gouttefarde et al. 2015 (docs/references.bib: gouttefarde2015) for ``r = 2``): the vertex centroid may jump when a
    vertex appears, but its cost stays small as ``r`` grows (the volume centroid needs a
    triangulation whose cost explodes beyond ``r ≈ 6``).  The number of vertices still
    grows quickly with ``r``: this method is meant for small redundancy.

    Needs finite upper bounds (the polytope is unbounded otherwise): raises
    :class:`TautError` if a ``τ_max`` is infinite.  ``"infeasible"`` when ``w`` is not in
    the range of ``W`` or the polytope is empty."""
    N, m, n = W.shape
    if not np.isfinite(tmax).all():
        bad = int(np.argwhere(~np.isfinite(tmax))[0, -1])
        raise TautError(
            f"method 'barycentric' needs finite upper tension bounds (cable {bad + 1} has none): "
            "the polytope of feasible tensions is unbounded; use 'lp', 'qp' or 'inf'"
        )
    U, S, Vt = np.linalg.svd(W, full_matrices=True)
    tol = S.max(axis=-1, initial=0.0) * max(m, n) * _EPS
    keep = S > tol[:, None]
    rank = keep.sum(axis=-1)
    k = S.shape[-1]
    Sinv = np.divide(1.0, S, out=np.zeros_like(S), where=keep)
    tp = -np.einsum("kji,kj,klj,kl->ki", Vt[:, :k], Sinv, U[:, :, :k], w)
    infeasible = _residual(W, w, tp) > EQUILIBRIUM_RTOL * _eq_scale(W, w, tp)
    tau = np.full((N, n), np.nan)
    red = n - rank
    sel = np.flatnonzero(~infeasible & (red == 0))
    if sel.size:
        tau[sel] = tp[sel]
        lo, hi, t = tmin[sel], tmax[sel], tp[sel]
        infeasible[sel] = _violation(t, lo, hi) > EQUILIBRIUM_RTOL * _tension_scale(t, lo, hi)
    sel = np.flatnonzero(~infeasible & (red == 1))
    if sel.size:
        v = Vt[sel, rank[sel]]
        tau[sel], infeasible[sel] = _segment_centres(tp[sel], v, tmin[sel], tmax[sel])
    sel = np.flatnonzero(~infeasible & (red >= 2))
    if sel.size:
        h = _new_highs()
        for i in sel:
            t, empty = _polytope_centre(h, tp[i], Vt[i, rank[i] :].T, tmin[i], tmax[i])
            if t is not None:
                tau[i] = t
            infeasible[i] = empty
    return tau, infeasible


# ---- registry and entry points -----------------------------------------------------------

#: Tension distribution methods by name (the names are the ``--method`` values of the CLI).
METHODS: dict[str, Callable] = {
    "lp": _lp,
    "qp": _qp,
    "inf": _inf,
    "closed-form": _closed_form,
    "improved-closed-form": _improved_closed_form,
    "barycentric": _barycentric,
}


def _inputs(
    W: npt.ArrayLike, w: npt.ArrayLike, tmin: npt.ArrayLike, tmax: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, bool]:
    try:
        W = np.asarray(W, dtype=float)
        w = np.asarray(w, dtype=float)
        tmin = np.asarray(tmin, dtype=float)
        tmax = np.asarray(tmax, dtype=float)
    except (TypeError, ValueError) as e:
        raise TautError(f"structure matrix, wrench and tension bounds must be numbers ({e})") from None
    if W.ndim not in (2, 3) or 0 in W.shape[-2:]:
        raise TautError(f"structure matrix must have shape (m, n) or (N, m, n), got {W.shape}")
    m, n = W.shape[-2:]
    if w.ndim not in (1, 2) or w.shape[-1] != m:
        raise TautError(f"wrench must have shape ({m},) or (N, {m}) for a structure matrix of {m} rows, got {w.shape}")
    single = W.ndim == 2 and w.ndim == 1
    N = W.shape[0] if W.ndim == 3 else (w.shape[0] if w.ndim == 2 else 1)
    if W.ndim == 3 and w.ndim == 2 and w.shape[0] != N:
        raise TautError(f"{N} structure matrices but {w.shape[0]} wrenches")
    if not np.isfinite(W).all():
        raise TautError("structure matrix has non-finite entries")
    if not np.isfinite(w).all():
        raise TautError("wrench has non-finite entries")
    bounds = []
    for name, t in (("lower", tmin), ("upper", tmax)):
        try:
            bounds.append(np.broadcast_to(t, (N, n)).astype(float))
        except ValueError:
            raise TautError(f"{name} tension bounds must have shape ({n},) for {n} cables, got {t.shape}") from None
    lo, hi = bounds
    if np.isnan(lo).any() or np.isnan(hi).any():
        raise TautError("tension bounds must be numbers, got NaN")
    if not np.isfinite(lo).all() or (lo < 0).any():
        raise TautError("lower tension bounds must be finite and >= 0 (cables can only pull)")
    if (lo > hi).any():
        i = int(np.argwhere(lo > hi)[0, -1])
        raise TautError(f"tension bounds of cable {i + 1} are inverted: lower {lo.flat[i]:g} > upper {hi.flat[i]:g}")
    Wb = np.ascontiguousarray(np.broadcast_to(W, (N, m, n)))
    wb = np.ascontiguousarray(np.broadcast_to(w, (N, m)))
    return Wb, wb, lo, hi, single


def solve_tensions(
    W: npt.ArrayLike, wrench: npt.ArrayLike, *, tension_bounds: tuple[npt.ArrayLike, npt.ArrayLike], method: str = "lp"
) -> TensionResult:
    """Tensions ``τ`` with ``W τ + wrench = 0`` and ``tmin ≤ τ ≤ tmax`` at each pose.

    With more cables than the wrench has components the solutions form a polytope and
    ``method`` picks one of them (module docstring): ``"lp"`` the least sum, ``"qp"`` the
    least 2-norm, ``"inf"`` the least largest tension, ``"barycentric"`` the centroid of the
    polytope's vertices, ``"closed-form"`` and ``"improved-closed-form"`` the closed forms of
    Pott et al.  Every candidate is verified (module docstring) before it is reported.

    Parameters
    ----------
    W : array_like, shape (N, m, n) or (m, n)
        Structure matrices (shared by all poses when 2-D).
    wrench : array_like, shape (N, m) or (m,)
        External wrench on the platform [N, N m] (shared by all poses when 1-D).
    tension_bounds : (tmin, tmax)
        Tension bounds [N], each a number, ``(n,)`` or ``(N, n)``; ``tmin ≥ 0`` finite,
        ``tmax`` may be ``inf``.
    method : str, default "lp"
        One of :data:`METHODS`.

    Returns
    -------
    TensionResult
        Batched as ``W`` and ``wrench`` are; a pose without a solution gets zero tensions,
        ``feasible = False`` and status ``"infeasible"`` (proved) or ``"not-found"``.

    Raises
    ------
    TautError
        For arrays of the wrong shape or not finite, bounds that are inverted, negative or not
        a pair, an unknown method, or ``"barycentric"`` with an infinite upper bound.

    References
    ----------
        .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
           of Waterloo, 2022, §2.1.2, Eqs. 2.11–2.13. (docs/references.bib: rushton2022)

    Examples
    --------
    One wrench component, three cables: ``τ1 + 2 τ2 + 3 τ3 = 6``.

    >>> W, wrench = [[1.0, 2.0, 3.0]], [-6.0]
    >>> solve_tensions(W, wrench, tension_bounds=(0.0, 10.0), method="lp").tensions
    array([0., 0., 2.])
    >>> solve_tensions(W, wrench, tension_bounds=(0.0, 10.0), method="inf").tensions
    array([1., 1., 1.])
    >>> solve_tensions(W, wrench, tension_bounds=(0.0, 0.9)).status
    'infeasible'
    """
    if not isinstance(method, str) or method not in METHODS:
        raise TautError(f"unknown tension distribution method {method!r}; valid methods: {', '.join(METHODS)}")
    tmin, tmax = bounds_pair(tension_bounds)
    W, w, tmin, tmax, single = _inputs(W, wrench, tmin, tmax)
    cand, infeasible = METHODS[method](W, w, tmin, tmax)
    tau, ok = _verify(W, w, tmin, tmax, cand)
    status = np.where(ok, "optimal", np.where(infeasible, "infeasible", "not-found"))
    if single:
        return TensionResult(tau[0], bool(ok[0]), str(status[0]), method, np.zeros(0))
    return TensionResult(tau, ok, status, method, np.zeros((len(tau), 0)))
