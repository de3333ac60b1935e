"""Multi-precision branch-and-prune (taut.interval._precise) on two circles of radius 1 whose
centres are ``2 − δ`` apart, with ``δ`` an exact rational no float holds: two roots
``x = 1 − δ/2``, ``y = ±√(δ − δ²/4)`` for ``δ > 0``, none for ``δ < 0``, a double root at
``(1, 0)`` for ``δ = 0``.  The roots are checked in exact rational arithmetic, not with the
solver's balls."""

import json
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.interval._branch_prune import branch_and_prune
from taut.interval._expression import compile_system, compile_tape, const, variables

flint = pytest.importorskip("flint")

from taut.interval._precise import solve_precise  # noqa: E402  (needs python-flint)


def circles(delta: Fraction):
    x, y = variables(2)
    c = Fraction(2) - delta
    f = float(c)
    centre = const(float(np.nextafter(f, -np.inf)), float(np.nextafter(f, np.inf)), exact=c)
    if Fraction(f) == c:
        centre = const(f)
    return compile_system(2, [x**2 + y**2 - 1.0, (x - centre) ** 2 + y**2 - 1.0])


LO, HI = np.array([0.5, -0.5]), np.array([1.5, 0.5])


def holds(lo: float, hi: float, value_squared: Fraction, positive: bool) -> bool:
    """``[lo, hi]`` holds ``±√value_squared`` (exact comparisons of squares)."""
    lo_f, hi_f = Fraction(lo), Fraction(hi)
    if positive:
        return lo_f <= 0 or lo_f**2 <= value_squared <= hi_f**2
    return hi_f >= 0 or hi_f**2 <= value_squared <= lo_f**2


@settings(max_examples=10, deadline=None)
@given(exponent=st.integers(12, 60))
def test_two_roots_closer_than_double_precision_separates_are_certified(exponent):
    delta = Fraction(1, 2**exponent) / 3  # not a float: only the exact rational separates the roots
    res = solve_precise(circles(delta), [(LO, HI)])
    assert len(res.solutions) == 2 and not res.undecided and not res.boundary
    x = 1 - delta / 2
    y2 = delta - delta**2 / 4
    ys = sorted(res.solutions, key=lambda c: c.x[1])
    for c, positive in zip(ys, (False, True)):
        assert Fraction(c.lo[0]) <= x <= Fraction(c.hi[0])
        assert holds(c.lo[1], c.hi[1], y2, positive)
        assert (c.hi[1] < 0) != positive  # the two boxes are apart: one root each
        assert c.radius >= 0.0


def test_double_precision_leaves_them_undecided():
    """The reason for the module: the same system in float intervals (the centre rounded
    outwards) cannot be decided near the tangency."""
    res = branch_and_prune(circles(Fraction(1, 3 * 2**50)), LO, HI, tol=1e-9)
    assert res.undecided and len(res.solutions) < 2


@pytest.mark.parametrize("exponent", [20, 50, 100])
def test_circles_apart_by_less_than_an_ulp_have_no_root(exponent):
    res = solve_precise(circles(-Fraction(1, 3 * 2**exponent)), [(LO, HI)])
    assert not res.solutions and not res.boundary and not res.undecided


def test_a_double_root_stays_undecided_and_its_boxes_hold_it():
    """At the tangency the Jacobian is singular at the root: no Krawczyk box can prove it
    unique, so the search ends with undecided boxes around (1, 0), never a solution."""
    res = solve_precise(circles(Fraction(0)), [(LO, HI)], max_boxes=400)
    assert not res.solutions and res.undecided and res.boxes <= 400
    assert any(lo[0] <= 1.0 <= hi[0] and lo[1] <= 0.0 <= hi[1] for lo, hi in res.undecided)


def test_a_root_on_the_domain_bound_is_boundary():
    """A domain of y ≥ 0 leaves the upper root alone, a solution; a domain ending at the
    root's own x (a float: ``1 − 2⁻²¹``) makes its box straddle the bound: boundary."""
    delta = Fraction(1, 3 * 2**40)
    res = solve_precise(circles(delta), [(LO, HI)], domain=(np.array([0.0, 0.0]), np.array([2.0, 2.0])))
    assert len(res.solutions) == 1 and res.solutions[0].lo[1] > 0.0 and not res.boundary
    on = solve_precise(circles(Fraction(1, 2**20)), [(LO, HI)], domain=(np.array([0.0, 0.0]), np.array([1.0, 2.0])))
    x = float(1 - Fraction(1, 2**21))
    cut = solve_precise(circles(Fraction(1, 2**20)), [(LO, HI)], domain=(np.array([0.0, 0.0]), np.array([x, 2.0])))
    assert len(on.solutions) == 1 and len(cut.boundary) == 1 and not cut.solutions


def test_tape_keeps_exact_constants_apart():
    """Two constants with the same float enclosure but different exact values stay two
    nodes (hash-consing compares the rationals too), and each keeps its rational."""
    a, b = Fraction(1, 3), Fraction(1, 3) + Fraction(1, 10**30)
    lo, hi = float(np.nextafter(1 / 3, 0)), float(np.nextafter(1 / 3, 1))
    tape = compile_tape([const(lo, hi, exact=a), const(lo, hi, exact=b)], [(0, 0), (0, 0)])
    assert tape.end.tolist() == [1, 2] and tape.exact == (a, b)


HALF = (np.array([0.5, 0.0]), HI)


def test_several_boxes_share_one_budget():
    """Two start boxes, one root in each, found by one search; a budget too small for the
    double root leaves boxes unsearched, the second start box among them, exactly."""
    delta = Fraction(1, 3 * 2**30)
    halves = [(LO, np.array([1.5, 0.0])), HALF]
    res = solve_precise(circles(delta), halves)
    assert len(res.solutions) == 2 and not res.undecided
    cut = solve_precise(circles(Fraction(0)), halves, max_boxes=30)
    assert cut.boxes == 30 and cut.unsearched and not cut.solutions and not cut.undecided
    assert any(np.array_equal(lo, HALF[0]) and np.array_equal(hi, HALF[1]) for lo, hi in cut.unsearched)


def test_roots_on_a_bisection_face_are_certified():
    """The box is centred on the roots' x = 1 − 2⁻²¹, a float: the first cut goes through
    both roots, which then lie in no box's interior.  Newton's limit and a small box around it
    certify them, once each."""
    delta = Fraction(1, 2**20)
    x = float(1 - delta / 2)
    res = solve_precise(circles(delta), [(np.array([x - 0.5, -0.5]), np.array([x + 0.5, 0.5]))])
    assert len(res.solutions) == 2 and not res.undecided and not res.unsearched
    assert all(c.lo[0] <= x <= c.hi[0] for c in res.solutions)
    assert sorted(np.sign([c.x[1] for c in res.solutions]).tolist()) == [-1.0, 1.0]


def test_result_says_exhausted_and_complete_and_is_json():
    cut = solve_precise(circles(Fraction(0)), [(LO, HI)], max_boxes=30)
    assert cut.exhausted and not cut.complete and cut.elapsed_s >= 0.0
    done = solve_precise(circles(Fraction(1, 2**20)), [(LO, HI)])
    assert done.complete and not done.exhausted
    back = json.loads(json.dumps(cut.as_dict(), allow_nan=False))
    assert back["boxes"] == 30 and back["exhausted"] is True
    assert back["unsearched"] == [[lo.tolist(), hi.tolist()] for lo, hi in cut.unsearched]
    with pytest.raises(ValueError, match="read-only"):
        cut.unsearched[0][0][0] = 0.0
