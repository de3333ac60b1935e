"""Trajectories: angular rates against rotation matrices, the short way between angles, via
points, jointed platforms, robot-file trajectories, sampling and bad input."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.interpolate import CubicSpline

import taut
from taut.errors import TautError, TrajectoryError
from taut.geometry import rotation_matrix
from taut.model import Trajectory, robot_from_dict
from taut.motion import Motion, robot_trajectory, trajectory_from_robot, trajectory_from_waypoints, unwrap_angles

SPATIAL = taut.example("spatial-8cable")  # xyz-fixed
JOINTED = taut.example("adjustable-8cable")  # xyz-moving, prismatic joint s23
ROBOCRANE = taut.example("robocrane")  # tilt-torsion
PLANAR = taut.example("planar-4cable")
AGRICULTURE = taut.example("vscr-agriculture")  # point mass, waypoints by position, speed and dwell
ROBOTS = {r.orientation: r for r in (SPATIAL, JOINTED, ROBOCRANE)}

angle = st.floats(-math.pi, math.pi)
angles = st.tuples(angle, angle, angle)


def _spatial_waypoints(robot, orientations):
    W = np.zeros((len(orientations), robot.pose_size))
    W[:, 3:6] = orientations
    W[:, :3] = np.linspace([0.1, 0.2, 0.3], [0.4, 0.1, 0.5], len(orientations))
    if robot.n_joints:
        W[:, 6] = 2.0
    return W


def _skew(W):
    return np.stack([W[..., 2, 1], W[..., 0, 2], W[..., 1, 0]], axis=-1)


@pytest.mark.parametrize("convention", sorted(ROBOTS))
@settings(max_examples=20, deadline=None)
@given(orientations=st.lists(angles, min_size=2, max_size=4), law=st.sampled_from(["cubic", "quintic"]))
def test_angular_velocity_and_acceleration_match_rotation_matrices(convention, orientations, law):
    robot = ROBOTS[convention]
    m = trajectory_from_waypoints(robot, _spatial_waypoints(robot, orientations), durations=1.0, law=law, via="average")
    h = 1e-4
    t = np.linspace(h, m.duration - h, 23)[1:-1]
    t = t[np.min(np.abs(t[:, None] - m.breaks[None, :]), axis=1) > 2 * h]
    s = m.at(t)

    def R(times):
        return rotation_matrix(m.at(times).poses[:, 3:6], convention)

    R0, Rp, Rm = R(t), R(t + h), R(t - h)
    Rd = (Rp - Rm) / (2 * h)
    Rdd = (Rp - 2 * R0 + Rm) / h**2
    omega = Rd @ np.swapaxes(R0, 1, 2)  # [ω]× = Ṙ Rᵀ
    assert np.allclose(omega, -np.swapaxes(omega, 1, 2), atol=1e-5)
    assert np.allclose(s.angular_velocity, _skew(omega), atol=1e-5 * (1 + np.abs(s.angular_velocity).max()))
    # [α]× = d/dt(Ṙ Rᵀ) = R̈ Rᵀ + Ṙ Ṙᵀ
    alpha = Rdd @ np.swapaxes(R0, 1, 2) + Rd @ np.swapaxes(Rd, 1, 2)
    scale = 1 + np.abs(s.angular_acceleration).max()
    assert np.allclose(s.angular_acceleration, _skew(alpha), atol=1e-3 * scale)


@pytest.mark.parametrize("convention", sorted(ROBOTS))
@settings(max_examples=15, deadline=None)
@given(
    orientations=st.lists(angles, min_size=2, max_size=4),
    law=st.sampled_from(["linear", "cubic", "quintic", "trapezoidal"]),
)
def test_axis_rotation_turns_about_one_axis(convention, orientations, law):
    """``rotation="axis"``: each segment is ``R_s Exp(σ(t) θ k)`` with ``θ k`` the rotation
    vector of ``R_sᵀ R_e`` (scipy) and ``σ`` the time law's fraction (the positions' own),
    the angles continuous, ``ω`` along the fixed axis ``R_s k`` and equal to ``Ṙ Rᵀ``."""
    from scipy.spatial.transform import Rotation

    robot = ROBOTS[convention]
    W = _spatial_waypoints(robot, orientations)
    try:
        m = trajectory_from_waypoints(robot, W, durations=1.0, law=law, rotation="axis")
    except TrajectoryError as e:  # a turn through the gimbal lock is refused, by name
        assert "gimbal lock" in str(e)
        return
    assert m.rotation == "axis"
    assert np.allclose(
        rotation_matrix(m.waypoints[:, 3:6], convention), rotation_matrix(W[:, 3:6], convention), atol=1e-9
    )
    h = 1e-5
    for k in range(len(W) - 1):
        t = np.linspace(k + 2 * h, k + 1 - 2 * h, 9)
        s = m.at(t)
        Rs, Re = rotation_matrix(W[k, 3:6], convention), rotation_matrix(W[k + 1, 3:6], convention)
        rotvec = Rotation.from_matrix(Rs.T @ Re).as_rotvec()
        d = W[k + 1, 0] - W[k, 0]
        sigma = (s.poses[:, 0] - W[k, 0]) / d  # x moves by the same time law
        got = rotation_matrix(s.poses[:, 3:6], convention)
        if np.linalg.norm(rotvec) > np.pi - 1e-6 and not np.allclose(
            got, Rs @ Rotation.from_rotvec(sigma[:, None] * rotvec).as_matrix(), atol=1e-9
        ):
            rotvec = -rotvec  # a half turn goes either way about its axis
        want = Rs @ Rotation.from_rotvec(sigma[:, None] * rotvec).as_matrix()
        assert np.allclose(got, want, atol=1e-9)
        axis = Rs @ rotvec
        assert np.allclose(s.angular_velocity, np.outer(s.velocity[:, 0] / d, axis), atol=1e-9)
        assert np.allclose(s.angular_acceleration, np.outer(s.acceleration[:, 0] / d, axis), atol=1e-9)
        Rd = (
            rotation_matrix(m.at(t + h).poses[:, 3:6], convention)
            - rotation_matrix(m.at(t - h).poses[:, 3:6], convention)
        ) / (2 * h)
        omega = Rd @ np.swapaxes(rotation_matrix(s.poses[:, 3:6], convention), 1, 2)
        assert np.allclose(s.angular_velocity, _skew(omega), atol=1e-5 * (1 + np.abs(s.angular_velocity).max()))
    # continuous: no 2π jump.  Each sample step is within the largest rate times the time
    # step, except next to the gimbal lock (|cos b|, |sin θ| below 1e-2), where the angles'
    # rates grow as the inverse distance and may peak between samples: there a step stays
    # below 2π (an outer angle swings through π at most).
    dense = m.at(np.linspace(0, m.duration, 2001))
    step = np.abs(np.diff(dense.poses[:, 3:6], axis=0)).max(axis=1)
    middle = dense.poses[:, 4]
    lock = np.abs(np.sin(middle) if convention == "tilt-torsion" else np.cos(middle))
    near = np.minimum(lock[:-1], lock[1:]) < 1e-2
    assert np.all(step[near] < 2 * np.pi - 0.5)
    assert np.all(step[~near] <= 1.5 * np.abs(dense.velocity[:, 3:6]).max() * m.duration / 2000 + 1e-12)


def test_axis_rotation_refusals():
    W = _spatial_waypoints(SPATIAL, [[0.0, 1.4, 0.0], [math.pi, math.pi - 1.8, math.pi]])  # Ry(1.4) → Ry(1.8)
    with pytest.raises(TrajectoryError, match="segment 1 turns through the gimbal lock of the xyz-fixed angles"):
        trajectory_from_waypoints(SPATIAL, W, durations=1.0, rotation="axis")
    W = _spatial_waypoints(SPATIAL, [[0.0, 0.1, 0.0], [0.2, 0.3, 0.1]])
    for kwargs, message in [
        (dict(law="cubic", via="average", rotation="axis"), "rotation='axis' stops the turn at every waypoint"),
        (
            dict(law="cubic", velocities=[[0, 0, 0, 0.1, 0, 0], [0] * 6], rotation="axis"),
            "velocities at waypoint 1: with rotation='axis'",
        ),
        (dict(rotation="quaternion"), "unknown rotation 'quaternion'"),
    ]:
        with pytest.raises(TrajectoryError, match=message):
            trajectory_from_waypoints(SPATIAL, W, durations=1.0, **kwargs)
    with pytest.raises(TrajectoryError, match="stops the turn at every waypoint and is timed by durations"):
        trajectory_from_waypoints(SPATIAL, W, rotation="axis", max_velocity=1.0, max_acceleration=1.0)
    with pytest.raises(TrajectoryError, match="rotation='axis' turns a spatial rigid platform"):
        trajectory_from_waypoints(PLANAR, [[0.3, 0.3, 0.0], [0.4, 0.3, 1.0]], durations=1.0, rotation="axis")
    # translations may move through a waypoint while the turn stops there
    m = trajectory_from_waypoints(
        SPATIAL, W, durations=1.0, law="cubic", velocities=[[0.1, 0, 0, 0, 0, 0], [0] * 6], rotation="axis"
    )
    assert m.at([0.0]).velocity[0] == pytest.approx([0.1, 0, 0, 0, 0, 0])


def test_planar_and_point_mass_angular_rates():
    m = trajectory_from_waypoints(PLANAR, [[0.3, 0.3, -0.2], [0.6, 0.5, 0.4]], durations=2.0)
    s = m.sample(50)
    assert s.angular_velocity.shape == (len(s.times), 1)
    assert np.array_equal(s.angular_velocity[:, 0], s.velocity[:, 2])  # ω = θ̇
    assert np.array_equal(s.angular_acceleration[:, 0], s.acceleration[:, 2])
    point = trajectory_from_waypoints(AGRICULTURE, [[0, 0.3], [0.1, 0.5]], durations=1.0).sample(10)
    assert point.angular_velocity.shape == (11, 0)


@pytest.mark.parametrize("convention", sorted(ROBOTS))
def test_angles_take_the_short_way_across_pi(convention):
    robot = ROBOTS[convention]
    start, end = [3.0, 0.3, -3.1], [-3.0, 0.2, 3.05]
    W = _spatial_waypoints(robot, [start, end])
    m = trajectory_from_waypoints(robot, W, durations=1.0)
    s = m.sample(200)
    # each angle moves by less than π: 3.0 → 2π − 3.0 (0.283 rad), −3.1 → 3.05 − 2π (0.133 rad)
    travel = np.abs(s.poses[-1, 3:6] - s.poses[0, 3:6])
    assert travel == pytest.approx([2 * math.pi - 6.0, 0.1, 2 * math.pi - 6.15])
    assert np.all(np.abs(np.diff(s.poses[:, 3:6], axis=0)) < 0.01)
    # the end is the waypoint's rotation
    assert np.allclose(rotation_matrix(s.poses[-1, 3:6], convention), rotation_matrix(end, convention), atol=1e-12)
    # without unwrapping the long way is kept (a deliberate turn)
    long = trajectory_from_waypoints(robot, W, durations=1.0, unwrap=False).sample(200)
    assert np.abs(long.poses[-1, 3] - long.poses[0, 3]) == pytest.approx(6.0)


@settings(max_examples=60, deadline=None)
@given(orientations=st.lists(st.tuples(*[st.floats(-20, 20)] * 3), min_size=2, max_size=5))
def test_unwrap_keeps_each_rotation_and_steps_at_most_pi(orientations):
    for convention, robot in ROBOTS.items():
        W = _spatial_waypoints(robot, orientations)
        U = unwrap_angles(robot, W)
        assert np.all(np.abs(np.diff(U[:, 3:6], axis=0)) <= math.pi + 1e-9)
        assert np.allclose(rotation_matrix(U[:, 3:6], convention), rotation_matrix(W[:, 3:6], convention), atol=1e-9)
        assert np.array_equal(U[0], W[0]) and np.array_equal(U[:, :3], W[:, :3])
        assert np.allclose((U[:, 3:6] - W[:, 3:6]) / (2 * math.pi), np.round((U[:, 3:6] - W[:, 3:6]) / (2 * math.pi)))


def test_planar_angle_unwraps_too():
    m = trajectory_from_waypoints(PLANAR, [[0.3, 0.3, 3.1], [0.3, 0.3, -3.1]], durations=1.0)
    assert m.waypoints[1, 2] == pytest.approx(2 * math.pi - 3.1)


def test_gimbal_lock_waypoint_gives_finite_exact_rates():
    # b = π/2 (xyz-fixed) and tilt θ = 0 (tilt-torsion): E(q) is singular there, but ω = E q̇
    # needs no inverse: the rates stay finite and match R(q(t))
    for robot, locked in ((SPATIAL, [0.2, math.pi / 2, -0.4]), (ROBOCRANE, [0.7, 0.0, 0.3])):
        W = _spatial_waypoints(robot, [[0.0, 0.3, 0.0], locked, [0.3, 0.2, 0.1]])
        m = trajectory_from_waypoints(robot, W, durations=1.0, law="cubic", via="spline")
        h = 1e-6
        s = m.at([1.0])
        Rd = (
            rotation_matrix(m.at([1 + h]).poses[:, 3:6], robot.orientation)
            - rotation_matrix(m.at([1 - h]).poses[:, 3:6], robot.orientation)
        ) / (2 * h)
        omega = Rd @ np.swapaxes(rotation_matrix(s.poses[:, 3:6], robot.orientation), 1, 2)
        assert np.all(np.isfinite(s.angular_velocity))
        assert np.allclose(s.angular_velocity, _skew(omega), atol=1e-6)


def test_via_points_continuity_and_independent_spline():
    W = np.array(
        [[0.1, 0.1, 0.1, 0, 0, 0], [0.4, 0.2, 0.3, 0.2, 0, 0], [0.2, 0.5, 0.2, 0.1, 0.3, 0], [0.5, 0.5, 0.5, 0, 0, 0.4]]
    )
    d = [1.0, 0.7, 1.5]
    t = np.concatenate([[0], np.cumsum(d)])
    eps = 1e-9
    for law, via in (("cubic", "average"), ("quintic", "average"), ("cubic", "spline"), ("quintic", "stop")):
        m = trajectory_from_waypoints(SPATIAL, W, durations=d, law=law, via=via)
        left, right = m.at(t[1:-1] - eps), m.at(t[1:-1] + eps)
        assert np.allclose(left.poses, W[1:-1], atol=1e-8)
        assert np.allclose(left.poses, right.poses, atol=1e-8)
        assert np.allclose(left.velocity, right.velocity, atol=1e-6)
        if law == "quintic" or via == "spline":
            assert np.allclose(left.acceleration, right.acceleration, atol=1e-6)
        if via == "stop":
            assert np.allclose(left.velocity, 0, atol=1e-6)
        if via == "average":
            slopes = np.diff(W, axis=0) / np.array(d)[:, None]
            assert np.allclose(left.velocity, (slopes[:-1] + slopes[1:]) / 2, atol=1e-6)
    # the spline against scipy's clamped cubic spline
    m = trajectory_from_waypoints(SPATIAL, W, durations=d, law="cubic", via="spline")
    ref = CubicSpline(t, W, bc_type="clamped")
    tt = np.linspace(0, t[-1], 157)
    s = m.at(tt)
    assert np.allclose(s.poses, ref(tt), atol=1e-12)
    assert np.allclose(s.velocity, ref(tt, 1), atol=1e-10)
    assert np.allclose(s.acceleration, ref(tt, 2), atol=1e-9)
    # a cubic with average velocities has an acceleration jump at the via points
    m = trajectory_from_waypoints(SPATIAL, W, durations=d, law="cubic", via="average")
    assert not np.allclose(m.at(t[1:-1] - eps).acceleration, m.at(t[1:-1] + eps).acceleration, atol=1e-3)


def test_jointed_platform_joint_coordinates():
    # simulation a of the adjustable platform: z descends, then z and s23 move together
    m = trajectory_from_robot(JOINTED, "sim-a", duration=4.0)
    assert list(m.times) == [0.0, 2.0, 4.0]  # steps [100, 100] share the duration equally
    s = m.sample(100)
    first, second = s.times <= 2.0, s.times >= 2.0
    assert np.all(s.poses[first, 6] == 2.0) and np.all(s.velocity[first, 6] == 0.0)
    # second move: a straight line in pose space, s23 rises as fast as z falls
    assert np.allclose(s.poses[second, 6] - 2.0, -(s.poses[second, 2] - 2.5), atol=1e-12)
    lo, hi = JOINTED.joint_limits[0]
    assert s.poses[:, 6].min() >= lo and s.poses[:, 6].max() <= hi
    tau = (s.times[second] - 2.0) / 2.0
    assert np.allclose(s.poses[second, 6], 2.0 + 2.0 * (10 * tau**3 - 15 * tau**4 + 6 * tau**5), atol=1e-12)


def test_robot_trajectory_steps_share_the_duration():
    tr = JOINTED.trajectories["sim-a"].model_copy(update={"steps": (100, 300)})
    robot = JOINTED.model_copy(update={"trajectories": {"uneven": tr}})
    m = trajectory_from_robot(robot, "uneven", duration=4.0, law="cubic")
    assert m.times.tolist() == [0.0, 1.0, 4.0]
    assert np.allclose(m.at(m.times).poses, tr.waypoints)


def test_a_spline_that_overshoots_a_joint_limit_is_refused():
    W = np.array(
        [[5, 5, 4.5, 0, 0, 0, 0.5], [5, 5, 4.0, 0, 0, 0, 4.4], [5, 5, 3.5, 0, 0, 0, 4.5], [5, 5, 3.0, 0, 0, 0, 0.5]]
    )
    with pytest.raises(TrajectoryError, match=r"joint s23 reaches .* outside its limits \[0.4, 4.5\]"):
        trajectory_from_waypoints(JOINTED, W, durations=[1.0, 0.2, 1.0], law="cubic", via="spline")
    trajectory_from_waypoints(JOINTED, W, durations=[1.0, 0.2, 1.0], law="cubic")  # stopping at each: inside


def test_robot_trajectory_with_speed_and_dwell():
    tr = Trajectory(waypoints=((0, 0.991), (0, 0.229), (0.279, 0.991)), speed=0.2, dwell=0.5)
    robot = AGRICULTURE.model_copy(update={"trajectories": {"timed": tr}})
    m = trajectory_from_robot(robot, "timed", law="trapezoidal")
    P = np.array(tr.waypoints)
    moves = np.linalg.norm(np.diff(P, axis=0), axis=1) / tr.speed
    assert m.duration == pytest.approx(len(P) * tr.dwell + moves.sum())
    # held at each waypoint for the dwell, at rest
    for k, start in enumerate(np.concatenate([[0], np.cumsum(moves + tr.dwell)])):
        s = m.at(np.linspace(start, start + tr.dwell, 7))
        assert np.allclose(s.poses, P[k]) and np.allclose(s.velocity, 0)
    with pytest.raises(TrajectoryError, match="dwells at its waypoints"):
        trajectory_from_robot(robot, "timed", law="cubic", via="average")
    # the agriculture robot's own trajectory gives a dwell but no speed
    with pytest.raises(TrajectoryError, match="gives no speed: give its duration"):
        trajectory_from_robot(AGRICULTURE, "table-6.2")
    m = trajectory_from_robot(AGRICULTURE, "table-6.2", duration=10.0)
    assert m.duration == pytest.approx(10.0) and len(m.times) == len(AGRICULTURE.trajectories["table-6.2"].waypoints)
    with pytest.raises(TrajectoryError, match="no trajectory 'nope'"):
        trajectory_from_robot(JOINTED, "nope", duration=1.0)


def test_robot_trajectory_reads_the_file_once_for_every_user():
    """:func:`robot_trajectory` is the one reader of ``trajectories:``: waypoints as poses
    (positions completed from the first reference pose), steps, speed, dwell; the timed
    motion, the collision checks' pose sequence and the wrapping cables' samples start from
    it and refuse an unknown name with its one message."""
    from taut.collision import straight_moves, trajectory_poses
    from taut.wrapping import builtin_trajectory, timed_moves

    sim = robot_trajectory(JOINTED, "sim-a")
    assert sim.name == "sim-a" and sim.steps == (100, 100) and sim.speed is None and sim.dwell == 0.0
    assert sim.waypoints.tolist() == [[5, 5, 4.5, 0, 0, 0, 2], [5, 5, 2.5, 0, 0, 0, 2], [5, 5, 0.5, 0, 0, 0, 4]]
    assert not sim.waypoints.flags.writeable and "Simulation a)" in sim.description
    assert json.loads(json.dumps(sim.as_dict(), allow_nan=False))["steps"] == [100, 100]
    assert robot_trajectory(JOINTED).name == next(iter(JOINTED.trajectories))  # the first by default
    # positions only: the rest of the pose from the first reference pose (orientation, s23 = 2)
    moved = Trajectory(waypoints=((5, 5, 4), (5, 4, 3)), speed=0.5, dwell=1.0)
    robot = JOINTED.model_copy(update={"trajectories": {"moved": moved}})
    tr = robot_trajectory(robot, "moved")
    assert tr.waypoints.tolist() == [[5, 5, 4, 0, 0, 0, 2], [5, 4, 3, 0, 0, 0, 2]]
    assert (tr.speed, tr.dwell) == (0.5, 1.0)
    # its users: 201 poses on straight moves, a timed motion, time samples at speed with dwell
    poses = trajectory_poses(JOINTED, "sim-a")
    assert np.array_equal(poses, straight_moves(JOINTED, sim.waypoints, sim.steps)) and len(poses) == 201
    assert np.allclose(poses[100], sim.waypoints[1]) and np.allclose(
        poses[50], (sim.waypoints[0] + sim.waypoints[1]) / 2
    )
    assert trajectory_from_robot(robot, "moved").duration == pytest.approx(2 * 1.0 + math.sqrt(2) / 0.5)
    agri = robot_trajectory(AGRICULTURE, "table-6.2")
    t, P = builtin_trajectory(AGRICULTURE, "table-6.2", speed=0.2)
    t2, P2 = timed_moves(agri.waypoints, speed=0.2, dwell=agri.dwell, dt=0.01)
    assert np.array_equal(t, t2) and np.array_equal(P, P2) and np.allclose(P[-1], agri.waypoints[-1])
    moves = np.linalg.norm(np.diff(agri.waypoints, axis=0), axis=1).sum() / 0.2
    assert t[-1] == pytest.approx(moves + len(agri.waypoints) * agri.dwell)
    for read in (
        lambda: robot_trajectory(JOINTED, "nope"),
        lambda: trajectory_from_robot(JOINTED, "nope", duration=1.0),
        lambda: trajectory_poses(JOINTED, "nope"),
        lambda: builtin_trajectory(JOINTED, "nope"),
    ):
        with pytest.raises(
            TrajectoryError, match=r"adjustable.*: no trajectory 'nope' \(it has: sim-a, sim-b, sim-c, sim-d\)"
        ):
            read()
    with pytest.raises(TrajectoryError, match="has no trajectories"):
        robot_trajectory(SPATIAL)


def test_samples_and_immutability():
    m = trajectory_from_waypoints(PLANAR, [[0.3, 0.3, 0], [0.6, 0.5, 0.4], [0.4, 0.6, 0.0]], durations=[1.0, 0.75])
    s = m.sample(4)
    assert np.allclose(s.times, [0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5, 1.75])
    s = m.sample(3)  # 1.75 s is not a whole number of steps: the end is added
    assert np.allclose(s.times, [0, 1 / 3, 2 / 3, 1.0, 4 / 3, 5 / 3, 1.75])
    assert np.allclose(s.poses[-1], m.waypoints[-1])
    shuffled = m.at([1.2, 0.1, 0.5])
    assert np.allclose(
        shuffled.poses, m.at([1.2]).poses.tolist() + m.at([0.1]).poses.tolist() + m.at([0.5]).poses.tolist()
    )
    assert s.pose_names == ("x", "y", "theta")
    for a in (s.poses, s.velocity, s.angular_velocity, m.coefficients, m.waypoints, m.times):
        with pytest.raises(ValueError):
            a[0] = 1.0
    with pytest.raises(AttributeError):
        m.law = "cubic"  # type: ignore[misc]
    assert isinstance(m, Motion) and m.duration == 1.75


def test_results_are_frozen_and_json():
    """docs/architecture.md §2.7: ``as_dict`` in plain JSON types, the values round-trip."""
    m = trajectory_from_waypoints(PLANAR, [[0.3, 0.3, 0], [0.6, 0.5, 0.4]], durations=[1.5], law="cubic")
    s = m.sample(10)
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.times = s.times[:1]  # type: ignore[misc]
    back = json.loads(json.dumps(s.as_dict(), allow_nan=False))
    assert back["times"] == s.times.tolist() and back["poses"] == s.poses.tolist()
    assert back["angular_velocity"] == s.angular_velocity.tolist() and back["pose_names"] == ["x", "y", "theta"]
    motion = json.loads(json.dumps(m.as_dict(), allow_nan=False))
    assert motion["robot"] == PLANAR.name and motion["law"] == "cubic" and motion["duration"] == 1.5
    assert motion["waypoints"] == [[0.3, 0.3, 0], [0.6, 0.5, 0.4]] and motion["times"] == [0.0, 1.5]
    assert np.array(motion["coefficients"]).shape == m.coefficients.shape


BAD = [
    (dict(waypoints=[[0.3, 0.3, 0]], durations=1.0), "at least 2 waypoints, got 1"),
    (dict(waypoints=[], durations=1.0), "at least 2 waypoints, got none"),
    (dict(waypoints=[[0.3, 0.3, 0, 1], [0.4, 0.3, 0, 1]], durations=1.0), "takes poses of 3 coordinates"),
    (dict(waypoints=[[0.3, 0.3, 0], [np.nan, 0.3, 0]], durations=1.0), "waypoint 2, coordinate x is not finite"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=0.0), "durations must be finite numbers > 0"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=-1.0), "durations must be finite numbers > 0"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=np.inf), "durations must be finite numbers > 0"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], duration=np.nan), "duration must be finite numbers > 0"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0], [0.5, 0.3, 0]], times=[0, 1, 1]), "times must increase"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0], [0.5, 0.3, 0]], times=[0, 2, 1]), "times must increase"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], times=[1, 2]), "times must start at 0"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=[1.0, 2.0]), "expected one number or 1"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]]), "give exactly one of durations"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, duration=1.0), "got durations, duration"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, law="septic"), "unknown time law 'septic'"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, via="magic"), "unknown via-point velocities"),
    (
        dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, law="trapezoidal", via="average"),
        "fixes the velocities at the waypoints",
    ),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, law="quintic", via="spline"), "law='cubic'"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, law="trapezoidal", blend=0.6), "<= 0.5"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.3, 0.3, 0]], duration=1.0), "coincide"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.3, 0.3, 0]], max_velocity=1.0, max_acceleration=1.0), "coincide"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], max_velocity=1.0), "needs max_velocity and max_acceleration"),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], max_velocity=-1.0, max_acceleration=1.0), "max_velocity must be"),
    (
        dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0, law="cubic", velocities=[[0, 0, 0]]),
        "one per waypoint",
    ),
    (dict(waypoints=[[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1e-300), "too short for its change of pose"),
    (dict(waypoints="abc", durations=1.0), "lists of numbers"),
]


@pytest.mark.parametrize(("kwargs", "message"), BAD, ids=[m for _, m in BAD])
def test_bad_input_raises_one_clear_typed_error(kwargs, message):
    kwargs = dict(kwargs)
    waypoints = kwargs.pop("waypoints")
    with pytest.raises(TrajectoryError, match=message.replace("(", r"\(").replace("[", r"\[")) as info:
        trajectory_from_waypoints(PLANAR, waypoints, **kwargs)
    assert isinstance(info.value, TautError) and "\n" not in str(info.value)


def test_bad_samples():
    m = trajectory_from_waypoints(PLANAR, [[0.3, 0.3, 0], [0.4, 0.3, 0]], durations=1.0)
    for rate in (0, -1, np.nan, np.inf, "10"):
        with pytest.raises(TrajectoryError, match="sampling rate must be a finite number > 0"):
            m.sample(rate)  # type: ignore[arg-type]
    with pytest.raises(TrajectoryError, match=r"outside the trajectory's \[0, 1\] s"):
        m.at([0.5, 1.5])
    with pytest.raises(TrajectoryError, match="must be finite"):
        m.at([np.nan])
    with pytest.raises(TrajectoryError, match="at most"):
        m.sample(1e9)


def test_joint_limits_of_waypoints_and_position_only_waypoints():
    with pytest.raises(TrajectoryError, match=r"waypoint 2: joint s23 = 5 is outside its limits"):
        trajectory_from_waypoints(JOINTED, [[5, 5, 4, 0, 0, 0, 2], [5, 5, 4, 0, 0, 0, 5]], durations=1.0)
    # positions are completed from the first reference pose
    m = trajectory_from_waypoints(JOINTED, [[5, 5, 4], [5, 5, 3]], durations=1.0)
    assert np.allclose(m.waypoints[:, 3:], [[0, 0, 0, 2], [0, 0, 0, 2]])
    bare = robot_from_dict(
        {
            "name": "bare",
            "dimension": 2,
            "platform": {"kind": "rigid"},
            "cables": [{"exit": [0, 0], "anchor": [0, 0]}, {"exit": [1, 0], "anchor": [0, 0]}],
        }
    )
    assert np.allclose(trajectory_from_waypoints(bare, [[0, 1], [1, 1]], durations=1.0).waypoints[:, 2], 0.0)


@pytest.mark.parametrize("waypoints", ["ab", [[0.1, 0.2]], np.zeros((2, 2, 3))])
def test_unwrap_angles_refuses_what_is_not_poses(waypoints):
    with pytest.raises(TrajectoryError):
        unwrap_angles(PLANAR, waypoints)
