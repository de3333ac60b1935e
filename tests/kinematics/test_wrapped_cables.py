"""Straight-cable analyses of variable-structure robots (docs/architecture.md §4.4): where a
straight cable clears every obstacle they answer as for the robot without obstacles; where
it meets one they refuse, naming the cable and the obstacle.  Shapely decides independently
(tests/straight_cables.py)."""

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from straight_cables import contacts

from taut.errors import InfeasiblePoseError, WrappedCableError
from taut.kinematics import (
    CABLE_OK,
    batch_structure_matrices,
    ik_status,
    inverse_kinematics,
    obstacles_met,
    refuse_wrapped,
)
from taut.model import Polygon, load_robot
from taut.statics import distribute_tensions

VSCR = load_robot(Path(__file__).parents[1] / "model/fixtures/taut/vscr_weighted.yaml")
#: The same robot with a triangle in place of object 1: polygon obstacles too.
TRIANGLE = VSCR.model_copy(
    update={
        "obstacles": (
            Polygon(kind="polygon", name="triangle", vertices=((-0.3, -0.2), (0.3, -0.2), (0.0, 0.2))),
            *VSCR.obstacles[1:],
        )
    }
)
BARE = VSCR.model_copy(update={"obstacles": ()})

positions = st.tuples(st.floats(-1.9, 1.9), st.floats(-1.9, 1.9))


@pytest.mark.parametrize("robot", [VSCR, TRIANGLE], ids=["circles", "triangle"])
@settings(max_examples=60, deadline=None)
@given(p=st.lists(positions, min_size=1, max_size=8))
def test_obstacles_met_agrees_with_shapely(robot, p):
    met = obstacles_met(robot, p)
    ref, near = contacts(robot, p)
    decided = ~near
    np.testing.assert_array_equal(met[decided], ref[decided])
    status = ik_status(robot, np.asarray(p, float))[1]
    wrapped = (ref >= 0) & decided
    assert (status[wrapped] != CABLE_OK).all()


@settings(max_examples=40, deadline=None)
@given(p=positions)
def test_clear_pose_answers_as_without_obstacles_and_wrapped_pose_is_refused(p):
    ref, near = contacts(VSCR, [p])
    if near.any():
        return
    if (ref < 0).all():
        ik, bare = inverse_kinematics(VSCR, p), inverse_kinematics(BARE, p)
        np.testing.assert_array_equal(ik.lengths, bare.lengths)
        np.testing.assert_array_equal(ik.structure_matrix, bare.structure_matrix)
        t, tb = distribute_tensions(VSCR, p), distribute_tensions(BARE, p)
        assert t.feasible == tb.feasible
        np.testing.assert_array_equal(t.tensions, tb.tensions)
        return
    i = int(np.flatnonzero(ref[0] >= 0)[0])
    j = int(ref[0, i])
    for f in (inverse_kinematics, distribute_tensions):
        with pytest.raises(WrappedCableError, match=rf"cable {i + 1} meets obstacle {j + 1} \(object {j + 1}\)"):
            f(VSCR, p)


def test_wrapped_error_is_an_infeasible_pose_with_the_reason():
    with pytest.raises(InfeasiblePoseError) as exc:
        inverse_kinematics(VSCR, [0, -0.7])
    msg = str(exc.value)
    assert "\n" not in msg
    assert "its wrapped length depends on the motion; taut trajectory models the wrapping" in msg


def test_batch_marks_wrapped_poses_not_ok():
    rng = np.random.default_rng(5)
    p = rng.uniform(-1.9, 1.9, (200, 2))
    ref, near = contacts(VSCR, p)
    _, W, ok = batch_structure_matrices(VSCR, p)
    _, Wb, okb = batch_structure_matrices(BARE, p)
    wrapped = (ref >= 0).any(axis=1)
    decided = ~near.any(axis=1)
    assert wrapped[decided].any() and (~wrapped[decided]).any()
    np.testing.assert_array_equal(ok[decided], (okb & ~wrapped)[decided])
    np.testing.assert_array_equal(W[ok], Wb[ok])
    assert not W[~ok].any()


def test_refuse_wrapped_names_the_first_time():
    refuse_wrapped(VSCR, [[0.75, -0.5], [0.8, -0.5]])
    refuse_wrapped(BARE, [[0, -0.7]])
    with pytest.raises(WrappedCableError, match=r"at t = 2 s of a test cable 1 meets obstacle 2"):
        refuse_wrapped(VSCR, [[0.75, -0.5], [0, -0.7]], times=[1, 2], what="of a test")


def test_polygon_obstacle_in_space_is_refused():
    from taut.errors import UnsupportedRobotError
    from taut.model import example

    robot = example("spatial-8cable")
    robot = robot.model_copy(
        update={"obstacles": (Polygon(kind="polygon", vertices=((0, 0, 0), (1, 0, 0), (0, 1, 0))),)}
    )
    with pytest.raises(UnsupportedRobotError, match="polygon in space"):
        obstacles_met(robot, np.zeros(6))


def test_a_sphere_in_space_meets_the_cables_through_it():
    from taut.kinematics import anchors_at, default_guess
    from taut.model import Circle, example

    robot = example("spatial-8cable")
    q = default_guess(robot)
    mid = 0.5 * (robot.exits[0] + anchors_at(robot, q[None])[0, 0])
    ball = robot.model_copy(update={"obstacles": (Circle(kind="circle", center=tuple(mid), radius=0.01),)})
    met = obstacles_met(ball, q)
    assert met[0] == 0
    # the others: by their distance to the centre along 1000 points of each cable
    b = anchors_at(robot, q[None])[0]
    s = np.linspace(0, 1, 1001)[:, None, None]
    points = robot.exits[None] + s * (b - robot.exits)[None]
    far = np.linalg.norm(points - mid, axis=-1).min(axis=0) > 0.011
    assert (met[far] == -1).all()
    with pytest.raises(WrappedCableError, match="cable 1 meets obstacle 1 as a straight line"):
        inverse_kinematics(ball, q)
