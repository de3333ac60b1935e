"""MuJoCo as an independent engine for CASPR's SpiderBot (a UR3 arm on six actuated joints
carried by eight cables; the masses and inertias its file gives, the base's marked as a guess
there), exported to MJCF (``taut.model._mjcf``: the arm as a chain of hinge bodies, cable
tensions as tendon actuator controls, the joint motors' controls the joint torques) and driven
by the same tension and joint-torque profile, follows the motion of
``taut.dynamics.forward_dynamics`` over 1 s, the arm's joint coordinates included.  Both
integrate with RK4 at the same step, the inputs held over each step."""

from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

from taut.dynamics import forward_dynamics, inverse_dynamics  # noqa: E402
from taut.geometry import rate_matrix, rotation_matrix  # noqa: E402
from taut.model import load_robot, mjcf_text, pose_to_qpos  # noqa: E402

SPIDER = Path(__file__).parents[1] / "model" / "fixtures" / "caspr" / "real" / "SpiderBot_UR3_bodies.xml"


def rotation_angle(Ra, Rb):
    """The angle of ``Raᵀ Rb`` [rad], from its skew part (exact for small angles)."""
    S = Ra.T @ Rb
    return float(np.linalg.norm([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2)


def test_same_motion_as_mujoco():
    """The tensions and joint torques that hold SpiderBot at rest (taut's inverse dynamics,
    the arm's joints actuated) plus 10 N and a 10 N sine per cable and 0.3 N m sines per joint, from a
    moving start: over 1 s the base moves by decimetres and turns, and every joint turns, and at every
    1 ms step the two engines agree to 1e-6 m in the base's position, 1e-6 rad in its
    orientation and in each joint coordinate (measured: 2.6e-9 m, 1.6e-8 rad, 2.4e-10 rad on
    the joints).  The cable set is the file's ``set_IPAnema_inspired``, whose cables run
    straight; the default set, through swivelling pulleys, is checked in
    ``test_mujoco_spiderbot_pulleys.py``."""
    dt = 1e-3
    robot = load_robot(SPIDER, cable_set="set_IPAnema_inspired")
    q0 = np.array([0.0, 0.0, 0.3, 0.02, -0.01, 0.03, 0.1, -0.3, 0.4, 0.1, -1.5708, 0.05])
    qd0 = np.array([0.02, -0.01, 0.03, 0.05, -0.04, 0.06, 0.1, -0.1, 0.2, 0.1, -0.2, 0.3])
    need = inverse_dynamics(robot, q0, np.zeros(12), np.zeros(12), method="qp")
    assert need.feasible
    hold, torques = need.tensions, need.actuator_forces
    phase = np.arange(robot.n_cables)

    def tensions(t):
        # within the tension actuators' control range, which starts at 0 N
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
    data.qpos[:] = pose_to_qpos(robot, q0)
    R0 = rotation_matrix(q0[3:6], robot.orientation)
    data.qvel[:3] = qd0[:3]
    data.qvel[3:6] = R0.T @ rate_matrix(q0[3:6], robot.orientation) @ qd0[3:6]
    joints = [model.joint(f"joint{k}") for k in range(1, 7)]
    for k, joint in enumerate(joints):
        data.qvel[joint.dofadr[0]] = qd0[6 + k]
    mujoco.mj_forward(model, data)
    body = model.body("platform").id
    worst_p = worst_R = 0.0
    worst_j = np.zeros(6)
    for k, t in enumerate(run.times):
        q = run.poses[k]
        worst_p = max(worst_p, np.abs(data.xpos[body] - q[:3]).max())
        worst_j = np.maximum(worst_j, np.abs([data.qpos[j.qposadr[0]] for j in joints] - q[6:]))
        worst_R = max(
            worst_R, rotation_angle(data.xmat[body].reshape(3, 3), rotation_matrix(q[3:6], robot.orientation))
        )
        if k + 1 < len(run.times):
            data.ctrl[:] = np.concatenate([tensions(t), joint_torques(t)])
            mujoco.mj_step(model, data)
    moved = np.abs(run.poses - q0).max(axis=0)
    assert moved[:3].max() > 0.01 and (moved[6:] > 0.05).all(), moved  # a real motion, every joint
    assert worst_p <= 1e-6, worst_p
    assert worst_R <= 1e-6, worst_R
    assert worst_j.max() <= 1e-6, worst_j
