"""Shared by the table reproductions of 001_eb92e2f6589fc229.txt."""

from itertools import combinations

import numpy as np
import pytest

from taut.dgp.solve import _solve_subset
from taut.parallel import get_executor


@pytest.fixture
def solve_subsets():
    """``run(robot, m)``: every sub-problem with ``m`` taut cables at the robot's reference
    lengths, on two worker processes — ``{taut (0-based): (solutions, undecided boxes)}``."""

    def run(robot, m, workers=2):
        lengths = np.array(robot.reference.lengths)
        subsets = list(combinations(range(robot.n_cables), m))
        with get_executor(workers=workers) as ex:
            parts = ex.map(_solve_subset, [(robot, lengths, taut, 1e-7) for taut in subsets])
        return {taut: (sols, und) for taut, (sols, und, _) in zip(subsets, parts)}

    return run
