"""Scalar interval kernels with outward rounding (Berti 2015, §1.3.1).

An interval is a pair ``(lo, hi)`` of floats.  Every operation computes its endpoints in
round-to-nearest and moves each one outwards by at least one ulp: IEEE 754 ``+ − × ÷ √``
are correctly rounded (error ≤ ½ ulp), so the moved endpoint is a proven bound of the
exact result.  The move is the branch-free successor/predecessor of Rump, Zimmermann,
Boldo & Melquiond ("Computing predecessor and successor in rounding to nearest", BIT 49,
2009, Algorithm 2): ``x + (φ|x| + η)`` with ``φ = u(1 + 2u)``, ``u = 2⁻⁵³`` and ``η`` the
smallest subnormal is at least ``succ(x)`` (and at most ``succ(succ(x))``) in
round-to-nearest — two flops instead of a ``nextafter`` call.  Infinite endpoints are allowed (``0 × ∞`` is taken as ``0``,
the usual convention for endpoint products), an empty interval has ``lo > hi`` (or NaN).

The kernels are Numba functions (``cache=True``, ``fastmath=False``: fast-math would let
the compiler reorder and contract the roundings away) so that :mod:`taut.interval._hc4`
and :mod:`taut.interval._krawczyk` can call them inside their own compiled loops;
:mod:`taut.interval._arithmetic` lifts them to arrays.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §1.3.1. (docs/references.bib: berti2015)
.. [2] S. M. Rump, P. Zimmermann, S. Boldo, G. Melquiond, "Computing predecessor and successor
   in rounding to nearest", BIT Numerical Mathematics 49(2), 2009, Algorithm 2.
   (docs/references.bib: rump2009)
.. [3] R. E. Moore, "Interval Analysis", Prentice-Hall, 1966. (docs/references.bib: moore1966)
"""

from __future__ import annotations

import numpy as np
from numba import njit

INF = np.inf
_PHI = 2.0**-53 * (1.0 + 2.0**-52)  #: u(1 + 2u), u = 2⁻⁵³ (Rump et al. 2009)
_ETA = 5e-324  #: smallest positive subnormal, 2⁻¹⁰⁷⁴
_MAX = float(np.finfo(np.float64).max)


@njit(cache=True, fastmath=False, inline="always")
def down(x: float) -> float:
    """A float ``≤ pred(x)`` (a lower bound of any real within ½ ulp of ``x``).  ``-∞`` and
    NaN are returned unchanged; ``+∞`` becomes the largest finite float, because a ``+∞``
    computed from finite operands is an overflow whose exact value is finite, and ``+∞``
    would not be a lower bound of it."""
    if x == INF:
        return _MAX
    if x == -INF:
        return x
    return x - (_PHI * abs(x) + _ETA)


@njit(cache=True, fastmath=False, inline="always")
def up(x: float) -> float:
    """A float ``≥ succ(x)``; ``-∞`` becomes the most negative finite float (see :func:`down`)."""
    if x == -INF:
        return -_MAX
    if x == INF:
        return x
    return x + (_PHI * abs(x) + _ETA)


@njit(cache=True, fastmath=False)
def add(al: float, ah: float, bl: float, bh: float) -> tuple[float, float]:
    return down(al + bl), up(ah + bh)


@njit(cache=True, fastmath=False)
def sub(al: float, ah: float, bl: float, bh: float) -> tuple[float, float]:
    return down(al - bh), up(ah - bl)


@njit(cache=True, fastmath=False, inline="always")
def prod_down(a: float, b: float) -> float:
    """Lower bound of ``a·b``: exact 0 only when a factor is 0 (an underflow to 0 is not)."""
    if a == 0.0 or b == 0.0:
        return 0.0
    return down(a * b)


@njit(cache=True, fastmath=False, inline="always")
def prod_up(a: float, b: float) -> float:
    """Upper bound of ``a·b``: exact 0 only when a factor is 0 (an underflow to 0 is not)."""
    if a == 0.0 or b == 0.0:
        return 0.0
    return up(a * b)


@njit(cache=True, fastmath=False)
def mul(al: float, ah: float, bl: float, bh: float) -> tuple[float, float]:
    """``[a] × [b]`` by the signs of the endpoints (Moore's nine cases): two rounded
    products, four only when both factors straddle 0."""
    if al >= 0.0:
        if bl >= 0.0:
            return prod_down(al, bl), prod_up(ah, bh)
        if bh <= 0.0:
            return prod_down(ah, bl), prod_up(al, bh)
        return prod_down(ah, bl), prod_up(ah, bh)
    if ah <= 0.0:
        if bl >= 0.0:
            return prod_down(al, bh), prod_up(ah, bl)
        if bh <= 0.0:
            return prod_down(ah, bh), prod_up(al, bl)
        return prod_down(al, bh), prod_up(al, bl)
    if bl >= 0.0:
        return prod_down(al, bh), prod_up(ah, bh)
    if bh <= 0.0:
        return prod_down(ah, bl), prod_up(al, bl)
    # both straddle 0: the lower end is a product of opposite signs, the upper of equal ones
    return min(prod_down(al, bh), prod_down(ah, bl)), max(prod_up(al, bl), prod_up(ah, bh))


@njit(cache=True, fastmath=False)
def scale(c: float, al: float, ah: float) -> tuple[float, float]:
    """``c × [a]`` for a float ``c``."""
    return mul(c, c, al, ah)


@njit(cache=True, fastmath=False)
def sqr(al: float, ah: float) -> tuple[float, float]:
    """``[a]²`` — sharper than ``[a]×[a]``: ``[-1, 2]² = [0, 4]``."""
    if al >= 0.0:
        lo, hi = prod_down(al, al), prod_up(ah, ah)
    elif ah <= 0.0:
        lo, hi = prod_down(ah, ah), prod_up(al, al)
    else:
        lo, hi = 0.0, max(prod_up(al, al), prod_up(ah, ah))
    return max(lo, 0.0), hi


@njit(cache=True, fastmath=False)
def sqrt(al: float, ah: float) -> tuple[float, float]:
    """``√[a]`` of the non-negative part of ``[a]`` (empty when ``ah < 0``)."""
    if ah < 0.0:
        return 1.0, -1.0
    lo = 0.0 if al <= 0.0 else np.sqrt(al)
    return (down(lo) if lo > 0.0 else 0.0), up(np.sqrt(ah))


#: The float nearest π/2, which is below π/2: ``atan`` never exceeds it by more than the
#: rounding of the enclosures, ``tan`` is finite and increasing on ``[−HALF_PI, HALF_PI]``.
HALF_PI = float(np.pi / 2)


@njit(cache=True, fastmath=False)
def atan(al: float, ah: float) -> tuple[float, float]:
    """``atan[a]``: the libm ``atan`` at each end (increasing), moved outwards by two ulps —
    libm's ``atan`` and ``tan`` are within one ulp of the exact value (glibc manual, "Known
    Maximum Errors in Math Functions"; the tests check both against 256-bit arb balls)."""
    return down(down(np.arctan(al))), up(up(np.arctan(ah)))


@njit(cache=True, fastmath=False)
def tan_inverse(zl: float, zh: float) -> tuple[float, float]:
    """The ``x`` with ``atan x ∈ [zl, zh]``: ``tan`` of the ends clipped to ``(−π/2, π/2)``,
    moved outwards by two ulps, infinite where the clip reaches ``±π/2`` (empty,
    ``lo > hi``, when ``[zl, zh]`` misses ``(−π/2, π/2)``)."""
    if zh < -HALF_PI or zl > HALF_PI:
        return 1.0, -1.0
    lo = -INF if zl <= -HALF_PI else down(down(np.tan(zl)))
    hi = INF if zh >= HALF_PI else up(up(np.tan(zh)))
    return lo, hi


@njit(cache=True, fastmath=False)
def div(al: float, ah: float, bl: float, bh: float) -> tuple[float, float]:
    """``[a] / [b]`` for ``0 ∉ [b]`` (``[-∞, ∞]`` when ``0 ∈ [b]``)."""
    if bl <= 0.0 <= bh:
        return -INF, INF
    flip = bh < 0.0  # [a] / [b] = −([a] / −[b]), outward rounding being symmetric
    if flip:
        bl, bh = -bh, -bl
    # 0 < bl: by the sign of [a], two quotients
    if al >= 0.0:
        lo, hi = al / bh, ah / bl
    elif ah <= 0.0:
        lo, hi = al / bl, ah / bh
    else:
        lo, hi = al / bl, ah / bl
    if flip:
        return down(-hi), up(-lo)
    return down(lo), up(hi)


@njit(cache=True, fastmath=False)
def power(al: float, ah: float, n: int) -> tuple[float, float]:
    """``[a]^n`` for an integer ``n ≥ 0``: even powers by repeated :func:`sqr`, odd powers
    (monotone) as ``x·x^(n-1)`` at each endpoint separately; every product is rounded
    outwards."""
    if n == 0:
        return 1.0, 1.0
    if n == 1:
        return al, ah
    if n % 2 == 0:
        sl, sh = sqr(al, ah)
        return power(sl, sh, n // 2)
    el, eh = power(al, al, n - 1)
    lo = mul(al, al, el, eh)[0]
    el, eh = power(ah, ah, n - 1)
    hi = mul(ah, ah, el, eh)[1]
    return lo, hi


@njit(cache=True, fastmath=False)
def neg(al: float, ah: float) -> tuple[float, float]:
    return -ah, -al
