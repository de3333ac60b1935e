"""Bad input to taut.workspace raises a TautError subclass with a one-line message, never a
bare ValueError, TypeError or AttributeError (docs/architecture.md §2.7)."""

import numpy as np
import pytest

import taut
from taut.errors import TautError
from taut.statics import BoxWrenchSet
from taut.workspace import (
    default_bounds,
    evaluate_workspace,
    make_condition,
    pose_grid,
    position_grid,
)

PLANAR = taut.example("planar-4cable")

CASES = {
    "shrink not a number": lambda: default_bounds(PLANAR, shrink="a"),
    "shrink beyond half": lambda: default_bounds(PLANAR, shrink=0.7),
    "bounds not numbers": lambda: position_grid(PLANAR, bounds="ab"),
    "bounds not finite": lambda: position_grid(PLANAR, bounds=[[np.nan, 1.0], [0.0, 1.0]]),
    "bounds inverted": lambda: position_grid(PLANAR, bounds=[[1.0, 0.0], [0.0, 1.0]]),
    "axes not a sequence": lambda: pose_grid(PLANAR, 3),
    "grid index beyond": lambda: position_grid(PLANAR, resolution=3).poses_at([100]),
    "grid index not integer": lambda: position_grid(PLANAR, resolution=3).poses_at(["a"]),
    "grid index float": lambda: position_grid(PLANAR, resolution=3).poses_at([1.5]),
    "grid start negative": lambda: position_grid(PLANAR, resolution=3).poses(-5, 2),
    "progress not callable": lambda: evaluate_workspace(PLANAR, "static", resolution=3, progress=3),
    "executor unknown": lambda: evaluate_workspace(PLANAR, "static", resolution=3, executor="x"),
    "wrench set of another size": lambda: evaluate_workspace(
        PLANAR, "wrench-feasible", resolution=3, wrench_set=BoxWrenchSet.around(np.zeros(6), np.ones(6))
    ),
    "condition of a string": lambda: make_condition("static").evaluate(PLANAR, "x"),
    "interference of a string": lambda: make_condition("interference-free").evaluate(PLANAR, "x"),
    "result index beyond": lambda: evaluate_workspace(PLANAR, "static", resolution=3).poses_at([9]),
}


@pytest.mark.parametrize("name", CASES)
def test_bad_input_is_a_taut_error(name):
    with pytest.raises(TautError) as info:
        CASES[name]()
    assert "\n" not in str(info.value)


def test_grid_slices_are_the_poses_of_their_indices():
    grid = position_grid(PLANAR, resolution=3)
    np.testing.assert_array_equal(grid.poses(2, 5), grid.poses_at(np.arange(2, 5)))
    assert grid.poses(7, 100).shape == (2, 3) and grid.poses(20).shape == (0, 3)
