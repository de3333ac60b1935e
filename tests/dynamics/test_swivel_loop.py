"""Swivelling pulleys in the compiled dynamics (``taut.dynamics._tree.cable_path`` in every
kernel, hence in ``simulate_control``): the compiled length and direction are those of the
pulley kinematics (``taut.kinematics.swivel_paths``) and the direction is the gradient of
that length (finite differences), and the control loop tracks with the distribution solving
the kinematics' structure matrix through the tangent points."""

import numpy as np
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taut
from taut.dynamics import simulate_control
from taut.dynamics._tree import CABLE_COLUMNS, cable_path
from taut.kinematics import structure_matrix, swivel_paths
from taut.motion import trajectory_from_waypoints
from taut.statics import external_wrench

from .conftest import SPATIAL_INERTIA, with_platform

coordinate = st.floats(-3.0, 3.0)
EXIT = np.array([0.2, -0.1, 0.3])


def kinematics_length(k, radius, b):
    return swivel_paths([EXIT], [k], [radius], [[b]]).lengths[0, 0]


@settings(max_examples=200, deadline=None)
@given(
    anchor=st.tuples(coordinate, coordinate, coordinate),
    axis=st.tuples(coordinate, coordinate, coordinate).filter(lambda v: np.linalg.norm(v) > 0.1),
    radius=st.floats(0.01, 0.5),
)
def test_compiled_pulley_path_is_the_kinematics_and_its_direction_the_length_gradient(anchor, axis, radius):
    """Length ``r β + l_f`` and direction ``(C − b)/l_f`` as the kinematics computes them, and
    ``−u = ∂l/∂b`` by central differences of the kinematics' length; an anchor on the swivel
    axis or on the pulley has no direction (−1)."""
    k = np.array(axis) / np.linalg.norm(axis)
    b = np.array(anchor)
    row = np.zeros(CABLE_COLUMNS)
    row[:3], row[8:11], row[11] = EXIT, k, radius
    u = np.empty(3)
    length = cable_path(row, b, u)
    paths = swivel_paths([EXIT], [k], [radius], [[b]])
    if paths.on_axis[0, 0] or paths.on_pulley[0, 0]:
        assert length == -1.0
        return
    C = paths.tangent_points[0, 0]
    free = np.linalg.norm(C - b)
    assume(free > 1e-3 and np.linalg.norm(np.cross(b - EXIT, k)) > 1e-3)
    assert abs(length - paths.lengths[0, 0]) <= 1e-12 * (1 + length)
    np.testing.assert_allclose(u, (C - b) / free, atol=1e-9)
    step = 1e-6
    grad = [
        (kinematics_length(k, radius, b + e) - kinematics_length(k, radius, b - e)) / (2 * step)
        for e in np.eye(3) * step
    ]
    np.testing.assert_allclose(-u, grad, atol=1e-6)


def test_control_through_swivelling_pulleys():
    """spatial-8cable with 3 cm pulleys at its exits (axes vertical), exact model: the loop
    tracks a 0.3 rad turn and a 25 cm move within 1e-5 (measured 5e-6 rad on the yaw, the
    zero-order hold), and at the end, at rest, the tensions
    it applies hold the platform's weight through the kinematics' structure matrix (the
    directions to the tangent points)."""
    robot = with_platform(taut.example("spatial-8cable"), inertia=SPATIAL_INERTIA, wrench_point=(0.02, -0.01, 0.03))
    pulleys = {"swivel": {"axis": (0, 0, 1), "radius": 0.03}}
    robot = robot.model_copy(update={"cables": tuple(c.model_copy(update=pulleys) for c in robot.cables)})
    goal = [0.2, 0.1, 0.1, 0.05, -0.05, 0.3]
    motion = trajectory_from_waypoints(robot, [[0, 0, 0, 0, 0, 0], goal], duration=1.0)
    run = simulate_control(robot, motion, method="qp")
    assert run.all_feasible and run.tracking_error_max.max() < 1e-5, run.tracking_error_max
    q = run.poses[-1]
    residual = structure_matrix(robot, q) @ run.tensions[-1] + external_wrench(robot, q)
    assert np.abs(residual).max() < 1e-3 * np.abs(run.tensions[-1]).max()
