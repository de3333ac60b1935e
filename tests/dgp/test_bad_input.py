"""docs/architecture.md §2.7: bad input to taut.dgp raises a TautError subclass naming what is
wrong, never the ValueError or TypeError NumPy or Python would raise deeper down."""

import numpy as np
import pytest

from taut.dgp import DGPSolution, build_subproblem, solve_dgp, solve_igp, track_equilibrium, track_path
from taut.errors import CableSetError, TautError
from taut.model import load_robot

ROBOT = load_robot("suspended-3cable")
START = DGPSolution((0, 1, 2), np.zeros(3), np.zeros(3), np.ones(3), True, 0.0, 0.0)
FIX = {"x": 1.0, "a": 0.0}


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: solve_dgp(ROBOT, "abc"), "cable lengths"),
        (lambda: solve_dgp(ROBOT, [[1, 2], [3]]), "cable lengths"),
        (lambda: solve_dgp(ROBOT, max_taut="x"), "max_taut"),
        (lambda: solve_dgp(ROBOT, max_taut=0), "max_taut"),
        (lambda: solve_dgp(ROBOT, max_boxes="x"), "max_boxes"),
        (lambda: solve_dgp(ROBOT, max_boxes=float("nan")), "max_boxes"),
        (lambda: solve_dgp(ROBOT, max_boxes=2.5), "max_boxes"),
        (lambda: solve_dgp(ROBOT, tol="x"), "tol"),
        (lambda: solve_dgp(ROBOT, tol=-1.0), "tol"),
        (lambda: solve_dgp(ROBOT, split="x"), "split"),
        (lambda: solve_igp(ROBOT, (0, 1), FIX, max_boxes="x"), "max_boxes"),
        (lambda: solve_igp(ROBOT, (0, 1), FIX, tol="x"), "tol"),
        (lambda: solve_igp(ROBOT, (0, 1), FIX, tol=np.inf), "tol"),
        (lambda: track_equilibrium(ROBOT, START, "abc"), "cable lengths"),
        (lambda: track_equilibrium(ROBOT, "x", [1.0, 1.0, 1.0]), "DGPSolution"),
        (lambda: track_path(ROBOT, START, [[1, 2, 3], [1]]), "lengths sequence"),
        (lambda: build_subproblem(ROBOT, [1.0, 1.0], (0, 1)), "cable lengths"),
    ],
)
def test_bad_arguments_raise_taut_errors(call, words):
    with pytest.raises(TautError, match=words):
        call()


@pytest.mark.parametrize("taut", [(7,), (0, 0), (), "ab", 3, (0.5, 1)])
def test_bad_taut_cables_of_a_subproblem(taut):
    with pytest.raises(CableSetError, match="taut cables"):
        build_subproblem(ROBOT, [1.0, 1.0, 1.0], taut)
