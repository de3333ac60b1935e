"""Interval linear systems ``[A] x = [b]`` (Berti 2015, §3.1.3,
Eqs. 3.9–3.12).

:func:`interval_gauss` is interval Gaussian elimination (no pivoting, every operation
outward-rounded): it returns a box enclosing the solutions of every ``A x = b`` with
``A ∈ [A]``, ``b ∈ [b]``, or ``None`` when a pivot contains 0.
:func:`preconditioned_solve` first multiplies both sides by a float matrix ``K``
(Eq. 3.10): ``K = mid([A])⁻¹`` for a square system; for an over-determined ``6 × m``
system (the equilibrium of ``m < 6`` taut cables, Eq. 3.9) the generalised inverse of
Eq. 3.12, ``K = (Wᵀ mid J)⁻¹ Wᵀ`` with ``W`` the rows of ``mid J`` with force and moment
halves swapped, which keeps units consistent.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.1.3, Eqs. 3.9–3.12. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.interval import _kernels as K
from taut.interval._expression import Tape
from taut.interval._hc4 import evaluate_kernel


@njit(cache=True, fastmath=False)
def precondition(C: np.ndarray, Jl: np.ndarray, Jh: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``S = C·J`` for a float matrix ``C`` and an interval matrix ``J = [Jl, Jh]``, rounded
    outwards: the enclosure ``[Sl, Sh]``.  Compiled."""
    h, n = C.shape[0], Jl.shape[1]
    Sl = np.zeros((h, n))
    Sh = np.zeros((h, n))
    for i in range(h):
        for j in range(n):
            sl, sh = 0.0, 0.0
            for k in range(C.shape[1]):
                c, jl, jh = C[i, k], Jl[k, j], Jh[k, j]
                if c == 0.0 or (jl == 0.0 and jh == 0.0):
                    continue
                if c > 0.0:  # point × interval: two rounded products instead of eight
                    pl, ph = K.prod_down(c, jl), K.prod_up(c, jh)
                else:
                    pl, ph = K.prod_down(c, jh), K.prod_up(c, jl)
                sl, sh = K.add(sl, sh, pl, ph)
            Sl[i, j], Sh[i, j] = sl, sh
    return Sl, Sh


@njit(cache=True, fastmath=False)
def _gauss(Al: np.ndarray, Ah: np.ndarray, bl: np.ndarray, bh: np.ndarray) -> tuple[bool, np.ndarray, np.ndarray]:
    n = Al.shape[0]
    Al, Ah, bl, bh = Al.copy(), Ah.copy(), bl.copy(), bh.copy()
    for k in range(n):
        if Al[k, k] <= 0.0 <= Ah[k, k]:
            return False, bl, bh
        for i in range(k + 1, n):
            fl, fh = K.div(Al[i, k], Ah[i, k], Al[k, k], Ah[k, k])
            for j in range(k + 1, n):
                pl, ph = K.mul(fl, fh, Al[k, j], Ah[k, j])
                Al[i, j], Ah[i, j] = K.sub(Al[i, j], Ah[i, j], pl, ph)
            pl, ph = K.mul(fl, fh, bl[k], bh[k])
            bl[i], bh[i] = K.sub(bl[i], bh[i], pl, ph)
    xl, xh = np.empty(n), np.empty(n)
    for i in range(n - 1, -1, -1):
        sl, sh = bl[i], bh[i]
        for j in range(i + 1, n):
            pl, ph = K.mul(Al[i, j], Ah[i, j], xl[j], xh[j])
            sl, sh = K.sub(sl, sh, pl, ph)
        xl[i], xh[i] = K.div(sl, sh, Al[i, i], Ah[i, i])
    return True, xl, xh


def interval_gauss(
    Al: npt.ArrayLike, Ah: npt.ArrayLike, bl: npt.ArrayLike, bh: npt.ArrayLike
) -> tuple[np.ndarray, np.ndarray] | None:
    """An enclosure of the solution set of a square interval linear system ``[A] x = [b]``:
    interval Gaussian elimination without pivoting, every operation outward-rounded (Berti
    2015, §3.1.3).

    Parameters
    ----------
    Al, Ah : array_like, shape (n, n)
        The matrix's ends.
    bl, bh : array_like, shape (n,)
        The right-hand side's ends.

    Returns
    -------
    (xlo, xhi) or None
        None when a pivot contains 0.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.3, Eq. 3.9. (docs/references.bib: berti2015)

    Examples
    --------
    >>> interval_gauss([[2.0, 0.0], [0.0, 4.0]], [[2.0, 0.0], [0.0, 4.0]], [1.0, 1.0], [2.0, 2.0])
    (array([0.5 , 0.25]), array([1. , 0.5]))
    """
    ok, xl, xh = _gauss(np.asarray(Al, float), np.asarray(Ah, float), np.asarray(bl, float), np.asarray(bh, float))
    return (xl, xh) if ok else None


def generalised_inverse(J: np.ndarray) -> np.ndarray:
    """``K = (Wᵀ J)⁻¹ Wᵀ`` of Eq. 3.12 for a ``6 × m`` wrench matrix ``J`` (``W`` swaps the
    force and moment rows); ``J⁻¹`` when ``J`` is square."""
    if J.shape[0] == J.shape[1]:
        return np.linalg.inv(J)
    half = J.shape[0] // 2
    W = np.vstack([J[half:], J[:half]])
    return np.linalg.solve(W.T @ J, W.T)


def preconditioned_solve(
    Al: npt.ArrayLike,
    Ah: npt.ArrayLike,
    bl: npt.ArrayLike,
    bh: npt.ArrayLike,
    *,
    preconditioner: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray] | None:
    """:func:`interval_gauss` on the preconditioned system ``K[A] x = K[b]`` (Berti 2015, Eqs.
    3.10–3.12), far tighter than without ``K`` when ``[A]`` is narrow.

    Parameters
    ----------
    Al, Ah : array_like, shape (r, n)
        The matrix's ends (``r ≥ n``: an over-determined wrench system takes the generalised
        inverse of Eq. 3.12).
    bl, bh : array_like, shape (r,)
    preconditioner : ndarray, shape (n, r), optional
        ``K``; default :func:`generalised_inverse` of ``mid [A]``.

    Returns
    -------
    (xlo, xhi) or None
        None when elimination fails.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.3, Eqs. 3.10–3.12. (docs/references.bib: berti2015)

    Examples
    --------
    >>> A = [[2.0, 1.0], [1.0, 3.0]]
    >>> preconditioned_solve(A, A, [3.0, 4.0], [3.0, 4.0])
    (array([1., 1.]), array([1., 1.]))
    """
    Al, Ah = np.asarray(Al, float), np.asarray(Ah, float)
    bl, bh = np.asarray(bl, float), np.asarray(bh, float)
    K_ = preconditioner
    if K_ is None:
        try:
            K_ = generalised_inverse(0.5 * Al + 0.5 * Ah)
        except np.linalg.LinAlgError:
            return None
    if not np.all(np.isfinite(K_)):
        return None
    Cl, Ch = precondition(K_, Al, Ah)
    rl, rh = precondition(K_, bl[:, None], bh[:, None])
    return interval_gauss(Cl, Ch, rl[:, 0], rh[:, 0])


@njit(cache=True, fastmath=False)
def float_inverse(A: np.ndarray) -> tuple[bool, np.ndarray]:
    """``(ok, A⁻¹)`` by Gauss–Jordan with partial pivoting, in plain floating point.

    Only used for preconditioners (any float matrix gives a sound enclosure), so no
    rounding control; ``ok`` is False for a (numerically) singular or non-finite ``A``."""
    n = A.shape[0]
    M = A.copy()
    inv = np.eye(n)
    scale = 0.0
    for i in range(n):
        for j in range(n):
            scale = max(scale, abs(M[i, j]))
    if not (scale > 0.0 and scale < np.inf):
        return False, inv
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(M[i, k]) > abs(M[p, k]):
                p = i
        if not abs(M[p, k]) > 1e-14 * scale:
            return False, inv
        if p != k:
            for j in range(n):
                M[k, j], M[p, j] = M[p, j], M[k, j]
                inv[k, j], inv[p, j] = inv[p, j], inv[k, j]
        # columns j < k of M are already unit vectors: row k is zero there
        d = M[k, k]
        for j in range(k, n):
            M[k, j] /= d
        for j in range(n):
            inv[k, j] /= d
        for i in range(n):
            if i != k and M[i, k] != 0.0:
                f = M[i, k]
                for j in range(k, n):
                    M[i, j] -= f * M[k, j]
                for j in range(n):
                    inv[i, j] -= f * inv[k, j]
    for i in range(n):
        for j in range(n):
            if not np.isfinite(inv[i, j]):
                return False, inv
    return True, inv


@njit(cache=True, fastmath=False)
def _generalised_inverse(J: np.ndarray) -> tuple[bool, np.ndarray]:
    """Numba twin of :func:`generalised_inverse`."""
    r, m = J.shape
    if r == m:
        return float_inverse(J)
    half = r // 2
    W = np.empty_like(J)
    W[:half] = J[half:]
    W[half:] = J[:half]
    A = np.zeros((m, m))
    for i in range(m):
        for j in range(m):
            for k in range(r):
                A[i, j] += W[k, i] * J[k, j]
    ok, Ainv = float_inverse(A)
    Kp = np.zeros((m, r))
    for i in range(m):
        for j in range(r):
            for k in range(m):
                Kp[i, j] += Ainv[i, k] * W[j, k]
    return ok, Kp


@njit(cache=True, fastmath=False)
def enclosure_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    m: int,
    lo: np.ndarray,
    hi: np.ndarray,
) -> tuple[bool, np.ndarray, np.ndarray]:
    """Enclosure ``(ok, t_lo, t_hi)`` of the solutions ``t`` (``m`` of them) of the interval
    linear system ``[A](X) t = [b](X)`` whose ``r·m`` matrix entries (row-major) and ``r``
    right-hand sides are the constraints of the tape, over the box ``X = [lo, hi]``:
    preconditioned by the generalised inverse of ``mid A`` (Eq. 3.12), then interval Gauss.
    ``ok`` is False when no enclosure is found (a singular or unbounded ``A``)."""
    nc = start.size
    vl, vh = np.empty(nc), np.empty(nc)
    evaluate_kernel(op, a, b, clo, chi, start, end, lo, hi, vl, vh)
    r = nc // (m + 1)
    k = r * m
    Al, Ah = np.empty((r, m)), np.empty((r, m))
    Am = np.empty((r, m))
    none = np.empty(0)
    for i in range(r):
        for j in range(m):
            Al[i, j], Ah[i, j] = vl[i * m + j], vh[i * m + j]
            Am[i, j] = 0.5 * Al[i, j] + 0.5 * Ah[i, j]
            if not np.isfinite(Am[i, j]):
                return False, none, none
    bl, bh = np.empty((r, 1)), np.empty((r, 1))
    for i in range(r):
        bl[i, 0], bh[i, 0] = vl[k + i], vh[k + i]
    ok, Kp = _generalised_inverse(Am)
    if ok:
        ok, tl, th = _preconditioned_gauss(Kp, Al, Ah, bl, bh)
        if ok or r == m:
            return ok, tl, th
    # over-determined: Wᵀ mid A, symmetric indefinite, is singular on a surface of poses
    # where mid A has full rank (a random suspended robot, seed 4, 3 cables: the filter
    # failed on 4 M boxes whose tensions ran to 1e308); the scaled least-squares inverse
    # has full rank with mid A
    ok, Kp = _least_squares_inverse(Am)
    if not ok:
        return False, none, none
    return _preconditioned_gauss(Kp, Al, Ah, bl, bh)


@njit(cache=True, fastmath=False)
def _preconditioned_gauss(
    Kp: np.ndarray, Al: np.ndarray, Ah: np.ndarray, bl: np.ndarray, bh: np.ndarray
) -> tuple[bool, np.ndarray, np.ndarray]:
    """Interval Gauss on ``K[A] t = K[b]`` (``b`` a column); not ok for a non-finite ``K``."""
    for i in range(Kp.shape[0]):
        for j in range(Kp.shape[1]):
            if not np.isfinite(Kp[i, j]):
                return False, np.empty(0), np.empty(0)
    Cl, Ch = precondition(Kp, Al, Ah)
    rl, rh = precondition(Kp, bl, bh)
    return _gauss(Cl, Ch, rl[:, 0].copy(), rh[:, 0].copy())


@njit(cache=True, fastmath=False)
def _least_squares_inverse(J: np.ndarray) -> tuple[bool, np.ndarray]:
    """``K = (Jᵀ D² J)⁻¹ Jᵀ D²`` for a ``2h × m`` wrench matrix ``J``: the least-squares
    inverse with the lower (moment) half of the rows divided by ``ℓ``, the ratio of the
    halves' norms (units: a length), so that neither half dominates.  Any float ``K``
    gives a sound enclosure (Neumaier 1990, Ch. 4); this one is invertible whenever ``J``
    has full column rank.

    References
    ----------
    .. [1] A. Neumaier, "Interval Methods for Systems of Equations", Cambridge University
       Press, 1990, Ch. 4. (docs/references.bib: neumaier1990)
    """
    r, m = J.shape
    half = r // 2
    top, bottom = 0.0, 0.0
    for i in range(r):
        for j in range(m):
            if i < half:
                top += J[i, j] * J[i, j]
            else:
                bottom += J[i, j] * J[i, j]
    w2 = np.ones(r)
    if top > 0.0 and bottom > 0.0:
        w2[half:] = top / bottom
    A = np.zeros((m, m))
    for i in range(m):
        for j in range(m):
            for k in range(r):
                A[i, j] += J[k, i] * w2[k] * J[k, j]
    ok, Ainv = float_inverse(A)
    Kp = np.zeros((m, r))
    for i in range(m):
        for j in range(r):
            for k in range(m):
                Kp[i, j] += Ainv[i, k] * J[j, k] * w2[j]
    return ok, Kp


@njit(cache=True, fastmath=False)
def linear_filter_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    m: int,
    sign_only: bool,
    lo: np.ndarray,
    hi: np.ndarray,
) -> bool:
    """Contract the last ``m`` variables of the box with the enclosure of
    :func:`enclosure_kernel`, or — ``sign_only``, the unknowns hold no ``t`` — check that
    every ``t_j`` may be non-negative; False when the box is proven empty."""
    ok, tl, th = enclosure_kernel(op, a, b, clo, chi, start, end, m, lo, hi)
    if not ok:
        return True
    if sign_only:
        for j in range(m):
            if th[j] < 0.0:
                return False
        return True
    t0 = lo.size - m
    for j in range(m):
        if tl[j] > lo[t0 + j]:
            lo[t0 + j] = tl[j]
        if th[j] < hi[t0 + j]:
            hi[t0 + j] = th[j]
        if not lo[t0 + j] <= hi[t0 + j]:
            return False
    return True


class LinearFilter:
    """A filter ``f(lo, hi) -> bool`` for :func:`branch_and_prune`: the last ``m`` variables of the
    box solve an interval linear system (the equilibrium of the taut cables' tensions, Berti
    2015, Eq. 3.9), and are contracted to its enclosure; False when the box holds no solution.

    The branch-and-prune kernel runs it without Python.

    Parameters
    ----------
    tape : Tape
        The system's ``r·m`` matrix entries, row-major, then its ``r`` right-hand sides, as
        expressions of the box's variables.
    m : int
        Number of unknowns of the linear system.
    sign_only : bool, default False
        The solutions ``t ≥ 0`` of the system are not unknowns of the box: only reject boxes
        where some ``t_j`` must be negative.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.3, Eqs. 3.9–3.12. (docs/references.bib: berti2015)

    Examples
    --------
    ``2 t = 4`` contracts ``t ∈ [−10, 10]`` to 2:

    >>> from taut.interval import compile_tape, const
    >>> lin = LinearFilter(compile_tape([const(2.0), const(4.0)], [(-np.inf, np.inf)] * 2), 1)
    >>> lo, hi = np.array([-10.0]), np.array([10.0])
    >>> lin(lo, hi), lo, hi
    (True, array([2.]), array([2.]))
    """

    def __init__(self, tape: Tape, m: int, *, sign_only: bool = False) -> None:
        self.tape, self.m, self.sign_only = tape, int(m), bool(sign_only)

    def __call__(self, lo: np.ndarray, hi: np.ndarray) -> bool:
        op, a, b, clo, chi, start, end, _, _ = self.tape.arrays
        return bool(linear_filter_kernel(op, a, b, clo, chi, start, end, self.m, self.sign_only, lo, hi))

    def enclosure(self, lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray] | None:
        """An enclosure ``(t_lo, t_hi)`` of the solutions of the linear system over the box, or None.

        Parameters
        ----------
        lo, hi : ndarray, shape (n,)

        Returns
        -------
        (ndarray, ndarray) or None
        """
        op, a, b, clo, chi, start, end, _, _ = self.tape.arrays
        ok, tl, th = enclosure_kernel(
            op, a, b, clo, chi, start, end, self.m, np.asarray(lo, float), np.asarray(hi, float)
        )
        return (tl, th) if ok else None
