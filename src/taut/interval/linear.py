"""Interval linear systems ``[A] x = [b]`` (``001_eb92e2f6589fc229.txt`` §3.1.3,
Eqs. 3.9–3.12).

:func:`interval_gauss` is interval Gaussian elimination (no pivoting, every operation
outward-rounded): it returns a box enclosing the solutions of every ``A x = b`` with
``A ∈ [A]``, ``b ∈ [b]``, or ``None`` when a pivot contains 0.
:func:`preconditioned_solve` first multiplies both sides by a float matrix ``K``
(Eq. 3.10): ``K = mid([A])⁻¹`` for a square system; for an over-determined ``6 × m``
system (the equilibrium of ``m < 6`` taut cables, Eq. 3.9) the generalised inverse of
Eq. 3.12, ``K = (Wᵀ mid J)⁻¹ Wᵀ`` with ``W`` the rows of ``mid J`` with force and moment
halves swapped, which keeps units consistent.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from taut.interval import kernels as K
from taut.interval.krawczyk import _precondition


@njit(cache=True, fastmath=False)
def _gauss(Al, Ah, bl, bh):
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


def interval_gauss(Al, Ah, bl, bh):
    """Enclosure ``(xlo, xhi)`` of the solution set of a square interval system, or None."""
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


def preconditioned_solve(Al, Ah, bl, bh, K_=None):
    """Solve ``K[A] x = K[b]`` by :func:`interval_gauss` (Eqs. 3.10–3.12); ``K_`` defaults to
    :func:`generalised_inverse` of ``mid [A]``.  None when elimination fails."""
    Al, Ah = np.asarray(Al, float), np.asarray(Ah, float)
    bl, bh = np.asarray(bl, float), np.asarray(bh, float)
    if K_ is None:
        try:
            K_ = generalised_inverse(0.5 * Al + 0.5 * Ah)
        except np.linalg.LinAlgError:
            return None
    if not np.all(np.isfinite(K_)):
        return None
    Cl, Ch = _precondition(K_, Al, Ah)
    rl, rh = _precondition(K_, bl[:, None], bh[:, None])
    return interval_gauss(Cl, Ch, rl[:, 0], rh[:, 0])
