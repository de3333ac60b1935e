"""MuJoCo as an independent engine for a jointed platform: adjustable-8cable with assumed
masses (the built-in example's), exported to MJCF (``taut.model._mjcf``: the upper body
on a slide joint, cable tensions as tendon actuator controls, the joint's motor at zero: a
passive joint) and driven by the same tension profile, follows the motion of
``taut.dynamics.forward_dynamics`` over 1 s.  Both integrate with RK4 at the same step, the
tensions held over each step; MuJoCo integrates a quaternion and the angular velocity in the
body frame, taut the ``xyz-moving`` angles."""

import numpy as np
import pytest
from jointed_robots import adjustable

mujoco = pytest.importorskip("mujoco")

from mujoco_start import mujoco_start  # noqa: E402

from taut.dynamics import forward_dynamics, inverse_dynamics  # noqa: E402
from taut.geometry import rotation_matrix  # noqa: E402


def rotation_angle(Ra, Rb):
    """The angle of ``Raᵀ Rb`` [rad], from its skew part (exact for small angles)."""
    S = Ra.T @ Rb
    return float(np.linalg.norm([S[2, 1] - S[1, 2], S[0, 2] - S[2, 0], S[1, 0] - S[0, 1]]) / 2)


def test_same_motion_as_mujoco():
    """The tensions that hold the platform at rest plus 15 N sines per cable, from a moving
    start: over 1 s the platform moves up to 23 cm and turns up to 0.16 rad, the upper body
    slides 9 cm on its joint, and at every 1 ms step the two engines agree to 1e-6 m in the
    platform's position and the joint coordinate and 1e-6 rad in its orientation (measured:
    1.4e-9 m, 8e-14 m on the joint and 2.2e-9 rad, the truncation errors of two RK4s in
    different coordinates)."""
    dt = 1e-3
    robot = adjustable()
    q0 = np.array([5.0, 5.0, 1.5, 0.02, -0.01, 0.03, 1.5])
    qd0 = np.array([0.02, -0.01, 0.03, 0.05, -0.04, 0.06, 0.02])
    hold = inverse_dynamics(robot, q0, np.zeros(7), np.zeros(7), method="qp").tensions
    phase = np.arange(8)

    def tensions(t):
        return hold + 15.0 * np.sin(3 * t + phase)

    run = forward_dynamics(robot, q0, qd0, 1.0, tensions=tensions, method="RK4", step=dt)

    model, data = mujoco_start(robot, q0, qd0, dt)
    slide = model.joint("joint1")
    data.qvel[slide.dofadr[0]] = qd0[6]
    mujoco.mj_forward(model, data)
    body = model.body("platform").id
    worst_p = worst_j = worst_R = 0.0
    for k, t in enumerate(run.times):
        q = run.poses[k]
        worst_p = max(worst_p, np.abs(data.xpos[body] - q[:3]).max())
        worst_j = max(worst_j, abs(data.qpos[slide.qposadr[0]] - q[6]))
        worst_R = max(
            worst_R, rotation_angle(data.xmat[body].reshape(3, 3), rotation_matrix(q[3:6], robot.orientation))
        )
        if k + 1 < len(run.times):
            data.ctrl[:] = 0.0
            data.ctrl[: robot.n_cables] = tensions(t)
            mujoco.mj_step(model, data)
    moved = np.abs(run.poses - q0).max(axis=0)
    assert moved[:3].max() > 0.1 and moved[3:6].max() > 0.1 and moved[6] > 0.05  # a real motion
    assert not run.beyond_limits.any()
    assert worst_p <= 1e-6, worst_p
    assert worst_j <= 1e-6, worst_j
    assert worst_R <= 1e-6, worst_R
