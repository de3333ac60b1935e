"""Slope enclosures by Gauss–Legendre quadrature (taut.interval._slope) against exact
rational arithmetic."""

from fractions import Fraction

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.interval import compile_system, const, krawczyk, sqrt, variables
from taut.interval._expression import NOT_POLYNOMIAL, degree
from taut.interval._hc4 import evaluate
from taut.interval._slope import points_for, slopes


@st.composite
def polynomials_with_a_box(draw):
    """``f(x) = Σ_k α_k Π_j (x_{v_kj} − s_kj)``: up to four terms of degree 1–4 in up to
    three unknowns; a box; points of the box."""
    n = draw(st.integers(1, 3))
    num = st.floats(-2.0, 2.0, allow_nan=False, allow_subnormal=False)
    x = variables(n)
    terms = []
    for _ in range(draw(st.integers(1, 4))):
        d = draw(st.integers(1, 4))
        factors = [(draw(st.integers(0, n - 1)), draw(num)) for _ in range(d)]
        terms.append((draw(num), factors))
    f = const(0.0)
    for alpha, factors in terms:
        t = const(alpha)
        for v, s in factors:
            t = t * (x[v] - s)
        f = f + t
    lo = np.array(draw(st.lists(num, min_size=n, max_size=n)))
    hi = lo + np.array(draw(st.lists(st.floats(0.0, 1.5), min_size=n, max_size=n)))
    u = np.array(draw(st.lists(st.floats(0.0, 1.0), min_size=n, max_size=n)))
    return n, f, terms, lo, hi, np.minimum(lo + u * (hi - lo), hi)


def _exact(terms, x):
    total = Fraction(0)
    for alpha, factors in terms:
        t = Fraction(alpha)
        for v, s in factors:
            t *= x[v] - Fraction(s)
        total += t
    return total


@settings(max_examples=300, deadline=None)
@given(polynomials_with_a_box())
def test_the_slope_enclosure_holds_the_exact_difference_quotient(case):
    """``f(x) − f(c) ∈ Σ_j S_j(X) (x_j − c_j)`` in exact arithmetic, for every point of
    the box and the rule :func:`points_for` picks for the polynomial's degree."""
    n, f, terms, lo, hi, x = case
    # the system's other equations only make it square; the test reads row 0
    system = compile_system(n, [f] + [variables(n)[i] for i in range(1, n)])
    points = points_for(int(system.degrees[0]))
    assert points in (1, 2)
    sl, sh = slopes(system, lo, hi, points)
    c = [Fraction(0.5 * lo[i] + 0.5 * hi[i]) for i in range(n)]
    xf = [Fraction(float(v)) for v in x]
    lower = upper = Fraction(0)
    for k in np.flatnonzero(system.rows == 0):
        j = system.cols[k]
        d = xf[j] - c[j]
        pair = (Fraction(sl[k]) * d, Fraction(sh[k]) * d)
        lower, upper = lower + min(pair), upper + max(pair)
    diff = _exact(terms, xf) - _exact(terms, c)
    assert lower <= diff <= upper


def test_a_quartic_needs_two_nodes():
    """``x⁴`` on ``[0, 2]`` from ``c = 1`` to ``x = 2``: the difference quotient is 15.
    The midpoint rule (exact for quadratics only) misses it; the two-node rule reaches it
    and no further."""
    (x,) = variables(1)
    system = compile_system(1, [x**4])
    assert system.degrees[0] == 4 and points_for(4) == 2
    one = slopes(system, [0.0], [2.0], 1)
    two = slopes(system, [0.0], [2.0], 2)
    assert one[1][0] < 15.0
    assert 15.0 <= two[1][0] <= 15.0 + 1e-9


def test_on_a_quadratic_the_slopes_are_half_as_wide_as_the_jacobian():
    x, y = variables(2)
    system = compile_system(2, [x**2 + x * y - 1, y**2 - x])
    lo, hi = np.array([0.5, 1.0]), np.array([1.5, 1.4])
    jl, jh = evaluate(system.jacobian, lo, hi)
    sl, sh = slopes(system, lo, hi, 1)
    assert np.all(sl >= jl) and np.all(sh <= jh)
    assert np.allclose(sh - sl, 0.5 * (jh - jl), rtol=1e-12, atol=1e-12)


def test_degree_of_expressions():
    x, y = variables(2)
    assert degree(x * y + 3) == 2
    assert degree((x**2 + y) ** 2) == 4
    assert degree((x - y) * (x + y) * x) == 3
    assert degree(x / 2.0) == 1
    assert degree(sqrt(x)) == NOT_POLYNOMIAL
    assert degree(x / y) == NOT_POLYNOMIAL
    assert points_for(5) == 0


def test_slopes_let_krawczyk_prove_a_box_empty_that_the_jacobian_cannot():
    """``x² − 5`` on ``[0.2, 2.2]`` (the root √5 is just outside): with ``J(X) = [0.4, 4.4]``
    the Krawczyk image still meets the box; with the slopes ``[1.4, 3.4]`` it does not."""
    (x,) = variables(1)
    system = compile_system(1, [x**2 - 5])
    assert krawczyk(system, [0.2], [2.2]).status == "unknown"
    assert krawczyk(system, [0.2], [2.2], points=1).status == "empty"


def test_the_two_nodes_are_upper_bounds_of_the_exact_ones():
    """``θ₁,₂ = (3 ∓ √3)/6``: ``θ⁺ ≥ θ₁ ⟺ 3 − 6θ⁺ ≤ √3`` and ``θ⁺ ≥ θ₂ ⟺ 6θ⁺ − 3 ≥ √3``, in
    exact rationals; and within 1e-14 of them."""
    from taut.interval._slope import NODES_2

    t1, t2 = (Fraction(float(t)) for t in NODES_2)
    assert 3 - 6 * t1 <= 0 or (3 - 6 * t1) ** 2 <= 3
    assert 6 * t2 - 3 > 0 and (6 * t2 - 3) ** 2 >= 3
    assert abs(float(NODES_2[0]) - (3 - np.sqrt(3)) / 6) < 1e-14
    assert abs(float(NODES_2[1]) - (3 + np.sqrt(3)) / 6) < 1e-14
