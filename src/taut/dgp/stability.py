"""Stability of an equilibrium by the reduced Hessian (``001_eb92e2f6589fc229.txt``
§3.2.2, Eqs. 3.41–3.43, after Carricato & Merlet 2013).

``H = Σ τ_i/ρ_i [[I, −(b̃_i − g̃)], [(b̃_i − g̃), ½((b̃_i − g̃)(g̃ − ã_i) + (g̃ − ã_i)(b̃_i − g̃))]]``
(moments about ``G``), ``N`` spans the null space of ``Jᵀ`` (rows
``[(b_i − a_i)ᵀ, ((b_i − g) × (b_i − a_i))ᵀ]/ρ_i``: the motions that keep the taut lengths),
and the equilibrium is stable when ``H_r = Nᵀ H N`` is positive definite.
"""

from __future__ import annotations

import numpy as np


def _skew(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def reduced_hessian(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> np.ndarray:
    """``H_r`` for the taut cables: exit points ``a``, anchors ``b`` (``(m, 3)``), load point ``g``."""
    H = np.zeros((6, 6))
    Jt = np.zeros((len(tau), 6))
    G = _skew(g)
    for i in range(len(tau)):
        Bg = _skew(b[i]) - G
        Ga = G - _skew(a[i])
        H += tau[i] / rho[i] * np.block([[np.eye(3), -Bg], [Bg, 0.5 * (Bg @ Ga + Ga @ Bg)]])
        Jt[i, :3] = (b[i] - a[i]) / rho[i]
        Jt[i, 3:] = np.cross(b[i] - g, b[i] - a[i]) / rho[i]
    _, s, vt = np.linalg.svd(Jt)
    rank = int(np.sum(s > 1e-10 * max(1.0, s[0] if s.size else 1.0)))
    N = vt[rank:].T
    return N.T @ H @ N


def is_stable(a, b, g, tau, rho) -> bool:
    """Positive-definite reduced Hessian (sufficient condition of §3.2.2); a fully
    constrained equilibrium (empty null space) is stable."""
    Hr = reduced_hessian(np.asarray(a), np.asarray(b), np.asarray(g), np.asarray(tau), np.asarray(rho))
    if Hr.size == 0:
        return True
    return bool(np.all(np.linalg.eigvalsh(0.5 * (Hr + Hr.T)) > 0.0))
