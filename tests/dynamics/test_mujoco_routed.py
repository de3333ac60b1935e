"""MuJoCo as an independent engine for routed cables (``cables[].via``): the exported model
(tendons through via sites) and ``taut.dynamics.forward_dynamics`` (the compiled tree with the
chain's forces at every via point on a moving body), driven by the same tension profile from a
moving start, agree over 1 s to 1e-6 m and 1e-6 rad on the platform's pose and the joint
coordinates (measured: 3.3e-8 m and 5.3e-7 rad for the rigid platform, whose crossed cables
amplify the two RK4s' truncation errors in different coordinates; 4.6e-11 m, 8.7e-11 rad and
1.4e-14 rad on the joints for the jointed one, its arm hanging below the upper body)."""

from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

from kinematics.test_routing import routed  # noqa: E402

from taut.dynamics import forward_dynamics, inverse_dynamics  # noqa: E402
from taut.geometry import rate_matrix, rotation_matrix  # noqa: E402
from taut.model import load_robot, mjcf_text, pose_to_qpos  # noqa: E402

RIGID = Path(__file__).parents[1] / "model" / "fixtures" / "taut" / "routed.yaml"


def _angle(Ra, Rb):
    S = Ra.T @ Rb
    return float(np.linalg.norm([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2)


@pytest.mark.parametrize(
    ("robot", "q0"),
    [
        (load_robot(RIGID), np.array([0.02, -0.01, 0.03, 0.05, -0.04, 0.02])),
        (routed(), np.array([5.0, 5.0, 1.5, 0.05, -0.03, 0.1, 1.5, 0.3])),
    ],
    ids=["rigid", "jointed"],
)
def test_same_motion_as_mujoco(robot, q0):
    dt, n, nj = 1e-3, robot.n_cables, robot.n_joints
    qd0 = np.linspace(-0.05, 0.05, robot.pose_size)
    need = inverse_dynamics(robot, q0, np.zeros(robot.pose_size), np.zeros(robot.pose_size), method="qp")
    assert need.feasible
    hold = need.tensions
    torques = np.zeros(nj)  # the motors' torques on their joints' coordinates, 0 on passive joints
    torques[robot.actuated_joints] = need.actuator_forces
    phase = np.arange(n)

    def tensions(t):
        return hold + 0.2 + 0.2 * np.sin(3 * t + phase)

    def wrench(t):
        return np.concatenate([np.zeros(robot.wrench_dim), torques])

    run = forward_dynamics(robot, q0, qd0, 1.0, tensions=tensions, wrench=wrench, method="RK4", step=dt)

    model = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    model.opt.timestep = dt
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(model)
    data.qpos[:] = pose_to_qpos(robot, q0)
    R0 = rotation_matrix(q0[3:6], robot.orientation)
    data.qvel[:3] = qd0[:3]
    data.qvel[3:6] = R0.T @ rate_matrix(q0[3:6], robot.orientation) @ qd0[3:6]
    joints = [model.joint(f"joint{k}") for k in range(1, nj + 1)]
    for k, joint in enumerate(joints):
        data.qvel[joint.dofadr[0]] = qd0[6 + k]
    mujoco.mj_forward(model, data)
    body = model.body("platform").id
    worst = np.zeros(3)
    for k, t in enumerate(run.times):
        q = run.poses[k]
        R = rotation_matrix(q[3:6], robot.orientation)
        joint_error = max((abs(data.qpos[j.qposadr[0]] - q[6 + i]) for i, j in enumerate(joints)), default=0.0)
        worst = np.maximum(
            worst, [np.abs(data.xpos[body] - q[:3]).max(), _angle(data.xmat[body].reshape(3, 3), R), joint_error]
        )
        if k + 1 < len(run.times):
            data.ctrl[:] = np.concatenate([tensions(t), torques])  # a drive on every joint, idle on passive ones
            mujoco.mj_step(model, data)
    assert np.abs(run.poses - q0).max(axis=0)[:3].max() > 0.01  # a real motion
    assert not run.beyond_limits.any()  # MuJoCo would stop a joint at its limit
    assert (worst <= 1e-6).all(), worst
