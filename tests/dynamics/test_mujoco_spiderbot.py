"""MuJoCo as an independent engine for CASPR's SpiderBot (a UR3 arm on six actuated joints
carried by eight cables; the masses and inertias its file gives, the base's marked as a guess
there), exported to MJCF (``taut.model._mjcf``: the arm as a chain of hinge bodies, cable
tensions as tendon actuator controls, the joint motors' controls the joint torques) and driven
by the same tension and joint-torque profile, follows the motion of
``taut.dynamics.forward_dynamics`` over 1 s, the arm's joint coordinates included.  Both
integrate with RK4 at the same step, the inputs held over each step.

With the default cable set the cables leave through swivelling pulleys.  taut's pulleys are
massless: each turns at once to face its cable's anchor.  In the exported model each is a
hinged wheel the tendon wraps, whose free motion is not taut's; so before every MuJoCo step
each hinge is set to the angle that faces the anchor *in MuJoCo's state*, and to that angle's
rate (MuJoCo's own velocity integrated over a short time), and the wheels' dynamics play no
part.  The tendon's path over the wheel, its length and the force it puts on the platform are
MuJoCo's."""

from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

from taut.dynamics import forward_dynamics, inverse_dynamics  # noqa: E402
from taut.geometry import angles_from_matrix, rate_matrix, rotation_matrix  # noqa: E402
from taut.model import load_robot, mjcf_text, pose_to_qpos  # noqa: E402

SPIDER = Path(__file__).parents[1] / "model" / "fixtures" / "caspr" / "real" / "SpiderBot_UR3_bodies.xml"

#: Time over which MuJoCo's velocity is integrated to give each pulley hinge's rate [s].
RATE_STEP = 1e-7

#: A moving start: base velocity and turn, every joint turning.
QD0 = np.array([0.02, -0.01, 0.03, 0.05, -0.04, 0.06, 0.1, -0.1, 0.2, 0.1, -0.2, 0.3])


def rotation_angle(Ra, Rb):
    """The angle of ``Raᵀ Rb`` [rad], from its skew part (exact for small angles)."""
    S = Ra.T @ Rb
    return float(np.linalg.norm([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2)


@dataclass
class Followed:
    moved: np.ndarray  #: largest change of each coordinate over taut's motion
    position: float  #: worst base position difference [m]
    rotation: float  #: worst base rotation difference [rad]
    joints: np.ndarray  #: worst difference of each joint coordinate [rad]
    swivels: np.ndarray  #: the pulley hinge angles at every step (steps, pulleys)


def follow(robot, q0, dt=1e-3):
    """Drive taut and MuJoCo with the tensions and joint torques that hold ``robot`` at rest at
    ``q0`` (taut's inverse dynamics, the arm's joints actuated) plus 10 N and a 10 N sine per
    cable and 0.3 N m sines per joint, from ``q0`` moving at :data:`QD0`, for 1 s; compare at
    every step."""
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

    run = forward_dynamics(robot, q0, QD0, 1.0, tensions=tensions, wrench=wrench, method="RK4", step=dt)

    model = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    model.opt.timestep = dt
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(model)
    joints = [model.joint(f"joint{k}") for k in range(1, 7)]
    hinges = [model.joint(f"swivel{i + 1}") for i in robot.swivel_cables]
    hinge_pos = np.array([h.qposadr[0] for h in hinges], dtype=int)
    hinge_dof = np.array([h.dofadr[0] for h in hinges], dtype=int)

    def pose_of(qpos):
        R = np.empty(9)
        mujoco.mju_quat2Mat(R, qpos[3:7])
        angles = angles_from_matrix(R.reshape(3, 3), robot.orientation)
        return np.concatenate([qpos[:3], angles, [qpos[j.qposadr[0]] for j in joints]])

    def face_the_anchors():
        if not hinges:
            return
        now = pose_to_qpos(robot, pose_of(data.qpos))[hinge_pos]
        ahead = data.qpos.copy()
        mujoco.mj_integratePos(model, ahead, data.qvel, RATE_STEP)
        later = pose_to_qpos(robot, pose_of(ahead))[hinge_pos]
        data.qpos[hinge_pos] = now
        data.qvel[hinge_dof] = np.angle(np.exp(1j * (later - now))) / RATE_STEP

    data.qpos[:] = pose_to_qpos(robot, q0)
    R0 = rotation_matrix(q0[3:6], robot.orientation)
    data.qvel[:3] = QD0[:3]
    data.qvel[3:6] = R0.T @ rate_matrix(q0[3:6], robot.orientation) @ QD0[3:6]
    for k, joint in enumerate(joints):
        data.qvel[joint.dofadr[0]] = QD0[6 + k]
    face_the_anchors()
    mujoco.mj_forward(model, data)
    body = model.body("platform").id
    worst_p = worst_R = 0.0
    worst_j = np.zeros(6)
    swivels = []
    for k, t in enumerate(run.times):
        q = run.poses[k]
        worst_p = max(worst_p, np.abs(data.xpos[body] - q[:3]).max())
        worst_j = np.maximum(worst_j, np.abs([data.qpos[j.qposadr[0]] for j in joints] - q[6:]))
        worst_R = max(
            worst_R, rotation_angle(data.xmat[body].reshape(3, 3), rotation_matrix(q[3:6], robot.orientation))
        )
        swivels.append(data.qpos[hinge_pos].copy())
        if k + 1 < len(run.times):
            data.ctrl[:] = np.concatenate([tensions(t), joint_torques(t)])
            face_the_anchors()
            mujoco.mj_step(model, data)
    moved = np.abs(run.poses - q0).max(axis=0)
    return Followed(moved, worst_p, worst_R, worst_j, np.unwrap(np.array(swivels), axis=0))


def test_same_motion_as_mujoco():
    """Straight cables (the file's ``set_IPAnema_inspired``): over 1 s the base moves by
    decimetres and turns, every joint turns, and at every 1 ms step the two engines agree to
    1e-6 m in the base's position, 1e-6 rad in its orientation and in each joint coordinate
    (measured: 2.6e-9 m, 1.6e-8 rad, 2.4e-10 rad on the joints)."""
    robot = load_robot(SPIDER, cable_set="set_IPAnema_inspired")
    got = follow(robot, np.array([0.0, 0.0, 0.3, 0.02, -0.01, 0.03, 0.1, -0.3, 0.4, 0.1, -1.5708, 0.05]))
    assert got.moved[:3].max() > 0.01 and (got.moved[6:] > 0.05).all(), got.moved  # a real motion, every joint
    assert got.position <= 1e-6 and got.rotation <= 1e-6 and got.joints.max() <= 1e-6, got


def test_same_motion_as_mujoco_through_swivelling_pulleys():
    """The default cable set, through eight swivelling pulleys: the same bounds while every
    pulley swivels by a tenth of a radian or more (measured: 1.9e-9 m, 2.2e-9 rad, 2.5e-9 rad
    on the joints; left free, MuJoCo's wheels spin off by radians and the base is 3.6 mm
    away)."""
    robot = load_robot(SPIDER)
    assert len(robot.swivel_cables) == robot.n_cables == 8
    got = follow(robot, np.array([1.445, 1.0005, 0.9025, 0.02, -0.01, 0.03, 0.1, -0.3, 0.4, 0.1, -1.5708, 0.05]))
    assert got.moved[:3].max() > 0.01 and (got.moved[6:] > 0.05).all(), got.moved
    assert (np.ptp(got.swivels, axis=0) > 0.05).all(), np.ptp(got.swivels, axis=0)
    assert got.position <= 1e-6 and got.rotation <= 1e-6 and got.joints.max() <= 1e-6, got
