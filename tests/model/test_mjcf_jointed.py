"""Jointed platforms in MuJoCo, checked by MuJoCo itself: each of ``platform.bodies`` is a
child body on a hinge or slide joint, its frame at every pose is taut's, its tendon lengths
are taut's inverse kinematics, and MuJoCo's inverse dynamics at rest is taut's jointed
statics: the platform rows of ``W τ + w_ext = 0`` and the joint forces ``ζ``
(Lieskovský 2020, Eq. 3.3.12), each joint's generalised force along ``+axis``."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taut
from taut.geometry import rotation_matrix
from taut.kinematics import body_frames, inverse_kinematics, joint_forces
from taut.model import JointActuator, robot_from_dict, robot_to_dict
from taut.model._mjcf import joint_frames, joint_order, mjcf_text, pose_to_qpos, swivel_wraps_agree
from taut.statics import distribute_tensions, external_wrench

mujoco = pytest.importorskip("mujoco")

from jointed_robots import ROBOTS  # noqa: E402


def random_poses(robot, n, rng, spread=0.5, tilt=0.4):
    """Platform poses around the centre of the exit points (positions within ``spread`` of
    the half-extent of the frame, angles within ``tilt``), joint coordinates uniform strictly
    inside their limits (where MuJoCo's joint limits do not push)."""
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    centre, half = (lo + hi) / 2, (hi - lo) / 2
    d = robot.dimension
    pos = centre + spread * half * rng.uniform(-1, 1, (n, d))
    ang = rng.uniform(-tilt, tilt, (n, robot.wrench_dim - d))
    limits = robot.joint_limits
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.uniform(1e-6, 1 - 1e-6, (n, robot.n_joints))
    poses = np.concatenate([pos, ang, q], axis=1)
    return poses[np.asarray(swivel_wraps_agree(robot, poses))]


def model_of(robot):
    m = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    return m, mujoco.MjData(m)


def dofs(robot, m):
    """MuJoCo's velocity addresses of the platform's freedoms and of taut's joints, in taut's order."""
    joints = [m.jnt_dofadr[m.joint(f"joint{k}").id] for k in range(1, robot.n_joints + 1)]
    return np.arange(robot.wrench_dim), np.array(joints)


def generalised(robot, wrench, pose):
    """A platform wrench (force in the fixed frame, moment about ``p``) as MuJoCo's platform
    generalised force: the freejoint takes the moment in the body frame."""
    if robot.dimension == 2:
        return wrench
    R = rotation_matrix(pose[3:6], robot.orientation)
    return np.concatenate([wrench[:3], R.T @ wrench[3:]])


def bodies(robot):
    """The 0-based indices of ``platform.bodies`` that are MuJoCo bodies: all but the joint
    frames, whose joints their child body carries."""
    return np.array([k for k in range(robot.n_joints) if k not in joint_frames(robot)], dtype=int)


def mass_matrix(m, data):
    M = np.zeros((m.nv, m.nv))
    column = np.zeros(m.nv)
    for j, e in enumerate(np.eye(m.nv)):
        mujoco.mj_mulM(m, data, column, e)
        M[:, j] = column
    return M


@pytest.mark.parametrize("name", list(ROBOTS))
def test_body_frames_and_tendon_lengths_are_taut_s(name):
    """At 1,000 random poses every body's frame in MuJoCo (from ``pose_to_qpos``) is taut's
    ``body_frames`` to 1e-12 and the tendon lengths are taut's IK lengths to 1e-9 m."""
    robot = ROBOTS[name]()
    poses = random_poses(robot, 1000, np.random.default_rng(31), spread=0.8, tilt=1.0)
    assert len(poses) == 1000
    expected = inverse_kinematics(robot, poses).lengths
    pos, rot = body_frames(robot, poses)
    d = robot.dimension
    m, data = model_of(robot)
    shown = bodies(robot)
    ids = [m.body(f"body{k + 1}").id for k in shown]
    got = np.empty_like(expected)
    frames = 0.0
    for k, qpos in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = qpos
        mujoco.mj_fwdPosition(m, data)
        got[k] = data.ten_length
        xpos = data.xpos[ids][:, :d]
        xmat = data.xmat[ids].reshape(-1, 3, 3)[:, :d, :d]
        frames = max(frames, np.abs(xpos - pos[k, shown + 1]).max(), np.abs(xmat - rot[k, shown + 1]).max())
    assert frames < 1e-12
    assert np.abs(got - expected).max() < 1e-9


@pytest.mark.parametrize("name", list(ROBOTS))
def test_inverse_dynamics_at_rest_is_jointed_statics(name):
    """At 1,000 random poses with random tensions ``τ`` within the bounds, the generalised
    force ``mj_inverse`` asks for at rest, less the tendons' (MuJoCo's own tendon Jacobian),
    is taut's: ``−(W τ + w_ext)`` on the platform's freedoms (the bodies' weights included)
    and the joint forces ``ζ`` of :func:`joint_forces` on the joints, to 1e-12 relative."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(32)
    poses = random_poses(robot, 1000, rng, tilt=1.0)
    tmin, tmax = robot.tension_bounds
    tau = rng.uniform(tmin, np.minimum(tmax, tmin + 100.0), (len(poses), robot.n_cables))
    W = inverse_kinematics(robot, poses).structure_matrix
    w = external_wrench(robot, poses)
    zeta = joint_forces(robot, poses, tau)
    m, data = model_of(robot)
    platform, joints = dofs(robot, m)
    n = robot.n_cables
    for k, qpos in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = qpos
        data.qvel[:] = 0
        data.ctrl[:] = 0
        data.ctrl[:n] = tau[k]
        mujoco.mj_forward(m, data)
        tendons = data.qfrc_actuator.copy()
        data.qacc[:] = 0
        mujoco.mj_inverse(m, data)
        rest = data.qfrc_inverse - tendons
        scale = np.abs(tau[k]).sum() + np.abs(w[k]).max()
        expected = generalised(robot, -(W[k] @ tau[k] + w[k]), poses[k])
        assert np.allclose(rest[platform], expected, rtol=0, atol=1e-12 * scale)
        assert np.allclose(rest[joints], zeta[k], rtol=0, atol=1e-12 * scale)


def hanging_poses(robot, n, rng, low=0.1, high=0.4):
    """Level poses low in the frame (heights between ``low`` and ``high`` of the exits' span
    above the lowest exit) with the joints in the middle half of their range, where suspended
    robots hold their weight."""
    poses = random_poses(robot, n, rng, spread=0.3, tilt=0.1)
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    d = robot.dimension
    poses[:, d - 1] = lo[d - 1] + (hi[d - 1] - lo[d - 1]) * rng.uniform(low, high, len(poses))
    limits = robot.joint_limits
    middle = (limits[:, 0] + limits[:, 1]) / 2
    poses[:, robot.wrench_dim :] = middle + (poses[:, robot.wrench_dim :] - middle) / 2
    return poses[np.asarray(swivel_wraps_agree(robot, poses))]


#: The robots whose cables hold their passive joints at poses of a random sample: the others'
#: passive joints hang where the cables across them and gravity balance (a set of measure zero
#: of their coordinates), so the test gives every joint of theirs an unbounded motor.
HELD_BY_CABLES = {"adjustable-8cable"}


def held(robot):
    """``robot`` with an unbounded motor on every joint (CASPR's ``actuated="true"``)."""
    bodies = tuple(
        b.model_copy(update={"joint": b.joint.model_copy(update={"actuator": JointActuator(force=(-np.inf, np.inf))})})
        for b in robot.platform.bodies
    )
    return robot.model_copy(update={"platform": robot.platform.model_copy(update={"bodies": bodies})})


@pytest.mark.parametrize("name", list(ROBOTS))
def test_distributed_tensions_and_joint_forces_hold_the_robot_still(name):
    """At the statically feasible poses among random ones (low ones too, below the exits,
    where the cables can hold a passive joint), taut's tension distribution on the tendons and
    its actuator forces on the drives of the actuated joints (zero on the passive ones):
    ``mj_inverse`` at rest finds nothing left to apply on the platform's freedoms (at most 1e-9
    relative, the bound of a feasible distribution) and exactly those forces on the joints,
    which are taut's joint forces ``ζ`` of the tensions, and ``mj_forward`` leaves the robot
    at rest."""
    robot = ROBOTS[name]()
    if name not in HELD_BY_CABLES:
        robot = held(robot)
    rng = np.random.default_rng(33)
    poses = np.concatenate(
        [
            random_poses(robot, 300, rng, spread=0.3, tilt=0.2),
            hanging_poses(robot, 300, rng),
            hanging_poses(robot, 300, rng, low=-0.9, high=0.0),
        ]
    )
    result = distribute_tensions(robot, poses)
    feasible = np.asarray(result.feasible)
    assert feasible.sum() >= 20, f"only {feasible.sum()} wrench-feasible poses"
    poses, tau = poses[feasible], result.tensions[feasible]
    zeta = np.zeros((len(poses), robot.n_joints))
    zeta[:, robot.actuated_joints] = result.actuator_forces[feasible]
    assert np.allclose(joint_forces(robot, poses, tau), zeta, rtol=0, atol=1e-9 * np.abs(tau).sum(axis=1).max())
    w = external_wrench(robot, poses)
    m, data = model_of(robot)
    platform, joints = dofs(robot, m)
    n = robot.n_cables
    for k, qpos in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = qpos
        data.qvel[:] = 0
        data.ctrl[:n] = tau[k]
        data.ctrl[n:] = 0
        mujoco.mj_forward(m, data)
        tendons = data.qfrc_actuator.copy()
        data.qacc[:] = 0
        mujoco.mj_inverse(m, data)
        rest = data.qfrc_inverse - tendons
        scale = np.abs(tau[k]).sum() + np.abs(w[k]).max()
        assert np.abs(rest[platform]).max() <= 1e-9 * scale
        assert np.allclose(rest[joints], zeta[k], rtol=0, atol=1e-12 * scale)
        data.ctrl[n:] = zeta[k]
        mujoco.mj_forward(m, data)
        assert np.allclose(data.qfrc_actuator[joints] - tendons[joints], zeta[k], rtol=0, atol=1e-12 * scale)
        assert np.abs(mass_matrix(m, data) @ data.qacc).max() <= 1e-9 * scale


def test_a_missing_joint_force_moves_the_arm():
    """The rest test above can fail: without the joint forces the bodies accelerate."""
    robot = ROBOTS["SpiderBot_UR3"]()
    poses = hanging_poses(robot, 100, np.random.default_rng(34))
    result = distribute_tensions(robot, poses)
    k = int(np.argmax(result.feasible))
    assert result.feasible[k]
    zeta = result.actuator_forces[k]
    assert robot.actuated_joints.tolist() == list(range(robot.n_joints))
    m, data = model_of(robot)
    data.qpos[:] = pose_to_qpos(robot, poses[k])
    data.ctrl[: robot.n_cables] = result.tensions[k]
    mujoco.mj_forward(m, data)
    assert np.abs(zeta).max() > 1
    assert np.abs(data.qacc[dofs(robot, m)[1]]).max() > 0.1


def test_the_model_holds_the_bodies_numbers():
    robot = ROBOTS["branching tree"]()
    m, _ = model_of(robot)
    assert (m.nq, m.nv, m.nu, m.ntendon) == (7 + 3, 6 + 3, 8 + 3, 8)
    names = {"platform": "platform"} | {b.name: f"body{k}" for k, b in enumerate(robot.platform.bodies, 1)}
    for k, body in enumerate(robot.platform.bodies, 1):
        b = m.body(f"body{k}")
        parent = names[body.parent]
        assert m.body(b.parentid[0]).name == parent
        assert b.mass[0] == body.mass
        R = np.zeros(9)
        mujoco.mju_quat2Mat(R, b.iquat)
        R = R.reshape(3, 3)
        xx, yy, zz, xy, xz, yz = body.inertia
        tensor = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
        assert np.allclose(R @ np.diag(b.inertia) @ R.T, tensor, atol=1e-12)
        assert np.allclose(b.ipos, body.com)
        j = m.joint(f"joint{k}")
        assert j.type[0] == (
            mujoco.mjtJoint.mjJNT_SLIDE if body.joint.kind == "prismatic" else mujoco.mjtJoint.mjJNT_HINGE
        )
        assert j.limited[0] == 1 and j.range.tolist() == list(body.joint.limits)
        drive = m.actuator(f"drive{k}")
        assert drive.trnid[0] == j.id and drive.gear[0] == 1 and drive.ctrllimited[0] == 0
    # cable 8 hangs from tip (body 3), a child of upper: MuJoCo's joints run upper, tip, side
    assert m.site_bodyid[m.site("anchor8").id] == m.body("body3").id
    assert joint_order(robot).tolist() == [0, 2, 1]
    assert [m.jnt_qposadr[m.joint(f"joint{k}").id] for k in (1, 2, 3)] == [7, 9, 8]


def test_bounded_joint_motors_limit_their_drives():
    """A joint actuator with finite bounds limits its drive's control to them in MuJoCo, which
    then clamps a larger command; an unbounded or missing one leaves the drive unlimited."""
    robot = ROBOTS["branching tree"]()
    bodies = list(robot.platform.bodies)
    for k, force in ((0, (-30.0, 30.0)), (1, (-5.0, float("inf")))):
        joint = bodies[k].joint.model_copy(update={"actuator": taut.model.JointActuator(force=force)})
        bodies[k] = bodies[k].model_copy(update={"joint": joint})
    robot = robot.model_copy(update={"platform": robot.platform.model_copy(update={"bodies": tuple(bodies)})})
    m, d = model_of(robot)
    assert m.actuator("drive1").ctrllimited[0] == 1 and m.actuator("drive1").ctrlrange.tolist() == [-30.0, 30.0]
    assert m.actuator("drive2").ctrllimited[0] == 0 and m.actuator("drive3").ctrllimited[0] == 0
    d.ctrl[:] = 0.0
    d.ctrl[m.actuator("drive1").id] = 100.0
    mujoco.mj_forward(m, d)
    assert d.actuator_force[m.actuator("drive1").id] == 30.0


def test_pose_to_qpos_puts_each_joint_coordinate_at_its_joint():
    robot = ROBOTS["branching tree"]()
    m, _ = model_of(robot)
    pose = np.array([5.0, 5.0, 3.0, 0.1, 0.2, 0.3, 2.5, 0.7, -0.3])
    qpos = pose_to_qpos(robot, pose)
    for k in range(1, 4):
        assert qpos[m.jnt_qposadr[m.joint(f"joint{k}").id]] == pose[5 + k]


@st.composite
def body_trees(draw):
    """spatial-8cable with 1–4 random bodies: each on the platform or an earlier body, on a
    prismatic or revolute joint with a random axis, origin and limits, with a random mass,
    centre of mass and physical inertia; each cable hangs from a random body."""
    data = robot_to_dict(taut.example("spatial-8cable"))
    data.pop("reference", None)
    data["platform"] |= {"inertia": [0.2, 0.3, 0.4, 0.01, 0.0, -0.02], "wrench_point": [0.01, 0.02, -0.03]}
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    bodies = []
    for k in range(draw(st.integers(1, 4))):
        lo = rng.uniform(-2, 0)
        bodies.append(
            {
                "name": f"b{k}",
                "parent": "platform" if k == 0 else str(rng.choice(["platform"] + [b["name"] for b in bodies])),
                "joint": {
                    "kind": str(rng.choice(["prismatic", "revolute"])),
                    "axis": rng.normal(size=3).tolist(),
                    "origin": rng.uniform(-0.3, 0.3, 3).tolist(),
                    "limits": [lo, lo + rng.uniform(0.5, 3)],
                },
                "mass": float(rng.uniform(0.1, 3)),
                "com": rng.uniform(-0.2, 0.2, 3).tolist(),
                "inertia": list(random_tensor(rng)),
            }
        )
    data["platform"]["bodies"] = bodies
    for cable in data["cables"]:
        k = int(rng.integers(-1, len(bodies)))
        if k >= 0:
            cable["body"] = bodies[k]["name"]
    return robot_from_dict(data), rng


def random_tensor(rng):
    """The inertia of a solid box of random sides, turned by a random rotation."""
    a, b, c = rng.uniform(0.05, 0.6, 3)
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    I = Q @ np.diag([b * b + c * c, a * a + c * c, a * a + b * b]) @ Q.T
    return I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2]


@pytest.mark.slow
@settings(max_examples=100, deadline=None)
@given(body_trees())
def test_any_body_tree_is_taut_s_kinematics_and_statics(tree):
    """For 100 random trees of bodies, at 20 random poses each: MuJoCo's body frames are taut's
    ``body_frames`` (1e-12), its tendon lengths taut's IK (1e-9 m), and ``mj_inverse`` at rest
    less the tendons' force is ``−(W τ + w_ext)`` on the platform and ``ζ`` on the joints
    (1e-12 relative)."""
    robot, rng = tree
    poses = random_poses(robot, 20, rng, tilt=1.0)
    tmin, tmax = robot.tension_bounds  # MuJoCo clamps a control to its range
    tau = rng.uniform(tmin, np.minimum(tmax, tmin + 50.0), (len(poses), robot.n_cables))
    ik = inverse_kinematics(robot, poses)
    w = external_wrench(robot, poses)
    zeta = joint_forces(robot, poses, tau)
    pos, rot = body_frames(robot, poses)
    m, data = model_of(robot)
    platform, joints = dofs(robot, m)
    shown = bodies(robot)
    ids = [m.body(f"body{k + 1}").id for k in shown]
    n = robot.n_cables
    for k, qpos in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = qpos
        data.qvel[:] = 0
        data.ctrl[:] = 0
        data.ctrl[:n] = tau[k]
        mujoco.mj_forward(m, data)
        assert np.abs(data.xpos[ids] - pos[k, shown + 1]).max() < 1e-12
        assert np.abs(data.xmat[ids].reshape(-1, 3, 3) - rot[k, shown + 1]).max() < 1e-12
        assert np.abs(data.ten_length - ik.lengths[k]).max() < 1e-9
        tendons = data.qfrc_actuator.copy()
        data.qacc[:] = 0
        mujoco.mj_inverse(m, data)
        rest = data.qfrc_inverse - tendons
        scale = np.abs(tau[k]).sum() + np.abs(w[k]).max()
        expected = generalised(robot, -(ik.structure_matrix[k] @ tau[k] + w[k]), poses[k])
        assert np.allclose(rest[platform], expected, rtol=0, atol=1e-12 * scale)
        assert np.allclose(rest[joints], zeta[k], rtol=0, atol=1e-12 * scale)
