import numpy as np
import pytest
from axis_rotations import rx, ry, rz
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import taut
from taut.kinematics import (
    anchor_points,
    cable_lengths,
    forward_kinematics,
    inverse_kinematics,
    structure_matrix,
    tension_from_stretch,
    unstretched_length,
)
from taut.kinematics._inverse import BATCH_POSES
from taut.model import robot_from_dict

SPATIAL = taut.example("spatial-8cable")
PLANAR = taut.example("planar-4cable")

spatial_poses = arrays(float, (6,), elements=st.floats(-0.3, 0.3))


def test_hand_computed_planar_pose():
    ik = inverse_kinematics(PLANAR, [0.0, 0.0, np.pi / 2])
    # anchor 1 (-0.1, -0.05) rotated by 90 degrees is (0.05, -0.1); exit (-1, -1)
    np.testing.assert_allclose(ik.anchors[0], [0.05, -0.1], atol=1e-15)
    assert ik.lengths[0] == pytest.approx(np.hypot(-1.05, -0.9))
    np.testing.assert_allclose(ik.directions[0], np.array([-1.05, -0.9]) / np.hypot(-1.05, -0.9))
    # moment of cable 1 about p: (b - p) x u
    u = ik.directions[0]
    assert ik.structure_matrix[2, 0] == pytest.approx(0.05 * u[1] - (-0.1) * u[0])


@settings(max_examples=40, deadline=None)
@given(spatial_poses)
def test_structure_matrix_is_minus_length_gradient(pose):
    """dl/dp = -u and dl/dc = -(moment about z): W^T is minus the IK Jacobian for twists."""
    W = structure_matrix(SPATIAL, pose)
    eps = 1e-6
    for k in range(3):
        dp = np.zeros(6)
        dp[k] = eps
        grad = (cable_lengths(SPATIAL, pose + dp) - cable_lengths(SPATIAL, pose - dp)) / (2 * eps)
        np.testing.assert_allclose(grad, -W[k], atol=1e-7)
    dc = np.zeros(6)
    dc[5] = eps  # xyz-fixed: the last angle rotates about the fixed z axis
    grad = (cable_lengths(SPATIAL, pose + dc) - cable_lengths(SPATIAL, pose - dc)) / (2 * eps)
    np.testing.assert_allclose(grad, -W[5], atol=1e-7)


@settings(max_examples=30, deadline=None)
@given(spatial_poses, arrays(float, (6,), elements=st.floats(-0.05, 0.05)))
def test_forward_inverts_inverse(pose, offset):
    # a guess near the pose: from far away damped Newton may reach another pose with the
    # same lengths (e.g. rotations by +a and -a about x at the centre of this symmetric robot)
    fk = forward_kinematics(SPATIAL, cable_lengths(SPATIAL, pose), guess=pose + offset)
    np.testing.assert_allclose(fk.pose, pose, atol=1e-8)
    assert fk.residual < 1e-9


def test_forward_rejects_unreachable_lengths():
    with pytest.raises(taut.UnreachableLengthsError, match="no pose"):
        forward_kinematics(SPATIAL, np.full(8, 0.2))
    with pytest.raises(taut.TautError, match="positive and finite"):
        forward_kinematics(SPATIAL, [1, 1, 1, 1, 1, 1, 1, np.nan])
    with pytest.raises(taut.TautError, match="expected 8 cable lengths"):
        forward_kinematics(SPATIAL, [1, 1])


def _ik_by_hand(robot, pose):
    """Lengths, unit vectors, anchors and structure matrix at one pose from Eqs. 2.1 and 2.8 of
    Rushton (2022), with the rotations written out (xyz-fixed: R = Rz(c) Ry(b) Rx(a))."""
    if robot.dimension == 3:
        p, R = np.asarray(pose[:3]), rz(pose[5]) @ ry(pose[4]) @ rx(pose[3])
    else:
        p, R = np.asarray(pose[:2]), rz(pose[2])[:2, :2]
    b = p + robot.anchors @ R.T
    v = robot.exits - b
    lengths = np.linalg.norm(v, axis=1)
    u = v / lengths[:, None]
    r = b - p
    moments = np.cross(r, u) if robot.dimension == 3 else r[:, 0] * u[:, 1] - r[:, 1] * u[:, 0]
    return lengths, u, b, np.vstack([u.T, np.atleast_2d(moments.T)])


@pytest.mark.parametrize("size", [7, BATCH_POSES - 1, BATCH_POSES, BATCH_POSES + 1, 100])
@pytest.mark.parametrize("robot", [SPATIAL, PLANAR], ids=["spatial", "planar"])
def test_batches_match_the_equations_on_both_sides_of_the_kernel_threshold(robot, size):
    """From :data:`BATCH_POSES` poses on, rigid platforms go through the Numba kernel."""
    rng = np.random.default_rng(size)
    poses = rng.uniform(-0.3, 0.3, (size, robot.pose_size))
    ik = inverse_kinematics(robot, poses)
    assert ik.structure_matrix.shape == (size, robot.wrench_dim, robot.n_cables)
    for k, pose in enumerate(poses):
        lengths, u, b, W = _ik_by_hand(robot, pose)
        np.testing.assert_allclose(ik.lengths[k], lengths, rtol=1e-13)
        np.testing.assert_allclose(ik.directions[k], u, rtol=0, atol=1e-13)
        np.testing.assert_allclose(ik.anchors[k], b, rtol=0, atol=1e-13)
        np.testing.assert_allclose(ik.structure_matrix[k], W, rtol=0, atol=1e-13)


def test_bad_poses_are_typed_errors():
    with pytest.raises(taut.PoseError, match="6 coordinates"):
        inverse_kinematics(SPATIAL, [0, 0, 0])
    with pytest.raises(taut.PoseError, match="not finite"):
        inverse_kinematics(SPATIAL, [0, 0, np.inf, 0, 0, 0])
    # platform anchor 1 placed exactly on its exit point
    with pytest.raises(taut.InfeasiblePoseError, match="cable 1 has zero length"):
        inverse_kinematics(SPATIAL, [-1.65, -0.9, -1.05, 0, 0, 0])


def test_point_mass_and_prismatic_body():
    pm = robot_from_dict(
        {
            "name": "pm",
            "dimension": 3,
            "platform": {"kind": "point-mass"},
            "cables": [{"exit": [0, 0, 1]}, {"exit": [1, 0, 1]}, {"exit": [0, 1, 1]}],
        }
    )
    ik = inverse_kinematics(pm, [0.0, 0.0, 0.0])
    np.testing.assert_allclose(ik.lengths, [1, np.sqrt(2), np.sqrt(2)])
    assert ik.structure_matrix.shape == (3, 3)
    jointed = robot_from_dict(
        {
            "name": "slider",
            "dimension": 3,
            "orientation": "xyz-moving",
            "platform": {
                "bodies": [{"name": "lower", "joint": {"kind": "prismatic", "axis": [0, 0, 2], "limits": [0, 1]}}]
            },
            "cables": [
                {"exit": [0, 0, 5], "anchor": [0, 0, 0]},
                {"exit": [0, 0, -5], "anchor": [0, 0, 0], "body": "lower"},
            ],
        }
    )
    b = anchor_points(jointed, [0, 0, 0, np.pi / 2, 0, 0, 0.5])
    # the joint axis is the body z axis, which the rotation about x by 90 degrees maps to -y
    np.testing.assert_allclose(b[1], [0, -0.5, 0], atol=1e-15)
    with pytest.raises(taut.PoseError, match="outside its limits"):
        anchor_points(jointed, [0, 0, 0, 0, 0, 0, 1.5])


@given(st.floats(0.1, 10), st.floats(0, 1e4), st.floats(1e3, 1e7))
def test_unstretched_length_inverts_eq_2_15(length, tension, ea):
    l0 = unstretched_length(length, tension, ea)
    assert l0 <= length
    # l − l0 cancels: the tension is exact to about EA·ε
    assert tension_from_stretch(length, l0, ea) == pytest.approx(tension, rel=1e-9, abs=1e-14 * ea)


RIGID = [n for n in taut.example_names() if taut.example(n).n_joints == 0]


@pytest.mark.parametrize("name, convention", [(n, None) for n in RIGID] + [("spatial-8cable", "xyz-moving")])
def test_few_poses_agree_with_the_batch_kernel(name, convention):
    """Fewer than BATCH_POSES poses go through NumPy, more through the Numba kernel: the two
    paths give the same lengths, directions, anchors and structure matrices."""
    from taut.kinematics._forward import default_guess
    from taut.kinematics._inverse import BATCH_POSES
    from taut.model import robot_to_dict

    # the kernel does not take obstacles (they send every batch through NumPy); the straight
    # cables of a variable-structure robot still have to agree between the two paths
    robot = taut.example(name).model_copy(update={"obstacles": ()})
    if convention is not None:
        robot = robot_from_dict(robot_to_dict(robot) | {"orientation": convention})
    rng = np.random.default_rng(2)
    poses = default_guess(robot) + rng.uniform(-0.05, 0.05, (BATCH_POSES, robot.pose_size))
    many = inverse_kinematics(robot, poses)
    for k in (0, 1, 5):
        few = inverse_kinematics(robot, poses[k : k + 3])
        for field in ("lengths", "directions", "anchors", "structure_matrix"):
            np.testing.assert_allclose(getattr(few, field), getattr(many, field)[k : k + 3], rtol=1e-12, atol=1e-12)
