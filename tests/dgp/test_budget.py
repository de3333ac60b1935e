"""The box budget of the DGP bounds its time: a certification (Newton and Krawczyk in
Python, dozens of times a compiled box) is charged to it, and lengths beyond what double
precision resolves are refused."""

import numpy as np
import pytest

from taut.dgp import solve_dgp
from taut.dgp._formulation import build_subproblem
from taut.errors import TautError
from taut.interval import CERTIFY_BOXES, branch_and_prune
from taut.model import load_robot

ROBOT = load_robot("suspended-3cable")


def test_certifications_are_charged_to_the_box_budget():
    """Lengths of 1e9 m, two taut cables: the pose unknowns near 1e9 are 1.2e-7 apart, so
    boxes of width ``tol`` that Krawczyk cannot prove anything in are reached all along the
    solution curve, and every one is a candidate for Newton; the budget stops them all the
    same (without the charge: 20,000 boxes and thousands of certifications)."""
    sp = build_subproblem(ROBOT, np.full(3, 1e9), (0, 1))
    budget = 20_000
    res = branch_and_prune(
        sp.system,
        sp.lo,
        sp.hi,
        primary=sp.primary,
        filters=(sp.statics,),
        certify_width=1.0,
        filter_width=1.0,
        passes=4,
        ratio=0.1,
        domain=(sp.lo, sp.hi),
        bisection="smear",
        starve=10.0,
        tube=sp.geometry,
        max_boxes=budget,
    )
    tried = res.stats["certifications"]
    assert tried > 100 and res.undecided  # the budget ran out: the rest is undecided
    # the last box popped and the last certification may overrun it by one each
    assert res.boxes + CERTIFY_BOXES * tried <= budget + CERTIFY_BOXES + 1


@pytest.mark.parametrize("length", [1e9, 2e5])
def test_lengths_double_precision_cannot_resolve_are_refused(length):
    with pytest.raises(TautError, match=r"cannot resolve tol = 1e-07 m .* up to 1\.1e\+05 m"):
        solve_dgp(ROBOT, np.full(3, length))
    # the limit is relative to tol: 2**40 tol
    with pytest.raises(TautError, match=r"tol = 1e-12 m there \(it takes coordinates up to 1\.1 m\)"):
        solve_dgp(ROBOT, np.full(3, 10.0), tol=1e-12)
