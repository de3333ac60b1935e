"""taut.interval.bisect: the two halves of a box by the solver's bisection rule."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from taut.interval._branch_prune import bisect

boxes = st.integers(1, 6).flatmap(
    lambda n: st.tuples(
        st.lists(st.floats(-1e3, 1e3), min_size=n, max_size=n),
        st.lists(st.floats(1e-3, 1e3), min_size=n, max_size=n),
        st.lists(st.booleans(), min_size=n, max_size=n),
    )
)


@settings(max_examples=200, deadline=None)
@given(boxes)
def test_halves_split_the_widest_primary_variable_at_its_midpoint(case):
    lo_list, widths, mask = case
    lo = np.array(lo_list)
    hi = lo + np.array(widths)
    primary = np.array(mask) if any(mask) else None
    before = lo.copy(), hi.copy()
    (alo, ahi), (blo, bhi) = bisect(lo, hi, primary=primary)
    assert np.array_equal(lo, before[0]) and np.array_equal(hi, before[1])  # new arrays
    assert np.array_equal(alo, lo) and np.array_equal(bhi, hi)
    (cut,) = np.flatnonzero((ahi != hi) | (blo != lo))
    assert ahi[cut] == blo[cut] == 0.5 * lo[cut] + 0.5 * hi[cut]
    candidates = np.arange(lo.size) if primary is None else np.flatnonzero(primary)
    assert hi[cut] - lo[cut] == np.max((hi - lo)[candidates]) and cut in candidates


def test_score_and_eps_choose_the_variable():
    lo, hi = np.zeros(3), np.array([4.0, 2.0, 1.0])
    (_, ahi), _ = bisect(lo, hi, score=np.array([0.0, 0.0, 1.0]))
    assert ahi.tolist() == [4.0, 2.0, 0.5]  # largest score among the primary variables
    (_, ahi), _ = bisect(lo, hi, primary=[False, True, True], tol=3.0)
    assert ahi.tolist() == [2.0, 2.0, 1.0]  # primary ones below eps: the widest of all


def test_an_unbounded_variable_is_cut_at_a_finite_point():
    (_, ahi), (blo, _) = bisect([0.0, -np.inf], [1.0, np.inf])
    assert ahi[1] == blo[1] == 0.0
    (_, ahi), _ = bisect([2.0], [np.inf])
    assert ahi[0] == 4.0
