"""A MuJoCo model of a taut robot started where taut's forward dynamics starts: shared by the
MuJoCo cross-checks of the dynamics."""

from taut.geometry import rate_matrix, rotation_matrix
from taut.model import mjcf_text, pose_to_qpos


def mujoco_start(robot, q0, qd0, dt):
    """``(model, data)`` of ``robot``'s exported model at the pose ``q0`` with the pose rates
    ``qd0`` (platform first; the free joint's ω is in the body frame), stepped by RK4 at ``dt``.
    The rates of jointed bodies beyond the platform's are the caller's to set."""
    import mujoco

    model = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    model.opt.timestep = dt
    model.opt.integrator = mujoco.mjtIntegrator.mjINT_RK4
    data = mujoco.MjData(model)
    data.qpos[:] = pose_to_qpos(robot, q0)
    data.qvel[:3] = qd0[:3]
    R0 = rotation_matrix(q0[3:6], robot.orientation)
    data.qvel[3:6] = R0.T @ rate_matrix(q0[3:6], robot.orientation) @ qd0[3:6]
    return model, data
