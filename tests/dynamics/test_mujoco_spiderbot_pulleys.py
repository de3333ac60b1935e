"""MuJoCo as an independent engine for CASPR's SpiderBot with its default cable set, whose eight
cables leave through swivelling pulleys (``CUcablerobot``): taut's forward dynamics and
MuJoCo's, driven by the same tension and joint-torque profile, follow the same motion over 1 s.

taut's pulleys are massless: each turns at once to face its cable's anchor.  In the exported
model each is a hinged wheel the tendon wraps (``taut.model._mjcf``), whose free motion is not
taut's; so before every MuJoCo step each hinge is set to the angle that faces the anchor
*in MuJoCo's state* (and to that angle's rate, by integrating MuJoCo's own velocity over a
short time), and the wheel's dynamics play no part.  The tendon's path over the wheel, its
length and the force it puts on the platform are MuJoCo's."""

from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

from taut.dynamics import forward_dynamics, inverse_dynamics  # noqa: E402
from taut.geometry import angles_from_matrix, rate_matrix, rotation_matrix  # noqa: E402
from taut.model import load_robot, mjcf_text, pose_to_qpos  # noqa: E402

SPIDER = Path(__file__).parents[1] / "model" / "fixtures" / "caspr" / "real" / "SpiderBot_UR3_bodies.xml"

#: Time over which MuJoCo's velocity is integrated to give each hinge's rate [s].
RATE_STEP = 1e-7


def rotation_angle(Ra, Rb):
    """The angle of ``Raᵀ Rb`` [rad], from its skew part (exact for small angles)."""
    S = Ra.T @ Rb
    return float(np.linalg.norm([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2)


@pytest.mark.slow
def test_same_motion_as_mujoco_through_swivelling_pulleys():
    """At every 1 ms step the two engines agree to 1e-6 m in the base's position, 1e-6 rad in
    its orientation and in each joint coordinate, while the base moves by centimetres and
    every pulley swivels."""
    dt = 1e-3
    robot = load_robot(SPIDER)
    assert len(robot.swivel_cables) == robot.n_cables == 8
    q0 = np.array([1.445, 1.0005, 0.9025, 0.02, -0.01, 0.03, 0.1, -0.3, 0.4, 0.1, -1.5708, 0.05])
    qd0 = np.array([0.02, -0.01, 0.03, 0.05, -0.04, 0.06, 0.1, -0.1, 0.2, 0.1, -0.2, 0.3])
    need = inverse_dynamics(robot, q0, np.zeros(12), np.zeros(12), method="qp")
    assert need.feasible
    hold, torques = need.tensions, need.actuator_forces
    phase = np.arange(robot.n_cables)

    def tensions(t):
        return hold + 10.0 + 10.0 * np.sin(3 * t + phase)

    def joint_torques(t):
        return torques + 0.3 * np.sin(2 * t + np.arange(6))

    def wrench(t):
        return np.concatenate([np.zeros(6), joint_torques(t)])

    run = forward_dynamics(robot, q0, qd0, 1.0, tensions=tensions, wrench=wrench, method="RK4", step=dt)

    model = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    model.opt.timestep = dt
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(model)
    joints = [model.joint(f"joint{k}") for k in range(1, 7)]
    hinges = np.array([model.joint(f"swivel{i + 1}").qposadr[0] for i in robot.swivel_cables])
    hinge_dofs = np.array([model.joint(f"swivel{i + 1}").dofadr[0] for i in robot.swivel_cables])
    free = model.joint(0)
    assert free.type[0] == mujoco.mjtJoint.mjJNT_FREE

    def pose_of(qpos):
        R = np.empty(9)
        mujoco.mju_quat2Mat(R, qpos[free.qposadr[0] + 3 : free.qposadr[0] + 7])
        angles = angles_from_matrix(R.reshape(3, 3), robot.orientation)
        return np.concatenate(
            [qpos[free.qposadr[0] : free.qposadr[0] + 3], angles, [qpos[j.qposadr[0]] for j in joints]]
        )

    def face_the_anchors():
        now = pose_to_qpos(robot, pose_of(data.qpos))[hinges]
        ahead = data.qpos.copy()
        mujoco.mj_integratePos(model, ahead, data.qvel, RATE_STEP)
        later = pose_to_qpos(robot, pose_of(ahead))[hinges]
        data.qpos[hinges] = now
        data.qvel[hinge_dofs] = (np.angle(np.exp(1j * (later - now)))) / RATE_STEP

    data.qpos[:] = pose_to_qpos(robot, q0)
    R0 = rotation_matrix(q0[3:6], robot.orientation)
    data.qvel[:3] = qd0[:3]
    data.qvel[3:6] = R0.T @ rate_matrix(q0[3:6], robot.orientation) @ qd0[3:6]
    for k, joint in enumerate(joints):
        data.qvel[joint.dofadr[0]] = qd0[6 + k]
    face_the_anchors()
    mujoco.mj_forward(model, data)
    body = model.body("platform").id
    worst_p = worst_R = 0.0
    worst_j = np.zeros(6)
    swivel = []
    for k, t in enumerate(run.times):
        q = run.poses[k]
        worst_p = max(worst_p, np.abs(data.xpos[body] - q[:3]).max())
        worst_j = np.maximum(worst_j, np.abs([data.qpos[j.qposadr[0]] for j in joints] - q[6:]))
        worst_R = max(
            worst_R, rotation_angle(data.xmat[body].reshape(3, 3), rotation_matrix(q[3:6], robot.orientation))
        )
        swivel.append(data.qpos[hinges].copy())
        if k + 1 < len(run.times):
            data.ctrl[:] = np.concatenate([tensions(t), joint_torques(t)])
            face_the_anchors()
            mujoco.mj_step(model, data)
    moved = np.abs(run.poses - q0).max(axis=0)
    turned = np.ptp(np.unwrap(np.array(swivel), axis=0), axis=0)
    print(
        f"moved {moved.round(4)}, swivels turned {turned.round(4)}; worst {worst_p:.2e} m {worst_R:.2e} rad {worst_j.max():.2e} rad"
    )
    assert moved[:3].max() > 0.01 and (moved[6:] > 0.05).all(), moved
    assert (turned > 1e-3).all(), turned
    assert worst_p <= 1e-6, worst_p
    assert worst_R <= 1e-6, worst_R
    assert worst_j.max() <= 1e-6, worst_j
