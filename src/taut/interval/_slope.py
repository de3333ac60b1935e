"""Slope enclosures of polynomial equations by Gauss–Legendre quadrature of the mean-value
integral (for the Krawczyk-type operators of Berti (2015), §3.2.1).

For ``x`` and the centre ``c`` of a box ``X``,

    f(x) − f(c) = S(x) (x − c),    S(x) = ∫₀¹ ∇f(c + θ (x − c)) dθ,

and a Krawczyk or Newton operator stays valid with any enclosure of the *slopes*
``S(x)``, ``x ∈ X``, in place of the Jacobian over ``X`` (Krawczyk & Neumaier, SIAM J.
Numer. Anal. 22, 1985) — it then excludes boxes and contracts them, but no longer proves
a solution unique.  For a polynomial of degree ``d`` the integrand is a polynomial in
``θ`` of degree ``d − 1``, so a Gauss–Legendre rule with ``p`` nodes integrates it exactly
when ``d ≤ 2p``:

* ``d ≤ 2``: ``S(x) = ∇f((x + c)/2)`` ∈ ``J(Z)``, ``Z = c + ½ (X − c)``;
* ``d ≤ 4``: ``S(x) = ½ [∇f(c + θ₁(x − c)) + ∇f(c + θ₂(x − c))]``,
  ``θ₁,₂ = ½ ∓ √3/6``, ∈ ``½ [J(Z₁) + J(Z₂)]``.

The boxes ``Z`` have half the radius of ``X`` on average, so the slope enclosure is about
half as wide as ``J(X)`` — the DGP's equations (quadratic with the plane normal as an
unknown, of degree ≤ 4 without it) are curved on the scale of the platform, and the
Jacobian's width is what keeps the parametric Krawczyk operator from proving boxes
beside the pose manifold empty.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.2.1. (docs/references.bib: berti2015)
.. [2] R. Krawczyk, A. Neumaier, "Interval slopes for rational functions and associated centered
   forms", SIAM Journal on Numerical Analysis 22, 1985. (docs/references.bib: krawczyk1985)
"""

from __future__ import annotations

import numpy as np
from numba import njit

from taut.interval import _kernels as K
from taut.interval._expression import System
from taut.interval._hc4 import evaluate, evaluate_kernel

#: Upper bounds of the two Gauss–Legendre nodes ``½ ∓ √3/6`` on [0, 1]: the rounded values
#: plus 1e-15, far above their few ulps of rounding error (checked exactly in the tests);
#: only upper bounds matter, ``c + θ (X − c)`` grows with ``θ``.
NODES_2 = 0.5 + np.array([-1.0, 1.0]) * np.sqrt(3.0) / 6.0 + 1e-15


def slopes(system: System, lo: np.ndarray, hi: np.ndarray, points: int) -> tuple[np.ndarray, np.ndarray]:
    """The slope enclosure of a :class:`~taut.interval.System`'s Jacobian
    entries over the box (``points`` nodes; the Jacobian over the box when 0)."""
    if not points:
        return evaluate(system.jacobian, lo, hi)
    vl, vh = np.empty(system.rows.size), np.empty(system.rows.size)
    slope_kernel(*system.jacobian.arrays[:7], np.asarray(lo, float), np.asarray(hi, float), points, vl, vh)
    return vl, vh


def points_for(degree: int) -> int:
    """Gauss–Legendre nodes that make the slope of a polynomial of ``degree`` exact:
    1 up to degree 2, 2 up to degree 4, 0 (no slope rule: use the Jacobian) above."""
    if degree <= 2:
        return 1
    return 2 if degree <= 4 else 0


@njit(cache=True, fastmath=False)
def _shrunk(lo: np.ndarray, hi: np.ndarray, theta: float) -> tuple[np.ndarray, np.ndarray]:
    """``c + θ (X − c)`` with ``c`` the midpoint of ``X`` (as the operators compute it),
    rounded outwards; variables with an infinite bound keep their domain."""
    zl, zh = lo.copy(), hi.copy()
    for i in range(lo.size):
        c = 0.5 * lo[i] + 0.5 * hi[i]
        if np.isfinite(c) and np.isfinite(lo[i]) and np.isfinite(hi[i]):
            zl[i] = max(lo[i], K.down(c + K.down(theta * K.down(lo[i] - c))))
            zh[i] = min(hi[i], K.up(c + K.up(theta * K.up(hi[i] - c))))
    return zl, zh


@njit(cache=True, fastmath=False)
def slope_kernel(
    jop: np.ndarray,
    ja: np.ndarray,
    jb: np.ndarray,
    jclo: np.ndarray,
    jchi: np.ndarray,
    jstart: np.ndarray,
    jend: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    points: int,
    out_lo: np.ndarray,
    out_hi: np.ndarray,
) -> None:
    """The slope enclosure of every Jacobian entry (tape ``j*``) over the box, with respect
    to its midpoint: ``points`` Gauss–Legendre nodes (1 or 2, see :func:`points_for`)."""
    if points == 1:
        zl, zh = _shrunk(lo, hi, 0.5)
        evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, zl, zh, out_lo, out_hi)
        return
    zl, zh = _shrunk(lo, hi, NODES_2[0])
    evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, zl, zh, out_lo, out_hi)
    sl, sh = np.empty(out_lo.size), np.empty(out_lo.size)
    zl, zh = _shrunk(lo, hi, NODES_2[1])
    evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, zl, zh, sl, sh)
    for k in range(out_lo.size):
        # ½ (a + b): the halving is exact unless the sum is subnormal, hence the rounding
        l, h = K.add(out_lo[k], out_hi[k], sl[k], sh[k])
        out_lo[k], out_hi[k] = K.down(0.5 * l), K.up(0.5 * h)
