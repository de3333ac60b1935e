"""MuJoCo as an independent engine: spatial-8cable exported to MJCF (``taut.model._mjcf``,
cable tensions as tendon actuator controls) and driven by the same tension profile follows
the same motion as ``taut.dynamics``.  Both integrate with RK4 at the same step, the tensions
held over each step (MuJoCo applies a control that way); MuJoCo integrates a quaternion and
the angular velocity in the body frame, taut the Euler angles of ``xyz-fixed``."""

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")

from mujoco_start import mujoco_start  # noqa: E402

from taut.dynamics import forward_dynamics  # noqa: E402
from taut.geometry import rotation_matrix  # noqa: E402
from taut.statics import distribute_tensions  # noqa: E402

DT = 1e-3


def test_same_motion_as_mujoco(spatial):
    q0 = np.array([0.05, -0.03, 0.08, 0.05, -0.04, 0.1])
    qd0 = np.array([0.1, 0.05, -0.1, 0.2, -0.1, 0.3])
    tau0 = distribute_tensions(spatial, q0, method="qp").tensions
    phase = np.arange(8)

    def tensions(t):
        return tau0 + 3.0 * (1 + np.sin(4 * t + phase))

    taut_run = forward_dynamics(spatial, q0, qd0, 1.0, tensions=tensions, method="RK4", step=DT)

    model, data = mujoco_start(spatial, q0, qd0, DT)
    mujoco.mj_forward(model, data)
    body = model.body("platform").id
    worst_p, worst_R, moved = 0.0, 0.0, 0.0
    for k, t in enumerate(taut_run.times):
        q = taut_run.poses[k]
        worst_p = max(worst_p, np.abs(data.xpos[body] - q[:3]).max())
        worst_R = max(worst_R, np.abs(data.xmat[body].reshape(3, 3) - rotation_matrix(q[3:6])).max())
        moved = max(moved, np.abs(q[:3] - q0[:3]).max())
        if k + 1 < len(taut_run.times):
            data.ctrl[:] = tensions(t)
            mujoco.mj_step(model, data)
    assert moved > 0.05  # a real motion, not a platform at rest
    # measured: 5e-8 m and 5e-7 in R (RK4 in different coordinates, errors amplified by the
    # open-loop instability of the crossed cables); the issue asks 1e-4 m over 1 s
    assert worst_p <= 1e-5, worst_p
    assert worst_R <= 1e-5, worst_R
