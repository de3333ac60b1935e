"""Interval enclosures contain the exact (rational) results: fractions.Fraction oracle."""

from fractions import Fraction as F

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.errors import ArgumentError
from taut.interval import Interval

finite = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)
unit = st.floats(min_value=0.0, max_value=1.0)


def _interval(draw):
    a, b = draw(finite), draw(finite)
    return min(a, b), max(a, b)


@st.composite
def intervals_and_points(draw):
    lo, hi = _interval(draw)
    t = draw(unit)
    x = F(lo) + (F(hi) - F(lo)) * F(t)  # an exact rational inside [lo, hi]
    return lo, hi, x


def _inside(x: F, iv: Interval) -> bool:
    lo, hi = float(iv.lo), float(iv.hi)
    return (lo == -np.inf or F(lo) <= x) and (hi == np.inf or x <= F(hi))


@settings(max_examples=300, deadline=None)
@given(intervals_and_points(), intervals_and_points())
def test_binary_operations_enclose_exact_results(a, b):
    al, ah, x = a
    bl, bh, y = b
    A, B = Interval(al, ah), Interval(bl, bh)
    assert _inside(x + y, A + B)
    assert _inside(x - y, A - B)
    assert _inside(x * y, A * B)
    if not bl <= 0.0 <= bh:
        assert _inside(x / y, A / B)


@settings(max_examples=300, deadline=None)
@given(intervals_and_points(), st.integers(min_value=0, max_value=5))
def test_unary_operations_enclose_exact_results(a, n):
    al, ah, x = a
    A = Interval(al, ah)
    assert _inside(x * x, A.sqr())
    assert _inside(x**n, A**n)
    if x >= 0:
        s = A.sqrt()
        # √x ∈ [lo, hi]  ⇔  lo² ≤ x ≤ hi² (lo, hi ≥ 0)
        assert F(float(s.lo)) ** 2 <= x <= F(float(s.hi)) ** 2


@settings(max_examples=200, deadline=None)
@given(intervals_and_points())
def test_bounds_are_outward_even_for_exact_float_inputs(a):
    """A sum of floats is usually inexact; the enclosure must still hold the exact value."""
    al, ah, x = a
    s = Interval(al, ah) + Interval(0.1)
    assert _inside(x + F(0.1), s)


def test_sqr_is_sharper_than_product_and_infinities_are_safe():
    a = Interval(-1.0, 2.0)
    assert (float(a.sqr().lo), float(a.sqr().hi)) == (0.0, np.nextafter(4.0, 5.0))
    assert (a * a).lo < 0
    z = Interval(0.0, 0.0) * Interval(0.0, np.inf)
    assert (float(z.lo), float(z.hi)) == (0.0, 0.0)
    assert np.isinf((Interval(1.0, 2.0) / Interval(-1.0, 1.0)).hi)
    assert Interval(-2.0, -1.0).sqrt().is_empty()


def test_negative_power_is_rejected():
    with pytest.raises(ArgumentError):
        Interval(1.0, 2.0) ** -1


@settings(max_examples=500, deadline=None)
@given(st.floats(allow_nan=False, allow_infinity=False, width=64))
def test_outward_steps_are_one_or_two_ulps(x):
    from taut.interval._kernels import down, up

    u, d = up(x), down(x)
    with np.errstate(over="ignore"):  # nextafter(±max, ±inf) overflows to ±inf: still a valid bound check
        assert np.nextafter(x, np.inf) <= u <= np.nextafter(np.nextafter(x, np.inf), np.inf)
        assert np.nextafter(np.nextafter(x, -np.inf), -np.inf) <= d <= np.nextafter(x, -np.inf)


def test_outward_steps_at_the_edges():
    from taut.interval._kernels import down, up

    tiny, big = 5e-324, np.finfo(float).max
    for x in (0.0, -0.0, tiny, -tiny, 2.2250738585072014e-308, 1.0, -1.0, 2.0**-1022, big, -big):
        assert up(x) > x and down(x) < x
    assert up(np.inf) == np.inf and down(-np.inf) == -np.inf
    # an infinite endpoint on the inner side can only be an overflow of finite operands:
    # it is pulled back to the largest finite float so the bound stays a bound
    assert down(np.inf) == big and up(-np.inf) == -big
    assert np.isnan(up(np.nan)) and np.isnan(down(np.nan))


def test_overflow_of_finite_operands_keeps_a_finite_inner_bound():
    q = Interval(1.0, 2.0) / Interval(5e-324, 1e-300)
    assert float(q.lo) <= 1e300 and np.isfinite(float(q.lo)) and float(q.hi) == np.inf
    p = Interval(1e200, 1e201) * Interval(-1e200, -1e199)
    assert float(p.lo) == -np.inf and float(p.hi) == -np.finfo(float).max


def _ulps_below(x: float, k: int) -> float:
    for _ in range(k):
        x = float(np.nextafter(x, -np.inf))
    return x


def _ulps_above(x: float, k: int) -> float:
    for _ in range(k):
        x = float(np.nextafter(x, np.inf))
    return x


@settings(max_examples=400, deadline=None)
@given(intervals_and_points(), intervals_and_points())
def test_products_and_quotients_are_the_corner_hull_within_two_ulps(a, b):
    """Products and quotients pick their endpoints by sign (two operations, not four): the
    result is the hull of the four exact corner values, rounded out by at most two ulps —
    an endpoint taken from the wrong corner would be wider (or lose the enclosure)."""
    al, ah, _ = a
    bl, bh, _ = b
    pairs = [("*", Interval(al, ah) * Interval(bl, bh), [F(x) * F(y) for x in (al, ah) for y in (bl, bh)])]
    if not bl <= 0.0 <= bh:
        pairs.append(("/", Interval(al, ah) / Interval(bl, bh), [F(x) / F(y) for x in (al, ah) for y in (bl, bh)]))
    for _, iv, corners in pairs:
        lo, hi = float(iv.lo), float(iv.hi)
        exact_lo, exact_hi = min(corners), max(corners)
        assert _inside(exact_lo, iv) and _inside(exact_hi, iv)
        assert lo >= _ulps_below(_rounded(exact_lo), 2) and hi <= _ulps_above(_rounded(exact_hi), 2)


def _rounded(x: F) -> float:
    """The nearest float, ±∞ past the largest one."""
    try:
        return float(x)
    except OverflowError:
        return np.inf if x > 0 else -np.inf


def test_products_and_quotients_with_infinite_endpoints():
    def pair(iv):
        return float(iv.lo), float(iv.hi)

    assert pair(Interval(0.0, np.inf) * Interval(1.0, 2.0)) == (0.0, np.inf)
    assert pair(Interval(-np.inf, -1.0) * Interval(-np.inf, -2.0))[1] == np.inf
    assert pair(Interval(-np.inf, -1.0) * Interval(-np.inf, -2.0))[0] >= 2.0 - 1e-15
    assert pair(Interval(-1.0, 2.0) * Interval(0.0, np.inf)) == (-np.inf, np.inf)
    lo, hi = pair(Interval(1.0, np.inf) / Interval(1.0, np.inf))
    assert lo <= 0.0 and hi == np.inf
    lo, hi = pair(Interval(-3.0, 6.0) / Interval(-np.inf, -2.0))
    assert -3.0 - 1e-15 <= lo <= -3.0 and 1.5 <= hi <= 1.5 + 1e-15
