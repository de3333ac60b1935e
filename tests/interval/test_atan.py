"""The arctangent of the tapes: its enclosures, its HC4 projection and its derivative hold
the exact values, which 256-bit arb balls (python-flint) compute independently of libm."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.interval import atan, branch_and_prune, compile_system, contract, evaluate, variables
from taut.interval._kernels import atan as atan_kernel
from taut.interval._kernels import tan_inverse

flint = pytest.importorskip("flint")

finite = st.floats(min_value=-1e300, max_value=1e300, allow_nan=False, allow_infinity=False)
angles = st.floats(min_value=-1.5707963267948966, max_value=1.5707963267948966, allow_nan=False)


def _arb(x: float):
    flint.ctx.prec = 256
    return flint.arb(x)


def _below(lo: float, exact) -> bool:
    """``lo`` is a lower bound of the arb ball ``exact`` (proven: its whole ball)."""
    return lo == -np.inf or bool(_arb(lo) <= exact.lower())


def _above(hi: float, exact) -> bool:
    return hi == np.inf or bool(_arb(hi) >= exact.upper())


@settings(max_examples=400, deadline=None)
@given(finite, finite)
def test_atan_encloses_the_exact_arctangent(x, y):
    lo, hi = min(x, y), max(x, y)
    el, eh = atan_kernel(lo, hi)
    assert _below(el, _arb(lo).atan()) and _above(eh, _arb(hi).atan())
    assert el <= eh


@settings(max_examples=400, deadline=None)
@given(angles, angles)
def test_tan_inverse_encloses_every_argument_of_the_angles(z1, z2):
    zl, zh = min(z1, z2), max(z1, z2)
    lo, hi = tan_inverse(zl, zh)
    # every x with atan(x) in [zl, zh] lies in [tan zl, tan zh] (exact tangents of the floats)
    assert _below(lo, _arb(zl).tan()) and _above(hi, _arb(zh).tan())


def test_tan_inverse_at_the_ends_of_the_range():
    assert tan_inverse(-np.inf, np.inf) == (-np.inf, np.inf)
    assert tan_inverse(-2.0, 0.0)[0] == -np.inf
    assert tan_inverse(0.0, 1.5707963267948966)[1] == np.inf
    lo, hi = tan_inverse(1.6, 2.0)  # above π/2: no argument
    assert lo > hi
    lo, hi = tan_inverse(-3.0, -1.5707963267948968)  # below −π/2
    assert lo > hi


@settings(max_examples=200, deadline=None)
@given(st.floats(min_value=-1.5, max_value=1.5), st.floats(0.0, 10.0), st.floats(0.0, 10.0))
def test_hc4_keeps_the_root_of_an_arctangent_equation(c, below, above):
    """``atan(x) = c`` and ``x = y`` on a box holding the root ``x = y = tan c``: the
    contracted box still holds it."""
    exact = _arb(c).tan()  # the x whose arctangent is the float c
    mid = float(exact.mid())
    x, y = variables(2)
    system = compile_system(2, [atan(x) - c, x - y])
    lo = np.array([np.nextafter(mid, -np.inf) - below, -100.0])
    hi = np.array([np.nextafter(mid, np.inf) + above, 100.0])
    assert contract(system.tape, lo, hi)
    assert _below(lo[0], exact) and _above(hi[0], exact)
    assert _below(lo[1], exact) and _above(hi[1], exact)


def test_a_certified_root_of_an_arctangent_system_and_its_derivative():
    """``2 atan(x) + y = π/2``, ``y = x − 1``: one root, near x = 1 (atan 1 = π/4 gives
    y = 0); branch-and-prune certifies it with the Jacobian of ``atan`` (1/(1 + x²))."""
    x, y = variables(2)
    system = compile_system(2, [2.0 * atan(x) + y - float(np.pi / 2), y - x + 1.0])
    res = branch_and_prune(system, np.array([-5.0, -10.0]), np.array([5.0, 10.0]), tol=1e-10)
    assert res.complete and len(res.solutions) == 1
    c = res.solutions[0]
    # the exact root: g(x) = 2 atan x + x − 1 − π/2 changes sign over the certified box
    flint.ctx.prec = 256
    pi2 = flint.arb.pi() / 2

    def g(v):
        return 2 * _arb(v).atan() + _arb(v) - 1 - pi2

    assert g(c.lo[0]).upper() < 0 < g(c.hi[0]).lower()
    # the Jacobian tape holds the derivative 2/(1 + x²) at the root
    jl, jh = evaluate(system.jacobian, c.lo, c.hi)
    d = 2.0 / (1.0 + c.x[0] ** 2)
    assert jl[0] <= d <= jh[0]
