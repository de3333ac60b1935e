"""MuJoCo as an independent engine for routed cables (``cables[].via``): the exported spatial
tendons through the via sites have taut's cable lengths, and their Jacobians (MuJoCo's
``ten_J``, the tendon length's rate per generalised velocity) are taut's Jacobian rows, over
random poses of a rigid and of a jointed platform."""

from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

from kinematics.test_routing import routed  # noqa: E402

from taut.geometry import rotation_matrix  # noqa: E402
from taut.kinematics import actuator_jacobian, cable_lengths  # noqa: E402
from taut.model import load_robot, mjcf_text, pose_to_qpos  # noqa: E402

RIGID = Path(__file__).parent / "fixtures" / "taut" / "routed.yaml"


def _poses(robot, rng, count):
    if robot.n_joints:
        return [
            np.array(
                [
                    *rng.uniform(4, 6, 2),
                    rng.uniform(1, 2),
                    *rng.uniform(-0.3, 0.3, 3),
                    rng.uniform(0.8, 3),
                    rng.uniform(-1, 1),
                ]
            )
            for _ in range(count)
        ]
    return [rng.uniform(-0.3, 0.3, 6) for _ in range(count)]


@pytest.mark.parametrize("robot", [load_robot(RIGID), routed()], ids=["rigid", "jointed"])
def test_tendons_have_the_routed_lengths_and_jacobians(robot):
    model = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    data = mujoco.MjData(model)
    n = robot.n_cables
    for pose in _poses(robot, np.random.default_rng(5), 200):
        data.qpos[:] = pose_to_qpos(robot, pose)
        mujoco.mj_forward(model, data)
        assert np.allclose(data.ten_length[:n], cable_lengths(robot, pose), rtol=0, atol=1e-12)
        J = actuator_jacobian(robot, pose)[:n].copy()
        # MuJoCo's freejoint takes the angular velocity in the body frame, taut's the fixed frame
        J[:, 3:6] = J[:, 3:6] @ rotation_matrix(pose[3:6], robot.orientation)
        dense = np.zeros((model.ntendon, model.nv))
        mujoco.mju_sparse2dense(dense, data.ten_J, model.ten_J_rownnz, model.ten_J_rowadr, model.ten_J_colind)
        assert np.allclose(dense[:n], J, rtol=0, atol=1e-10)
    assert robot.routed_cables
