"""docs/architecture.md §2.7: bad input to taut.wrapping raises a TautError subclass naming what
is wrong, never the ValueError, TypeError or IndexError NumPy or Numba would raise deeper down."""

import numpy as np
import pytest

from taut.errors import CableSetError, PoseError, TautError
from taut.model import example
from taut.wrapping import (
    CableState,
    CableStateTree,
    builtin_trajectory,
    contacts_text,
    full_poses,
    rebuild_path,
    run_trajectory,
    timed_moves,
    track_cable_state,
    update_state,
    wrapped_inverse_kinematics,
)

ROBOT = example("vscr-single-cable")
POSE = [[0.75, -0.5]]
TREE = CableStateTree([[0.5, 0.5, 0.1], [0.0, 0.0, 0.0]])


@pytest.mark.parametrize(
    "call, words",
    [
        (lambda: wrapped_inverse_kinematics(ROBOT, POSE, initial={0: "x"}), "cable state"),
        (lambda: wrapped_inverse_kinematics(ROBOT, POSE, initial={0: [(99, 1)]}), "object"),
        (lambda: wrapped_inverse_kinematics(ROBOT, POSE, initial={0: [(0, 2)]}), "direction"),
        (lambda: run_trajectory(ROBOT, "x", POSE), "times"),
        (lambda: run_trajectory(ROBOT, [[0.0]], POSE), "times"),
        (lambda: run_trajectory(ROBOT, [0.0], POSE, wrench=[1, 2, 3, 4]), "wrench"),
        (lambda: run_trajectory(ROBOT, [0.0], POSE, tension_bounds="x"), "tension_bounds"),
        (lambda: timed_moves("x"), "waypoints"),
        (lambda: timed_moves([[0, 0], [1, 1]], speed="x"), "speed"),
        (lambda: timed_moves([[0, 0], [np.nan, 1]]), "waypoints"),
        (lambda: timed_moves([[0, 0], [1, 1]], dwell=-1), "dwell"),
        (lambda: builtin_trajectory(ROBOT, dt="x"), "dt"),
        (lambda: CableStateTree("x"), "circles"),
        (lambda: CableStateTree([[0, 0]]), "circles"),
        (lambda: CableStateTree([[0, 0, 0]], winch_direction=0), "winch_direction"),
        (lambda: TREE.find("x"), "cable state"),
        (lambda: TREE.find([(7, 1)]), "object"),
        (lambda: TREE.shortest_taut_state("x"), "platform end"),
        (lambda: track_cable_state(TREE, "x"), "points"),
        (lambda: track_cable_state(TREE, [1.0, 2.0]), "points"),
        (lambda: track_cable_state(TREE, [[1, 2], [1, 3]], node=99), "node"),
        (lambda: update_state(TREE, 99, [1, 1], [1, 2]), "node"),
        (lambda: update_state(TREE, 0, "x", [1, 2]), "platform end"),
        (lambda: rebuild_path("x", 1, CableState(()), [1, 1]), "circles"),
        (lambda: rebuild_path(TREE.circles, 1, CableState(((5, 1),)), [1, 1]), "objects"),
        (lambda: contacts_text("x"), "contacts"),
    ],
)
def test_bad_arguments_raise_taut_errors(call, words):
    with pytest.raises(TautError, match=words):
        call()


def test_bad_poses_and_cables():
    with pytest.raises(PoseError):
        full_poses(ROBOT, "x")
    with pytest.raises(PoseError):
        full_poses(ROBOT, np.zeros((2, 2, 2)))
    with pytest.raises(CableSetError, match="initial"):
        wrapped_inverse_kinematics(ROBOT, POSE, initial={9: [(0, 1)]})
