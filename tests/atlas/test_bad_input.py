"""docs/architecture.md §2.7: bad input to taut.atlas raises a TautError subclass naming what is
wrong, never the ValueError, TypeError or IndexError NumPy or shapely would raise deeper down."""

import pytest

from taut.atlas import (
    atlas_workspace,
    build_atlas,
    cable_reachable_area,
    chart_lengths,
    direct_ik,
    iterative_ik,
    iterative_step,
    locate,
)
from taut.errors import PoseError, TautError
from taut.model import example

ROBOT = example("vscr-t-shaped")
START = ROBOT.reference.poses["initial"]


@pytest.fixture(scope="module")
def atlas():
    return build_atlas(ROBOT, START)


@pytest.mark.parametrize(
    "call, error, words",
    [
        (lambda a: build_atlas(ROBOT, "x"), PoseError, "start point"),
        (lambda a: build_atlas(ROBOT, START, theta="x"), PoseError, "theta"),
        (lambda a: build_atlas(ROBOT, START, initial={0: "x"}), TautError, "cable state"),
        (lambda a: build_atlas(ROBOT, START, max_charts=0), TautError, "max_charts"),
        (lambda a: build_atlas(ROBOT, START, arc_step=0), TautError, "arc_step"),
        (lambda a: build_atlas(ROBOT, START, arc_step="x"), TautError, "arc_step"),
        (lambda a: direct_ik(a, "x"), PoseError, "points"),
        (lambda a: direct_ik(a, [[0, 0, 0]]), PoseError, "points"),
        (lambda a: direct_ik(a, [[0, 0]], charts=[999]), TautError, "charts"),
        (lambda a: locate(a, [[0, 0]], charts="x"), TautError, "charts"),
        (lambda a: iterative_ik(a, [[0, 0], [0.1, 0]], chart=999), TautError, "chart"),
        (lambda a: iterative_ik(a, "x"), PoseError, "points"),
        (lambda a: iterative_step(a, 999, [0, 0], [0, 1]), TautError, "chart"),
        (lambda a: iterative_step(a, 0, [0, 0], "x"), PoseError, "p2"),
        (lambda a: atlas_workspace(a, step="x"), TautError, "step"),
        (lambda a: atlas_workspace(a, step=0), TautError, "step"),
        (lambda a: chart_lengths(a.trees, a.charts[0].nodes, [[0, 0]], offsets=[1]), TautError, "offsets"),
        (lambda a: chart_lengths(a.trees, a.charts[0].nodes, "x"), PoseError, "points"),
        (lambda a: chart_lengths(a.trees, (0,), [[0, 0]]), TautError, "nodes"),
        (lambda a: cable_reachable_area(a.trees[0], 0, installation_space=[[0, 0]]), TautError, "installation"),
        (lambda a: cable_reachable_area(a.trees[0], 10**6), TautError, "node"),
    ],
)
def test_bad_arguments_raise_taut_errors(atlas, call, error, words):
    with pytest.raises(error, match=words):
        call(atlas)
