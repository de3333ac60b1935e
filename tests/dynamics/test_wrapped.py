"""Inverse dynamics takes cables as straight lines: it refuses a motion where one of a
variable-structure robot's straight cables would cross an obstacle, and answers as for the
robot without obstacles where they clear."""

from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import LineString, Point

from taut.dynamics import inverse_dynamics
from taut.errors import WrappedCableError
from taut.model import load_robot

VSCR = Path(__file__).resolve().parents[1] / "model" / "fixtures" / "taut" / "vscr_weighted.yaml"


def _crosses(robot, pose) -> bool:
    """Shapely: does a straight cable from its exit to the point mass enter a circle?"""
    lines = [LineString([tuple(e), tuple(pose[:2])]) for e in robot.exits]
    discs = [Point(o.center).buffer(o.radius, 256) for o in robot.obstacles if o.kind == "circle"]
    return any(line.crosses(d) or line.within(d) for line in lines for d in discs)


def test_a_motion_through_an_obstacle_is_refused_and_a_clear_one_answered():
    robot = load_robot(VSCR)
    clear, through = np.array([0.75, -0.5]), np.array([0.0, -0.7])
    assert not _crosses(robot, clear) and _crosses(robot, through)
    zeros = np.zeros((2, 2))
    with pytest.raises(WrappedCableError, match=r"t = 0.5 s .*cable \d+ meets obstacle \d+"):
        inverse_dynamics(robot, np.array([clear, through]), zeros, zeros, times=[0.0, 0.5])
    free = robot.model_copy(update={"obstacles": ()})
    q = np.array([clear, clear + [0.01, 0.0]])
    got = inverse_dynamics(robot, q, zeros, zeros, method="qp")
    want = inverse_dynamics(free, q, zeros, zeros, method="qp")
    np.testing.assert_array_equal(got.tensions, want.tensions)
