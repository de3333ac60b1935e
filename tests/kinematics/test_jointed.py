"""Actuator positions, the 9×7 Jacobian (checked against finite differences) and the
structure matrix with joint force of the adjustable platform (Lieskovský 2020, §3.2–3.3)."""

import numpy as np
import pytest
from scipy.linalg import expm, null_space

import taut
from taut.errors import PoseError, TautError
from taut.geometry import angles_from_matrix, rotation_matrix
from taut.kinematics import inverse_kinematics
from taut.kinematics._jointed import actuator_jacobian, actuator_positions, joint_forces, jointed_structure_matrix
from taut.model import robot_from_dict, robot_to_dict

ROBOT = taut.example("adjustable-8cable")
#: Lieskovský 2020's model, without the example's assumed masses.
MASSLESS = ROBOT.model_copy(
    update={
        "platform": ROBOT.platform.model_copy(
            update={
                "bodies": tuple(
                    b.model_copy(update={"mass": None, "com": None, "inertia": None}) for b in ROBOT.platform.bodies
                )
            }
        )
    }
)


def _skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def _moved(robot, pose, twist, h):
    """The pose after moving with ``twist = [v, ω, q̇]`` for a time ``h`` (spatial rigid)."""
    R = rotation_matrix(pose[3:6], robot.orientation)
    out = pose.copy()
    out[:3] += h * twist[:3]
    out[3:6] = angles_from_matrix(expm(_skew(h * twist[3:6])) @ R, robot.orientation)
    out[6:] += h * twist[6:]
    return out


def _fd_jacobian(robot, pose, h=1e-6):
    cols = []
    for k in range(robot.pose_size):
        e = np.eye(robot.pose_size)[k]
        cols.append(
            (
                actuator_positions(robot, _moved(robot, pose, e, h))
                - actuator_positions(robot, _moved(robot, pose, e, -h))
            )
            / (2 * h)
        )
    return np.array(cols).T


def _revolute_variant():
    data = robot_to_dict(ROBOT)
    data["platform"]["bodies"][0]["joint"] = {
        "kind": "revolute",
        "name": "phi",
        "axis": [0.3, 0.2, 1.0],
        "origin": [0.1, 0, 2.0],
        "limits": [-1.0, 1.0],
    }
    return robot_from_dict(data)


def test_actuator_positions_are_lengths_then_joint():
    pose = np.array([5, 5, 4.5, 0.1, -0.05, 0.2, 3.0])
    q = actuator_positions(ROBOT, pose)
    assert q.shape == (9,)
    assert np.allclose(q[:8], inverse_kinematics(ROBOT, pose).lengths)
    assert q[8] == 3.0  # Eq. 3.2.4


@pytest.mark.parametrize("robot", [ROBOT, _revolute_variant()], ids=["prismatic", "revolute"])
def test_jacobian_matches_finite_differences(robot):
    rng = np.random.default_rng(1)
    for _ in range(10):
        q = rng.uniform(*robot.joint_limits[0]) * 0.9 if robot.joint_limits[0, 0] < 0 else rng.uniform(0.6, 4.3)
        pose = np.array([*rng.uniform(3, 7, 2), rng.uniform(2, 5), *rng.uniform(-0.4, 0.4, 3), q])
        J = actuator_jacobian(robot, pose)
        assert J.shape == (9, 7)
        assert np.allclose(J, _fd_jacobian(robot, pose), atol=1e-7)


def test_jacobian_structure_of_eq_3_2_12():
    pose = np.array([5, 5, 4, 0.2, 0.1, -0.3, 2.5])
    J = actuator_jacobian(ROBOT, pose)
    ik = inverse_kinematics(ROBOT, pose)
    u23 = rotation_matrix(pose[3:6], ROBOT.orientation) @ [0, 0, 1]
    assert np.allclose(J[:4, 6], 0)  # cables on the lower body do not feel s23
    assert np.allclose(J[4:8, 6], -ik.directions[4:] @ u23)  # u_23 · u_j, sign of l̇ = −u·ḃ
    assert np.allclose(J[8], [0, 0, 0, 0, 0, 0, 1])  # Eq. 3.2.8


def test_standard_robots_have_minus_W_transpose():
    robot = taut.example("spatial-8cable")
    pose = np.array([0.1, -0.2, 0.3, 0.1, 0.2, -0.1])
    assert np.allclose(actuator_jacobian(robot, pose), -inverse_kinematics(robot, pose).structure_matrix.T)


def test_structure_matrix_and_joint_force():
    rng = np.random.default_rng(4)
    poses = np.column_stack(
        [
            np.full(20, 5.0),
            np.full(20, 5.0),
            rng.uniform(3.5, 5, 20),
            rng.uniform(-0.2, 0.2, (20, 3)),
            rng.uniform(2, 3, 20),
        ]
    )
    A = jointed_structure_matrix(ROBOT, poses)
    assert A.shape == (20, 7, 9)
    assert np.allclose(A[:, :6, :8], inverse_kinematics(ROBOT, poses).structure_matrix)  # Eq. 3.3.10 (A = −W there)
    assert np.allclose(A[:, 6, 8], 1.0) and np.allclose(A[:, :6, 8], 0.0)
    for pose, Ak in zip(poses, A):
        # tensions balancing zero external wrench (Eq. 3.3.5): the joint force of Eq. 3.3.11
        # is the same from either body's cables (Lieskovský's model has no masses)
        N = null_space(Ak[:6, :8])
        tau = N @ np.ones(N.shape[1])
        zeta = joint_forces(MASSLESS, pose, tau)
        ik = inverse_kinematics(ROBOT, pose)
        u23 = rotation_matrix(pose[3:6], ROBOT.orientation) @ [0, 0, 1]
        upper = ik.directions[4:] @ u23 @ tau[4:]
        lower = ik.directions[:4] @ u23 @ tau[:4]
        assert np.isclose(zeta[0], -upper) and np.isclose(zeta[0], lower)
        # generalised equilibrium holds with the joint force included
        assert np.allclose(Ak @ np.concatenate([tau, zeta]), 0.0, atol=1e-9)
        # the assumed 8 kg upper body adds its weight along the joint axis to the joint's load
        weighted = joint_forces(ROBOT, pose, tau)
        assert np.isclose(weighted[0] - zeta[0], 8.0 * 9.81 * u23[2])


def test_joint_outside_limits_is_rejected():
    with pytest.raises(PoseError, match="outside its limits"):
        actuator_jacobian(ROBOT, [5, 5, 4, 0, 0, 0, 5.0])
    with pytest.raises(PoseError):
        actuator_positions(ROBOT, [5, 5, 4, 0, 0, 0])
    with pytest.raises(TautError, match="tensions"):
        joint_forces(ROBOT, [5, 5, 4, 0, 0, 0, 2.0], np.ones(9))
