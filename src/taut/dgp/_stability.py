"""Stability of an equilibrium by the reduced Hessian (Berti (2015)
§3.2.2, Eqs. 3.41–3.43, after Carricato & Merlet 2013).

``H = Σ τ_i/ρ_i [[I, −(b̃_i − g̃)], [(b̃_i − g̃), ½((b̃_i − g̃)(g̃ − ã_i) + (g̃ − ã_i)(b̃_i − g̃))]]``
(moments about ``G``), ``N`` spans the null space of ``Jᵀ`` (rows
``[(b_i − a_i)ᵀ, ((b_i − g) × (b_i − a_i))ᵀ]/ρ_i``: the motions that keep the taut lengths),
and the equilibrium is stable when ``H_r = Nᵀ H N`` is positive definite.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.2.2, Eqs. 3.41–3.43. (docs/references.bib: berti2015)
.. [2] M. Carricato, J.-P. Merlet, "Stability Analysis of Underconstrained Cable-Driven Parallel
   Robots", IEEE Transactions on Robotics 29(1), 2013. (docs/references.bib: carricato2013)
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True)
def reduced_hessian(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> np.ndarray:
    """``H_r`` for the taut cables: exit points ``a``, anchors ``b`` (``(m, 3)``), load point
    ``g``.  Compiled: the tracking update calls it once per step.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.2, Eqs. 3.41–3.43. (docs/references.bib: berti2015)
    .. [2] M. Carricato, J.-P. Merlet, "Stability Analysis of Underconstrained Cable-Driven
       Parallel Robots", IEEE Transactions on Robotics 29(1), 2013.
       (docs/references.bib: carricato2013)
    """
    H = np.zeros((6, 6))
    Jt = np.zeros((tau.size, 6))
    for i in range(tau.size):
        w = tau[i] / rho[i]
        bg = b[i] - g
        ga = g - a[i]
        Bg = np.array([[0.0, -bg[2], bg[1]], [bg[2], 0.0, -bg[0]], [-bg[1], bg[0], 0.0]])  # b̃_i − g̃
        Ga = np.array([[0.0, -ga[2], ga[1]], [ga[2], 0.0, -ga[0]], [-ga[1], ga[0], 0.0]])  # g̃ − ã_i
        S = 0.5 * (Bg @ Ga + Ga @ Bg)
        for r in range(3):
            H[r, r] += w
            for c in range(3):
                H[r, 3 + c] -= w * Bg[r, c]
                H[3 + r, c] += w * Bg[r, c]
                H[3 + r, 3 + c] += w * S[r, c]
        d = b[i] - a[i]
        Jt[i, :3] = d / rho[i]
        Jt[i, 3:] = np.cross(bg, d) / rho[i]
    _, s, vt = np.linalg.svd(Jt)
    top = max(1.0, s[0]) if s.size else 1.0
    rank = 0
    for v in s:
        if v > 1e-10 * top:
            rank += 1
    N = np.ascontiguousarray(vt[rank:].T)
    return N.T @ H @ N


@njit(cache=True)
def smallest_eigenvalue(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> float:
    """Smallest eigenvalue of the (symmetrised) reduced Hessian of :func:`reduced_hessian`,
    ``inf`` when the null space is empty; the equilibrium is stable when it is positive.
    Compiled, for callers that are compiled too (the tracking update); arrays contiguous."""
    Hr = reduced_hessian(a, b, g, tau, rho)
    if Hr.size == 0:
        return np.inf
    return np.linalg.eigvalsh(0.5 * (Hr + Hr.T))[0]


def is_stable(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> bool:
    """Positive-definite reduced Hessian (sufficient condition of §3.2.2); a fully
    constrained equilibrium (empty null space) is stable.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.2. (docs/references.bib: berti2015)
    """
    return bool(smallest_eigenvalue(*(np.ascontiguousarray(v, dtype=float) for v in (a, b, g, tau, rho))) > 0.0)
