"""Shared by the table reproductions of Berti (2015)."""

from itertools import combinations

import numpy as np
import pytest

from taut.dgp._solve import solve_subset
from taut.parallel import get_executor


@pytest.fixture
def solve_subsets():
    """``run(robot, m)``: every sub-problem with ``m`` taut cables at the robot's reference
    lengths, on two worker processes — ``{taut (0-based): (solutions, undecided boxes)}``."""

    def run(robot, m, workers=2):
        lengths = np.array(robot.reference.lengths)
        subsets = list(combinations(range(robot.n_cables), m))
        with get_executor(workers=workers) as ex:
            parts = ex.map(solve_subset, [(robot, lengths, taut, 1e-7) for taut in subsets])
        return {taut: (sols, und) for taut, (sols, und, _) in zip(subsets, parts)}

    return run


def _printed_taut(row):
    """Taut cables (0-based indices) of a printed row ``pose (6), tensions (n)``; None when the
    OCR lost one of its tensions."""
    if any(t is None for t in row[6:]):
        return None
    return tuple(i for i, t in enumerate(row[6:]) if t > 0)


@pytest.fixture
def match_rows():
    """``match(solutions, printed, pos_tol, ang_tol, tau_tol)``: each printed ``(row, stable)``
    — position, angles, then the tensions of every cable, ``None`` where the OCR lost a
    value — is met by exactly one solution of its taut set (within the tolerances) with the
    same stability flag; returns the solutions no row matched."""

    def match(sols, printed, pos_tol=3e-3, ang_tol=1e-2, tau_tol=3e-3):
        found = list(sols)
        for row, stable in printed:
            taut = _printed_taut(row)
            hits = [
                s
                for s in found
                if (taut is None or s.taut == taut)
                and all(
                    p is None or abs(v - p) <= (pos_tol if k < 3 else ang_tol)
                    for k, (v, p) in enumerate(zip(np.r_[s.position, s.orientation], row[:6]))
                )
            ]
            assert len(hits) == 1, row
            s = hits[0]
            assert all(p is None or abs(v - p) <= tau_tol for v, p in zip(s.tensions, row[6:])), row
            assert s.stable == stable, row
            found = [f for f in found if f is not s]
        return found

    return match
