"""Swivelling exit pulleys (Pott 2018, pulley kinematics): lengths with the wound arc, the
structure matrix with the moving tangent point, singular configurations, and every analysis
that goes through the inverse kinematics.

The reference computations here do not use taut's pulley formulas: the tangent point is
found by root finding over the pulley's swivel angle and wrap angle, the lengths are
differentiated by finite differences, and the two-``arccos`` wrap angle of WireX's
``doInverseKinematicsPulleyEx`` is checked where it holds."""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import taut
from taut.errors import InfeasiblePoseError, RobotFileError, UnsupportedRobotError
from taut.kinematics import (
    batch_structure_matrices,
    cable_lengths,
    forward_kinematics,
    inverse_kinematics,
    structure_matrix,
)
from taut.kinematics._inverse import ik_status
from taut.model import Robot, robot_from_dict, robot_to_dict

BASE = taut.example("spatial-8cable")
RADIUS = 0.05


def with_swivels(robot: Robot, radius: float, cables: list[int] | None = None) -> Robot:
    """``robot`` with swivelling pulleys of ``radius`` on ``cables`` (all by default), their
    axes vertical and the cables arriving from winches beyond the frame (upwards into the
    lower pulleys, downwards into the upper ones)."""
    data = robot_to_dict(robot)
    for i, c in enumerate(data["cables"]):
        if cables is None or i in cables:
            c["swivel"] = {"axis": [0.0, 0.0, -math.copysign(1.0, c["exit"][2])], "radius": radius}
    return robot_from_dict(data)


ROBOT = with_swivels(BASE, RADIUS)
poses = arrays(float, (6,), elements=st.floats(-0.3, 0.3))


def _basis(k: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    e1 = np.cross(k, [1.0, 0.0, 0.0] if abs(k[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    return e1, np.cross(k, e1)


def reference_path(D: np.ndarray, k: np.ndarray, r: float, b: np.ndarray) -> tuple[float, np.ndarray]:
    """Length and tangent point by root finding: the pulley at swivel angle ``g`` has its
    centre ``D + r n(g)``; the cable wound through ``f`` is at ``P = D + r n − r cos f n +
    r sin f k`` heading ``t = sin f n + cos f k``, and leaves where ``t`` points at ``b``.
    Of the solutions (the pulley turned towards the anchor, or half a turn away with a long
    wrap), the free pulley takes the shortest path."""
    from scipy.optimize import least_squares

    k = k / np.linalg.norm(k)
    e1, e2 = _basis(k)

    def parts(x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        g, f = x
        n = math.cos(g) * e1 + math.sin(g) * e2
        P = D + r * n - r * math.cos(f) * n + r * math.sin(f) * k
        return P, math.sin(f) * n + math.cos(f) * k

    def residual(x: np.ndarray) -> np.ndarray:
        P, t = parts(x)
        return (b - P) / np.linalg.norm(b - P) - t

    # from every swivel angle of a grid, the wrap angle of the grid that comes nearest
    wraps = np.linspace(0, 2 * np.pi, 48)
    starts = [
        (g, min(wraps, key=lambda f: float(np.linalg.norm(residual(np.array([g, f]))))))
        for g in np.linspace(0, 2 * np.pi, 24, endpoint=False)
    ]
    best: tuple[float, np.ndarray] | None = None
    for x0 in starts:
        sol = least_squares(residual, np.array(x0), xtol=1e-15, ftol=1e-15, gtol=1e-15)
        if np.linalg.norm(sol.fun) > 1e-10:
            continue
        g, f = sol.x[0], sol.x[1] % (2 * np.pi)
        P, _ = parts(np.array([g, f]))
        length = r * f + float(np.linalg.norm(b - P))
        if best is None or length < best[0]:
            best = (length, P)
    assert best is not None
    return best


def test_hand_computed_quarter_wrap() -> None:
    """Anchor level with the pulley centre, beyond it: a quarter turn, then straight."""
    data = {
        "name": "one pulley",
        "dimension": 3,
        "platform": {"kind": "point-mass"},
        "cables": [{"exit": [0, 0, 0], "swivel": {"axis": [0, 0, 1], "radius": 0.1}}],
    }
    robot = robot_from_dict(data)
    ik = inverse_kinematics(robot, [0.0, 1.0, 0.1])  # centre (0, 0.1, 0), top of the pulley at z = 0.1
    assert ik.lengths[0] == pytest.approx(0.1 * np.pi / 2 + 0.9)
    np.testing.assert_allclose(ik.exit_points[0], [0, 0.1, 0.1], atol=1e-15)
    np.testing.assert_allclose(ik.directions[0], [0, -1, 0], atol=1e-15)


@settings(max_examples=25, deadline=None)
@given(
    arrays(float, (3,), elements=st.floats(-1, 1)),
    arrays(float, (3,), elements=st.floats(-1, 1)),
    st.floats(0.01, 0.3),
    arrays(float, (3,), elements=st.floats(-2, 2)),
)
def test_tangent_point_and_length_match_root_finding(D: np.ndarray, k: np.ndarray, r: float, b: np.ndarray) -> None:
    assume(np.linalg.norm(k) > 0.1)
    data = {
        "name": "one pulley",
        "dimension": 3,
        "platform": {"kind": "point-mass"},
        "cables": [{"exit": D.tolist(), "swivel": {"axis": k.tolist(), "radius": r}}],
    }
    robot = robot_from_dict(data)
    try:
        ik = inverse_kinematics(robot, b)
    except InfeasiblePoseError:
        assume(False)  # singular configurations are tested on their own below
        return
    kk = k / np.linalg.norm(k)
    v = b - D
    d = float(np.linalg.norm(v - (v @ kk) * kk))
    centre_distance = math.hypot(d - r, float(v @ kk))
    assume(d > 1e-3 and centre_distance > r * 1.001)
    length, tangent = reference_path(D, k, r, b)
    assert ik.lengths[0] == pytest.approx(length, abs=1e-9)
    np.testing.assert_allclose(ik.exit_points[0], tangent, atol=1e-8)
    np.testing.assert_allclose(ik.directions[0], (tangent - b) / np.linalg.norm(tangent - b), atol=1e-7)


@settings(max_examples=40, deadline=None)
@given(
    st.floats(0.01, 0.3),
    st.floats(0.0, 2 * np.pi),
    st.floats(0.02, 3.0),
    st.floats(-3.0, 3.0),
)
def test_wirex_two_arccos_wrap_where_it_holds(r: float, swivel: float, rho_axis: float, height: float) -> None:
    """WireX: ``β = arccos(l_f/‖b − M‖) + arccos(b_z/‖b − M‖)`` in the winch frame, valid for
    anchors at least ``r`` from the axis (for nearer ones the second angle changes sign)."""
    assume(rho_axis >= r * 1.01)
    b = np.array([rho_axis * math.cos(swivel), rho_axis * math.sin(swivel), height])
    BM = math.hypot(rho_axis - r, height)
    assume(BM > r * 1.01)
    lf = math.sqrt(BM**2 - r**2)
    beta = math.acos(lf / BM) + math.acos(height / BM)
    data = {
        "name": "one pulley",
        "dimension": 3,
        "platform": {"kind": "point-mass"},
        "cables": [{"exit": [0, 0, 0], "swivel": {"axis": [0, 0, 1], "radius": r}}],
    }
    assert cable_lengths(robot_from_dict(data), b)[0] == pytest.approx(r * beta + lf, rel=1e-12, abs=1e-12)


def test_wrap_beyond_half_turn_and_anchor_near_the_axis() -> None:
    """Where the two-arccos form fails: the anchor behind the pulley and nearer the axis than
    the centre (a wrap of more than half a turn), and ahead of it near the axis (a small wrap)."""
    r = 0.1
    for b in ([0.05, 0.0, -1.0], [0.05, 0.0, 1.0], [0.02, 0.03, -0.3]):
        D, k = np.zeros(3), np.array([0.0, 0.0, 1.0])
        length, tangent = reference_path(D, k, r, np.array(b))
        data = {
            "name": "one pulley",
            "dimension": 3,
            "platform": {"kind": "point-mass"},
            "cables": [{"exit": [0, 0, 0], "swivel": {"axis": [0, 0, 1], "radius": r}}],
        }
        ik = inverse_kinematics(robot_from_dict(data), b)
        assert ik.lengths[0] == pytest.approx(length, abs=1e-10)
        np.testing.assert_allclose(ik.exit_points[0], tangent, atol=1e-9)
    behind = inverse_kinematics(robot_from_dict(data), [0.05, 0.0, -1.0]).lengths[0]
    assert behind > r * np.pi + 1.0  # more than half a turn wound, then about 1 m down


def _euler_rates(a: float, b: float, c: float) -> np.ndarray:
    """Columns: the angular velocity per unit rate of a, b, c for ``R = Rz(c) Ry(b) Rx(a)``."""
    cb, sb, cc, sc = math.cos(b), math.sin(b), math.cos(c), math.sin(c)
    x = np.array([cc * cb, sc * cb, -sb])  # Rz(c) Ry(b) e_x
    y = np.array([-sc, cc, 0.0])  # Rz(c) e_y
    return np.column_stack([x, y, [0.0, 0.0, 1.0]])


@settings(max_examples=30, deadline=None)
@given(poses, st.floats(0.01, 0.3))
def test_structure_matrix_is_minus_the_length_gradient(pose: np.ndarray, r: float) -> None:
    """``∂l/∂p = −u`` and, through the angular velocity of the xyz-fixed angles,
    ``∂l/∂(a, b, c) = −((R r_i) × u_i)ᵀ E``: ``Wᵀ [v; ω]`` is minus the cable speeds."""
    robot = with_swivels(BASE, r)
    W = structure_matrix(robot, pose)
    eps = 1e-6
    grad = np.empty((6, robot.n_cables))
    for j in range(6):
        dp = np.zeros(6)
        dp[j] = eps
        grad[j] = (cable_lengths(robot, pose + dp) - cable_lengths(robot, pose - dp)) / (2 * eps)
    np.testing.assert_allclose(grad[:3], -W[:3], atol=1e-7)
    np.testing.assert_allclose(grad[3:], -(_euler_rates(*pose[3:]).T @ W[3:]), atol=1e-7)


@settings(max_examples=20, deadline=None)
@given(poses)
def test_converges_to_the_point_model_at_rate_r(pose: np.ndarray) -> None:
    point = inverse_kinematics(BASE, pose)
    radii = [4e-3, 2e-3, 1e-3]
    dl = [np.abs(inverse_kinematics(with_swivels(BASE, r), pose).lengths - point.lengths).max() for r in radii]
    dW = [
        np.abs(inverse_kinematics(with_swivels(BASE, r), pose).structure_matrix - point.structure_matrix).max()
        for r in radii
    ]
    for coarse, fine in zip(dl, dl[1:]):
        assert 1.9 < coarse / fine < 2.1  # first order in r
    for coarse, fine in zip(dW, dW[1:]):
        assert 1.8 < coarse / fine < 2.2
    assert dl[-1] < 10 * radii[-1]


def test_singular_configurations_raise_and_are_flagged() -> None:
    data = {
        "name": "one pulley",
        "dimension": 3,
        "platform": {"kind": "point-mass"},
        "cables": [{"exit": [0, 0, 0], "swivel": {"axis": [0, 0, 1], "radius": 0.1}}],
    }
    robot = robot_from_dict(data)
    with pytest.raises(InfeasiblePoseError, match="cable 1 has its anchor on the axis of its swivelling pulley"):
        inverse_kinematics(robot, [0.0, 0.0, -1.0])
    with pytest.raises(InfeasiblePoseError, match="inside the circle of its swivelling pulley"):
        inverse_kinematics(robot, [0.15, 0.0, 0.02])  # 0.054 from the centre (0.1, 0, 0)
    bad = np.array([[0.0, 0.0, -1.0], [0.15, 0.0, 0.02], [1.0, 0.0, 1.0]])
    ik, status = ik_status(robot, bad)
    assert status[:, 0].tolist() == [2, 3, 0]
    assert np.isfinite(ik.lengths).all() and np.isfinite(ik.structure_matrix).all()
    # the length on the axis does not depend on the pulley plane: from (−r, −1) about the
    # centre, the tangent of length 1 touches the far side after half a turn and 2·atan(r)
    assert ik.lengths[0, 0] == pytest.approx(0.1 * (np.pi + 2 * math.atan(0.1)) + 1.0, rel=1e-12)


def test_batch_path_equals_inverse_kinematics_and_flags_singular_poses() -> None:
    """The Numba kernel against the NumPy implementation, singular poses included."""
    rng = np.random.default_rng(7)
    P = np.column_stack([rng.uniform(-0.3, 0.3, (64, 3)), rng.uniform(-0.2, 0.2, (64, 3))])
    lengths, W, ok = batch_structure_matrices(ROBOT, P)
    assert ok.all()
    ik = inverse_kinematics(ROBOT, P)
    np.testing.assert_allclose(lengths, ik.lengths, rtol=1e-14)
    np.testing.assert_allclose(W, ik.structure_matrix, atol=1e-15)
    one = robot_from_dict(
        {
            "name": "one pulley",
            "dimension": 3,
            "platform": {"kind": "point-mass"},
            "cables": [{"exit": [0, 0, 0], "swivel": {"axis": [0, 0, 1], "radius": 0.1}}],
        }
    )
    P = np.array([[0.0, 0.0, -1.0], [0.15, 0.0, 0.02], [1.0, 0.0, 1.0], [0.05, 0.0, -1.0]])
    lengths, W, ok = batch_structure_matrices(one, P)
    assert ok.tolist() == [False, False, True, True]
    assert not W[:2].any()
    ik, status = ik_status(one, P)
    np.testing.assert_allclose(lengths, ik.lengths, rtol=1e-14)
    np.testing.assert_allclose(W, ik.structure_matrix, atol=1e-15)


@settings(max_examples=15, deadline=None)
@given(poses, arrays(float, (6,), elements=st.floats(-0.03, 0.03)))
def test_forward_kinematics_inverts_the_pulley_model(pose: np.ndarray, offset: np.ndarray) -> None:
    fk = forward_kinematics(ROBOT, cable_lengths(ROBOT, pose), guess=pose + offset)
    np.testing.assert_allclose(fk.pose, pose, atol=1e-8)


def test_tensions_balance_the_wrench_through_the_pulley_directions() -> None:
    from taut.statics import distribute_tensions

    pose = np.array([0.1, -0.05, 0.1, 0.05, 0.0, -0.05])
    res = distribute_tensions(ROBOT, pose)
    W = structure_matrix(ROBOT, pose)
    from taut.statics import external_wrench

    assert res.feasible
    np.testing.assert_allclose(W @ res.tensions + external_wrench(ROBOT, pose), 0.0, atol=1e-8)


def test_interference_check_uses_the_tangent_points() -> None:
    from taut.collision import capsule_segments

    pose = np.zeros((1, 6))
    A, B = capsule_segments(ROBOT, pose)
    ik = inverse_kinematics(ROBOT, pose[0])
    np.testing.assert_allclose(A[0, : ROBOT.n_cables], ik.exit_points)
    np.testing.assert_allclose(B[0, : ROBOT.n_cables], ik.anchors)
    assert np.linalg.norm(ik.exit_points - BASE.exits, axis=1).min() > 0.0


def test_the_equilibrium_solvers_model_a_mix_of_pulleys_and_fixed_exits() -> None:
    """Cable 2 alone through a pulley: the inverse problem's solutions and a tracking step
    from one of them have the pulley IK's lengths and balance with its structure matrix."""
    from taut.dgp import load, solve_igp, track_equilibrium
    from taut.geometry import rotation_matrix

    robot = with_swivels(taut.example("suspended-3cable"), 0.02, [1])
    res = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061})
    assert res.complete and res.solutions
    f, m, gp = load(robot)
    stable = [s for s in res.solutions if s.stable]
    assert len(stable) == 1
    start = stable[0]
    moved = track_equilibrium(robot, start, start.lengths + [0.0, 0.01, 0.0])
    for s, lengths in [*((s, s.lengths) for s in res.solutions), (moved, start.lengths + [0.0, 0.01, 0.0])]:
        pose = np.concatenate([s.position, s.orientation])
        ik = inverse_kinematics(robot, pose)
        np.testing.assert_allclose(ik.lengths, lengths, rtol=0, atol=1e-9)
        g = rotation_matrix(s.orientation, robot.orientation) @ gp
        np.testing.assert_allclose(ik.structure_matrix @ s.tensions + np.r_[f, m + np.cross(g, f)], 0.0, atol=1e-9)


@pytest.mark.parametrize(
    ("swivel", "dimension", "message"),
    [
        ({"axis": [0, 0, 1], "radius": 0.0}, 3, "greater than 0"),
        ({"axis": [0, 0, 1], "radius": -0.1}, 3, "greater than 0"),
        ({"axis": [0, 0, 0], "radius": 0.1}, 3, "non-zero vector"),
        ({"axis": [0, 0, float("nan")], "radius": 0.1}, 3, "finite number"),
        ({"axis": [0, 1], "radius": 0.1}, 3, "axis"),
        ({"axis": [0, 0, 1], "radius": 0.1}, 2, r"swivel.axis \[0.0, 0.0, 1.0\] points out of the robot's plane"),
        ({"axis": [1, 0, 0], "radius": 0.1}, 2, r"gives a third \(z\) number"),
        ({"axis": [1, 0], "radius": 0.1}, 3, "expected 3 numbers"),
    ],
)
def test_bad_swivels_are_refused(swivel: dict, dimension: int, message: str) -> None:
    d = dimension
    data = {
        "name": "bad",
        "dimension": d,
        "platform": {"kind": "point-mass"},
        "cables": [{"exit": [0.0] * d, "swivel": swivel}, {"exit": [1.0] * d}],
    }
    with pytest.raises(RobotFileError, match=message):
        robot_from_dict(data)


def test_jointed_platform_jacobian_through_pulleys() -> None:
    """The adjustable 8-cable robot with pulleys on its frame posts (axes vertical, cables
    from winches below): the actuator Jacobian's translation and joint columns are the
    derivatives of the pulley lengths."""
    from taut.kinematics._jointed import actuator_jacobian, actuator_positions

    data = robot_to_dict(taut.example("adjustable-8cable"))
    for c in data["cables"]:
        c["swivel"] = {"axis": [0.0, 0.0, 1.0], "radius": 0.15}
    robot = robot_from_dict(data)
    pose = np.array([5.3, 4.6, 2.5, 0.05, -0.04, 0.1, 2.2])
    J = actuator_jacobian(robot, pose)
    q = actuator_positions(robot, pose)
    np.testing.assert_allclose(q[:8], cable_lengths(robot, pose))
    assert (q[:8] > np.linalg.norm(robot.exits - inverse_kinematics(robot, pose).anchors, axis=1)).all()
    eps = 1e-6
    for j in (0, 1, 2, 6):
        dp = np.zeros(7)
        dp[j] = eps
        grad = (cable_lengths(robot, pose + dp) - cable_lengths(robot, pose - dp)) / (2 * eps)
        np.testing.assert_allclose(grad, J[:8, j], atol=1e-7)


# ---- planar robots: the swivel axis in the robot's plane ------------------------------------------

PLANAR = robot_from_dict(
    {
        "name": "planar pulleys",
        "dimension": 2,
        "platform": {"kind": "rigid"},
        "cables": [
            {"exit": [-1.0, -1.0], "anchor": [-0.1, -0.05], "swivel": {"axis": [0.0, 1.0], "radius": 0.05}},
            {"exit": [1.0, -1.0], "anchor": [0.1, -0.05], "swivel": {"axis": [0.6, 0.8], "radius": 0.04}},
            {"exit": [1.0, 1.0], "anchor": [0.1, 0.05], "swivel": {"axis": [0.0, -1.0], "radius": 0.05}},
            {"exit": [-1.0, 1.0], "anchor": [-0.1, 0.05]},
        ],
    }
)
planar_poses = arrays(float, (3,), elements=st.floats(-0.4, 0.4))


def planar_with_radius(r: float) -> Robot:
    data = robot_to_dict(PLANAR)
    for c in data["cables"]:
        if "swivel" in c:
            c["swivel"]["radius"] = r
    return robot_from_dict(data)


@pytest.mark.slow
@settings(max_examples=30, deadline=None)
@given(planar_poses)
def test_planar_lengths_and_tangent_points_match_root_finding(pose: np.ndarray) -> None:
    """The spatial root-finding reference with the plane embedded at z = 0 and the axes in it."""
    ik = inverse_kinematics(PLANAR, pose)
    for i in PLANAR.swivel_cables:
        s = PLANAR.cables[i].swivel
        D, k = np.array([*PLANAR.exits[i], 0.0]), np.array([*s.axis, 0.0])
        length, tangent = reference_path(D, k, s.radius, np.array([*ik.anchors[i], 0.0]))
        assert ik.lengths[i] == pytest.approx(length, abs=1e-9)
        np.testing.assert_allclose(ik.exit_points[i], tangent[:2], atol=1e-8)
        assert abs(tangent[2]) < 1e-8, "the tangent point is in the plane"


@settings(max_examples=30, deadline=None)
@given(planar_poses, st.floats(0.01, 0.3))
def test_planar_structure_matrix_is_minus_the_length_gradient(pose: np.ndarray, r: float) -> None:
    """Rows ``f_x, f_y, m_z``: ``∂l/∂(x, y, θ) = −W`` by central differences."""
    robot = planar_with_radius(r)
    W = structure_matrix(robot, pose)
    assert W.shape == (3, 4)
    eps = 1e-6
    for j in range(3):
        dp = np.zeros(3)
        dp[j] = eps
        grad = (cable_lengths(robot, pose + dp) - cable_lengths(robot, pose - dp)) / (2 * eps)
        np.testing.assert_allclose(grad, -W[j], atol=1e-7)


@settings(max_examples=20, deadline=None)
@given(planar_poses)
def test_planar_converges_to_the_point_model_at_rate_r(pose: np.ndarray) -> None:
    point = inverse_kinematics(
        PLANAR.model_copy(update={"cables": [c.model_copy(update={"swivel": None}) for c in PLANAR.cables]}), pose
    )
    radii = [4e-3, 2e-3, 1e-3]
    runs = [inverse_kinematics(planar_with_radius(r), pose) for r in radii]
    dl = [np.abs(ik.lengths - point.lengths).max() for ik in runs]
    dW = [np.abs(ik.structure_matrix - point.structure_matrix).max() for ik in runs]
    for coarse, fine in zip(dl, dl[1:]):
        assert 1.9 < coarse / fine < 2.1
    for coarse, fine in zip(dW, dW[1:]):
        assert 1.8 < coarse / fine < 2.2
    assert dl[-1] < 10 * radii[-1]


def test_planar_pulley_flips_across_the_axis_line() -> None:
    """A point mass crossing the axis line of a pulley: the pulley faces it from the other
    side (swivel angle 0 → π), the length is continuous, the direction jumps, and on the
    line the pose is singular."""
    from taut.kinematics._swivel import swivel_angles

    robot = robot_from_dict(
        {
            "name": "one planar pulley",
            "dimension": 2,
            "platform": {"kind": "point-mass"},
            "cables": [{"exit": [0.0, 0.0], "swivel": {"axis": [0.0, 1.0], "radius": 0.1}}, {"exit": [0.0, 5.0]}],
        }
    )
    # winch frame of (0, 1, 0): x axis (1, 0, 0), so an anchor at x > 0 has γ = 0; behind the
    # pulley (y < 0) the cable wraps about half a turn, and the side matters
    left, right = np.array([-1e-7, -2.0]), np.array([1e-7, -2.0])
    assert swivel_angles(robot, right)[0] == 0.0 and swivel_angles(robot, left)[0] == pytest.approx(np.pi)
    a, b = inverse_kinematics(robot, left), inverse_kinematics(robot, right)
    assert a.lengths[0] == pytest.approx(b.lengths[0], abs=1e-6)
    np.testing.assert_allclose(a.exit_points[0], b.exit_points[0] * [-1, 1], atol=1e-6)
    assert b.exit_points[0, 0] > 0.1 and a.directions[0, 0] < -0.04 and b.directions[0, 0] > 0.04
    with pytest.raises(InfeasiblePoseError, match="cable 1 has its anchor on the axis of its swivelling pulley"):
        inverse_kinematics(robot, [0.0, 2.0])
    with pytest.raises(InfeasiblePoseError, match="swivel angle is undefined"):
        swivel_angles(robot, [0.0, 2.0])
    # hand computation: anchor (1, 0.1) level with the top of the pulley centred at (0.1, 0)
    ik = inverse_kinematics(robot, [1.0, 0.1])
    assert ik.lengths[0] == pytest.approx(0.1 * np.pi / 2 + 0.9)
    np.testing.assert_allclose(ik.exit_points[0], [0.1, 0.1], atol=1e-15)


def test_swivel_angles_of_a_spatial_pulley_by_hand() -> None:
    from taut.kinematics._swivel import swivel_angles

    robot = robot_from_dict(
        {
            "name": "one pulley",
            "dimension": 3,
            "platform": {"kind": "point-mass"},
            "cables": [{"exit": [0, 0, 0], "swivel": {"axis": [0, 0, 1], "radius": 0.1}}, {"exit": [0, 0, 3]}],
        }
    )
    poses = [[1.0, 1.0, -1.0], [0.0, -2.0, 0.5], [-1.0, 0.0, 1.0]]
    np.testing.assert_allclose(swivel_angles(robot, poses)[:, 0], [np.pi / 4, -np.pi / 2, np.pi], atol=1e-15)
    with pytest.raises(UnsupportedRobotError, match="no cable leaves through a swivelling pulley"):
        swivel_angles(BASE, np.zeros(6))


def test_planar_batch_path_and_analyses_use_the_pulleys() -> None:
    """Planar robots with pulleys go through NumPy in the batch entry point, and the tension
    distribution balances the wrench through the tangent directions."""
    from taut.statics import distribute_tensions, external_wrench

    rng = np.random.default_rng(3)
    P = rng.uniform(-0.3, 0.3, (64, 3))
    lengths, W, ok = batch_structure_matrices(PLANAR, P)
    ik = inverse_kinematics(PLANAR, P)
    assert ok.all()
    np.testing.assert_allclose(lengths, ik.lengths, rtol=0, atol=0)
    np.testing.assert_allclose(W, ik.structure_matrix, rtol=0, atol=0)
    robot = PLANAR.model_copy(update={"platform": {"kind": "rigid", "wrench": [0.0, -5.0, 0.1]}})
    pose = np.array([0.1, -0.05, 0.1])
    res = distribute_tensions(robot, pose)
    assert res.feasible
    np.testing.assert_allclose(
        structure_matrix(robot, pose) @ res.tensions + external_wrench(robot, pose), 0, atol=1e-8
    )


CASPR = Path(__file__).parents[1] / "model" / "fixtures" / "caspr"


@pytest.mark.slow
@settings(max_examples=30, deadline=None)
@given(st.floats(-0.4, 0.4), st.floats(-0.4, 0.4), st.floats(-0.4, 0.4))
def test_caspr_planar_base_rotating_pulleys(x: float, z: float, theta: float) -> None:
    """A PLANAR_XZ CASPR robot whose base_rotating_pulleys have entry vectors in the XZ plane:
    taut's planar swivels, whose lengths are the root-finding reference in CASPR's 3-D frame
    (taut (x, y, θ) = CASPR (x, z, −θ))."""
    from taut.model import load_robot

    robot = load_robot(CASPR / "planar_pulley_xz_bodies.xml")
    assert robot.dimension == 2 and robot.swivel_cables == (0, 1, 2)
    cables = ET.parse(CASPR / "planar_pulley_xz_cables.xml").getroot()
    ik = inverse_kinematics(robot, [x, z, -theta])
    c, s_ = math.cos(theta), math.sin(theta)
    for i, el in enumerate(cables.iter("cable_ideal")):
        pulley = el.find("attachments/base_rotating_pulley")
        if pulley is None:
            continue
        vec = [np.array(pulley.find(tag).text.split(), float) for tag in ("fixed_location", "cable_entry_vector")]
        radius = float(pulley.find("pulley_radius").text)
        local = np.array(el.find("attachments/attachment/location").text.split(), float)
        # PLANAR_XZ: rotation θ about CASPR's y axis, then the translation (x, 0, z)
        B = np.array([x, 0.0, z]) + np.array([[c, 0, s_], [0, 1, 0], [-s_, 0, c]]) @ local
        length, tangent = reference_path(vec[0], vec[1], radius, B)
        assert ik.lengths[i] == pytest.approx(length, abs=1e-9)
        np.testing.assert_allclose(ik.exit_points[i], tangent[[0, 2]], atol=1e-8)


def test_caspr_planar_pulleys_round_trip(tmp_path: Path) -> None:
    """The CASPR writer lifts a planar swivel axis into the robot's plane, and reads back."""
    from taut.model import load_robot, write_caspr

    robot = load_robot(CASPR / "planar_pulley_xz_bodies.xml")
    write_caspr(robot, tmp_path / "back_bodies.xml")
    back = load_robot(tmp_path / "back_bodies.xml")
    assert [c.swivel for c in back.cables] == [c.swivel for c in robot.cables]
    q = np.array([[0.1, -0.2, 0.3], [0.0, 0.0, 0.0]])
    np.testing.assert_allclose(inverse_kinematics(back, q).lengths, inverse_kinematics(robot, q).lengths, atol=1e-15)


def test_caspr_planar_point_mass_pulley(tmp_path: Path) -> None:
    """A P_XZ point mass whose first cable, attached off its origin, leaves through an in-plane
    base_rotating_pulley: the anchor offset folds into the exit as for a straight cable, and the
    lengths are the root-finding reference in CASPR's frame."""
    from taut.model import load_robot

    bodies = (CASPR / "point_xz_bodies.xml").read_text()
    cables = (CASPR / "point_xz_cables.xml").read_text()
    old = "<attachment><link>0</link><location>-1 0 1</location></attachment><attachment><link>1</link><location>0 0 0</location>"
    assert old in cables
    cables = cables.replace(
        old,
        "<base_rotating_pulley><fixed_location>-1 0 1</fixed_location><pulley_radius>0.05</pulley_radius>"
        "<cable_entry_vector>0.6 0 -0.8</cable_entry_vector></base_rotating_pulley>"
        "<attachment><link>1</link><location>0.05 0 0.02</location>",
    )
    (tmp_path / "p_bodies.xml").write_text(bodies)
    (tmp_path / "p_cables.xml").write_text(cables)
    robot = load_robot(tmp_path / "p_bodies.xml")
    assert (robot.dimension, robot.platform.kind, robot.swivel_cables) == (2, "point-mass", (0,))
    assert robot.cables[0].swivel.axis == (0.6, -0.8)
    for x, z in [(0.1, -0.2), (-0.3, 0.25), (0.4, 0.4)]:
        length, tangent = reference_path(
            np.array([-1.0, 0.0, 1.0]), np.array([0.6, 0.0, -0.8]), 0.05, np.array([x + 0.05, 0.0, z + 0.02])
        )
        ik = inverse_kinematics(robot, [x, z])
        assert ik.lengths[0] == pytest.approx(length, abs=1e-9)
        np.testing.assert_allclose(ik.exit_points[0], tangent[[0, 2]] - [0.05, 0.02], atol=1e-8)


@settings(max_examples=100, deadline=None)
@given(
    position=st.tuples(*[st.floats(-1.0, 1.0)] * 3),
    axis=st.tuples(*[st.floats(-1.0, 1.0)] * 3).filter(lambda v: np.linalg.norm(v) > 0.1),
    radius=st.floats(0.01, 1.0),
)
def test_refuse_near_swivel_axis_is_the_distance_to_the_axis(position, axis, radius) -> None:
    """A pose is refused exactly when an anchor is nearer its pulley's axis than the radius
    (the distance ``‖(b − a) × k‖`` of the anchor from the axis line), naming that cable."""
    from taut.kinematics import refuse_near_swivel_axis

    base = taut.example("spatial-8cable")
    k = np.array(axis) / np.linalg.norm(axis)
    cables = list(base.cables)
    cables[2] = cables[2].model_copy(update={"swivel": {"axis": tuple(axis), "radius": radius}})
    robot = base.model_copy(update={"cables": tuple(cables)})
    pose = np.array([*position, 0.0, 0.0, 0.0])
    b = pose[:3] + robot.anchors[2]
    distance = np.linalg.norm(np.cross(b - robot.exits[2], k))
    assume(abs(distance - radius) > 1e-9)
    if distance < radius:
        with pytest.raises(InfeasiblePoseError, match=r"at pose 1 cable 3's anchor is .* within the pulley's radius"):
            refuse_near_swivel_axis(robot, pose)
    else:
        assert refuse_near_swivel_axis(robot, pose) is None
