"""The MuJoCo model of a robot, checked by MuJoCo itself: its tendon lengths are taut's
inverse kinematics, its inverse dynamics at rest is taut's static equilibrium, and taut's
tension distribution applied as actuator controls holds the platform still."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import taut
from taut.errors import UnsupportedRobotError
from taut.geometry import CONVENTIONS, rotation_matrix
from taut.kinematics import inverse_kinematics
from taut.model import example_names, robot_from_dict, robot_to_dict
from taut.model._mjcf import check_mjcf, mjcf_text, pose_to_qpos, quaternions, write_mjcf
from taut.statics import distribute_tensions, external_wrench

mujoco = pytest.importorskip("mujoco")

G = 9.81


def random_inertia(rng, mass, dimension):
    """The tensor of a solid box of random sides, turned by a random rotation: a physical
    body, with products of inertia."""
    a, b, c = rng.uniform(0.05, 0.6, 3)
    moments = mass / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])
    if dimension == 2:
        return (float(moments[2]),)
    Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    I = Q @ np.diag(moments) @ Q.T
    return (I[0, 0], I[1, 1], I[2, 2], I[0, 1], I[0, 2], I[1, 2])


def with_mass(robot, seed=0):
    """``robot`` with a mass and an inertia: a constant pure-force ``wrench`` becomes the
    weight of the mass that has it under 9.81 m/s², along its direction."""
    rng = np.random.default_rng(seed)
    data = robot_to_dict(robot)
    plat = dict(data.get("platform", {}))
    d = robot.dimension
    if "wrench" in plat:
        w = np.array(plat.pop("wrench"), float)
        assert not w[d:].any(), "a wrench with a moment is not a weight"
        plat["mass"] = float(np.linalg.norm(w[:d]) / G)
        plat["gravity"] = (w[:d] / plat["mass"]).tolist()
    plat.setdefault("mass", 2.0)
    if plat.get("kind", "rigid") == "rigid":
        plat["inertia"] = list(random_inertia(rng, plat["mass"], d))
    data["platform"] = plat
    return robot_from_dict(data)


def point_mass(name):
    data = robot_to_dict(taut.example(name))
    data["platform"] = {"kind": "point-mass", "mass": 1.5}
    data["cables"] = [{k: v for k, v in c.items() if k != "anchor"} for c in data["cables"]]
    data.pop("reference", None)
    return robot_from_dict(data)


def moving(robot):
    """The same robot with the orientation convention ``xyz-moving``."""
    return robot.model_copy(update={"orientation": "xyz-moving"})


ROBOTS = {
    "spatial-8cable": lambda: with_mass(taut.example("spatial-8cable"), 1),
    "spatial-8cable xyz-moving": lambda: moving(with_mass(taut.example("spatial-8cable"), 2)),
    "cogiro": lambda: with_mass(taut.example("cogiro"), 3),
    "suspended-3cable": lambda: with_mass(taut.example("suspended-3cable"), 4),
    "marionet-vr": lambda: with_mass(taut.example("marionet-vr"), 5),
    "teaching-prototype": lambda: with_mass(taut.example("teaching-prototype"), 6),
    "robocrane tilt-torsion": lambda: with_mass(taut.example("robocrane"), 7),
    "planar-4cable": lambda: with_mass(taut.example("planar-4cable"), 8),
    "spatial point mass": lambda: point_mass("spatial-8cable"),
    "planar point mass": lambda: point_mass("planar-4cable"),
}


def random_poses(robot, n, rng, spread=0.5, tilt=0.6):
    """Poses around the centre of the exit points: positions within ``spread`` of the
    half-extent of the frame, angles within ``tilt`` rad of zero (any convention), joint
    coordinates strictly inside their limits."""
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    centre, half = (lo + hi) / 2, (hi - lo) / 2
    half = np.where(half > 0, half, 1.0)
    d = robot.dimension
    pos = centre + spread * half * rng.uniform(-1, 1, (n, d))
    k = robot.wrench_dim - d
    ang = rng.uniform(-tilt, tilt, (n, k))
    if robot.orientation == "tilt-torsion" and k == 3:
        ang[:, 1] = np.abs(ang[:, 1])
    limits = robot.joint_limits
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.uniform(1e-6, 1 - 1e-6, (n, robot.n_joints))
    return np.concatenate([pos, ang, q], axis=1)


def model_of(robot):
    m = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    return m, mujoco.MjData(m)


def mass_matrix(m, data):
    """MuJoCo's joint-space inertia matrix, column by column (``mj_mulM`` has one signature
    across MuJoCo 3 and 4, ``mj_fullM`` has not)."""
    M = np.zeros((m.nv, m.nv))
    column = np.zeros(m.nv)
    for j, e in enumerate(np.eye(m.nv)):
        mujoco.mj_mulM(m, data, column, e)
        M[:, j] = column
    return M


def generalised(robot, wrench, R):
    """A platform wrench (force in the fixed frame, moment about ``p``) as MuJoCo's
    generalised force: a freejoint takes the force in the world frame and the moment in the
    body frame (``Rᵀ m``, its angular velocity is local); slide/hinge joints take the
    components along their axes."""
    if robot.dimension == 3 and not robot.is_point_mass:
        return np.concatenate([wrench[:3], R.T @ wrench[3:]])
    return wrench


@pytest.mark.parametrize("name", list(ROBOTS))
def test_tendon_lengths_are_taut_lengths(name):
    """At 1,000 random poses MuJoCo's tendon lengths equal taut's IK lengths to 1e-9 m, and
    the platform frame MuJoCo builds from ``qpos`` is taut's."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(11)
    poses = random_poses(robot, 1000, rng, spread=0.9, tilt=math.pi)
    expected = inverse_kinematics(robot, poses).lengths
    qpos = pose_to_qpos(robot, poses)
    m, data = model_of(robot)
    body = m.body("platform").id
    got = np.empty_like(expected)
    for k in range(len(poses)):
        data.qpos[:] = qpos[k]
        mujoco.mj_fwdPosition(m, data)
        got[k] = data.ten_length
        if not robot.is_point_mass and robot.dimension == 3:
            assert np.allclose(
                data.xmat[body].reshape(3, 3), rotation_matrix(poses[k, 3:6], robot.orientation), atol=1e-12
            )
    assert np.abs(got - expected).max() < 1e-9


#: Why each built-in example the MuJoCo model cannot hold is refused (words of the message);
REFUSED_EXAMPLES = {
    "cogiro": "no platform.mass",
    "cogiro-sagging": "cable 1 has a weight",
    "marionet-vr": "no platform.mass",
    "robocrane": "no platform.mass",
    "suspended-3cable": "no platform.mass",
    "suspended-3pulley": "no platform.mass",
    "teaching-prototype": "no platform.mass",
    "vscr-agriculture": "obstacles",
    "vscr-four-cable": "obstacles",
    "vscr-rehabilitation": "obstacles",
    "vscr-rigid-t-shaped": "obstacles",
    "vscr-single-cable": "obstacles",
    "vscr-t-shaped": "obstacles",
}


@pytest.mark.parametrize("name", example_names())
def test_every_builtin_example_is_exported_or_refused_by_name(name, tmp_path, taut_cli):
    """Every built-in example either becomes a model whose tendon lengths are taut's IK at
    1,000 random poses (through ``taut convert``, as a user runs it), or is refused with
    its reason; the examples with a mass (spatial-8cable, planar-4cable, the point-mass
    camera-4cable and printer-5cable, and adjustable-8cable with its jointed body) are exported."""
    robot = taut.example(name)
    out = tmp_path / "robot.mjcf.xml"
    run = taut_cli("convert", name, str(out))
    if name in REFUSED_EXAMPLES:
        with pytest.raises(UnsupportedRobotError, match=REFUSED_EXAMPLES[name]):
            check_mjcf(robot)
        assert run.code == 2 and not out.exists()
        assert REFUSED_EXAMPLES[name] in run.err and run.err.count("\n") == 1
        return
    assert run.code == 0, run.err
    m = mujoco.MjModel.from_xml_path(str(out))
    data = mujoco.MjData(m)
    poses = random_poses(robot, 1000, np.random.default_rng(21), spread=0.9, tilt=math.pi)
    expected = inverse_kinematics(robot, poses).lengths
    got = np.empty_like(expected)
    for k, q in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = q
        mujoco.mj_fwdPosition(m, data)
        got[k] = data.ten_length
    assert np.abs(got - expected).max() < 1e-9
    assert m.body("platform").mass[0] == robot.platform.mass


def test_the_examples_with_a_mass_are_the_exported_ones():
    """The table above is not stale: exactly the examples it does not list pass the check."""
    exported = set()
    for name in example_names():
        try:
            check_mjcf(taut.example(name))
        except UnsupportedRobotError:
            continue
        exported.add(name)
    assert exported == set(example_names()) - set(REFUSED_EXAMPLES)
    assert exported == {
        "adjustable-8cable",
        "spatial-8cable",
        "planar-4cable",
        "planar-2cable",
        "camera-4cable",
        "printer-5cable",
    }


@pytest.mark.parametrize("name", list(ROBOTS))
def test_inverse_dynamics_at_rest_is_static_equilibrium(name):
    """``mj_inverse`` with zero velocity and acceleration gives the generalised force that
    holds the platform: taut's ``−w_ext`` in MuJoCo's generalised coordinates (at poses
    within the cables' length bounds, where no tendon limit pushes)."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(12)
    poses = random_poses(robot, 300, rng, tilt=math.pi)
    lengths = inverse_kinematics(robot, poses).lengths
    poses = poses[np.all(lengths <= robot.length_bounds[1], axis=1)]
    assert len(poses) >= 200
    w = external_wrench(robot, poses)
    qpos = pose_to_qpos(robot, poses)
    m, data = model_of(robot)
    scale = np.abs(w).max()
    assert scale > 0
    for k in range(len(poses)):
        data.qpos[:] = qpos[k]
        data.qvel[:] = 0
        data.qacc[:] = 0
        mujoco.mj_inverse(m, data)
        R = rotation_matrix(poses[k, 3:6], robot.orientation) if robot.wrench_dim == 6 else None
        assert np.allclose(data.qfrc_inverse, generalised(robot, -w[k], R), rtol=0, atol=1e-12 * scale)


def test_inverse_dynamics_sees_the_moment_of_an_offset_centre_of_mass():
    """The comparison above is not vacuous: at a tilted pose the weight at the centre of mass
    ``wrench_point`` has a moment about the platform origin, and MuJoCo finds it."""
    robot = ROBOTS["spatial-8cable"]()
    robot = robot.model_copy(update={"platform": robot.platform.model_copy(update={"wrench_point": (0.1, -0.05, 0.2)})})
    pose = np.array([0.1, 0.0, 0.2, 0.4, -0.3, 0.2])
    m, data = model_of(robot)
    data.qpos[:] = pose_to_qpos(robot, pose)
    mujoco.mj_inverse(m, data)
    R = rotation_matrix(pose[3:], robot.orientation)
    moment = np.cross(R @ np.array([0.1, -0.05, 0.2]), robot.weight)
    assert np.linalg.norm(moment) > 1
    assert np.allclose(data.qfrc_inverse[3:], -R.T @ moment, atol=1e-12)


def hanging_poses(robot, n, rng, tilt=0.2):
    """Poses below the exit points, along gravity, where suspended robots hold their weight."""
    d = robot.dimension
    g = robot.weight / np.linalg.norm(robot.weight)
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    centre, half = (lo + hi) / 2, (hi - lo) / 2
    pos = centre + 0.4 * half * rng.uniform(-1, 1, (n, d)) + np.outer(rng.uniform(0.2, 1.5, n) * half.max(), g)
    k = robot.wrench_dim - d
    ang = rng.uniform(-tilt, tilt, (n, k))
    if robot.orientation == "tilt-torsion" and k == 3:
        ang[:, 1] = np.abs(ang[:, 1])
    limits = robot.joint_limits
    q = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.uniform(1e-6, 1 - 1e-6, (n, robot.n_joints))
    return np.concatenate([pos, ang, q], axis=1)


def equilibrium_poses(robot, n, rng):
    """Equilibria of an underconstrained robot (fewer cables than platform freedoms): the
    position is fixed near a published pose, and Newton (``scipy.optimize.root``) finds the
    orientation and tensions with ``W τ + w_ext = 0``."""
    from scipy.optimize import root

    starts = np.array(list(robot.reference.poses.values()))
    out = []
    for start in starts[rng.integers(len(starts), size=n)]:
        start = start + np.concatenate([rng.uniform(-0.2, 0.2, 3), np.zeros(3)])

        def residual(x, start=start):
            pose = np.concatenate([start[:3], x[:3]])
            return inverse_kinematics(robot, pose).structure_matrix @ x[3:] + external_wrench(robot, pose)

        W = inverse_kinematics(robot, start).structure_matrix
        tau = np.linalg.lstsq(W, -external_wrench(robot, start), rcond=None)[0]
        x = root(residual, np.concatenate([start[3:], tau]), tol=1e-14).x
        if np.abs(residual(x)).max() < 1e-12:
            out.append(np.concatenate([start[:3], x[:3]]))
    return np.array(out)


@pytest.mark.parametrize("name", list(ROBOTS))
def test_distributed_tensions_hold_the_platform_still(name):
    """taut's tension distribution at wrench-feasible poses, applied as the actuators'
    controls, gives MuJoCo's generalised actuator force ``G(W τ)`` and leaves the platform
    at rest: the net generalised force ``M q̈`` equals taut's own equilibrium residual
    ``G(W τ + w_ext)`` (at most 1e-9 relative: the bound under which taut calls a
    distribution feasible) up to rounding, 1e-12 relative."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(13)
    if robot.n_cables < robot.wrench_dim:
        poses = equilibrium_poses(robot, 40, rng)
    else:
        poses = np.concatenate([random_poses(robot, 200, rng, spread=0.3, tilt=0.3), hanging_poses(robot, 200, rng)])
    result = distribute_tensions(robot, poses)
    feasible = np.asarray(result.feasible)
    assert feasible.sum() >= 20, f"only {feasible.sum()} wrench-feasible poses"
    poses, tau = poses[feasible], result.tensions[feasible]
    W = inverse_kinematics(robot, poses).structure_matrix
    w = external_wrench(robot, poses)
    qpos = pose_to_qpos(robot, poses)
    m, data = model_of(robot)
    for k in range(len(poses)):
        data.qpos[:] = qpos[k]
        data.qvel[:] = 0
        data.ctrl[:] = tau[k]
        mujoco.mj_forward(m, data)
        R = rotation_matrix(poses[k, 3:6], robot.orientation) if robot.wrench_dim == 6 else None
        scale = np.abs(tau[k]).sum() + np.abs(w[k]).max()
        assert np.allclose(data.qfrc_actuator, generalised(robot, W[k] @ tau[k], R), atol=1e-12 * scale)
        net = mass_matrix(m, data) @ data.qacc
        residual = generalised(robot, W[k] @ tau[k] + w[k], R)
        assert np.abs(residual).max() <= 1e-9 * scale
        assert np.allclose(net, residual, rtol=0, atol=1e-12 * scale)
        assert np.abs(data.qacc).max() < 1e-6


def test_a_wrong_tension_moves_the_platform():
    """The rest test above can fail: dropping one cable's tension accelerates the platform."""
    robot = ROBOTS["spatial-8cable"]()
    pose = np.zeros(6)
    tau = distribute_tensions(robot, pose).tensions
    m, data = model_of(robot)
    data.qpos[:] = pose_to_qpos(robot, pose)
    i = int(np.argmax(tau))
    data.ctrl[:] = tau
    data.ctrl[i] = robot.tension_bounds[0][i]
    mujoco.mj_forward(m, data)
    assert tau[i] > robot.tension_bounds[0][i] + 1
    assert np.abs(data.qacc).max() > 0.1


def test_the_model_holds_the_robot_numbers(tmp_path):
    robot = ROBOTS["spatial-8cable"]()
    path = tmp_path / "robot.mjcf.xml"
    write_mjcf(robot, path)
    m = mujoco.MjModel.from_xml_path(str(path))
    assert (m.nu, m.ntendon, m.nq, m.nv) == (8, 8, 7, 6)
    body = m.body("platform")
    assert body.mass[0] == robot.platform.mass
    # MuJoCo stores the principal moments and the frame of principal axes
    R = np.zeros(9)
    mujoco.mju_quat2Mat(R, body.iquat)
    R = R.reshape(3, 3)
    assert np.allclose(R @ np.diag(body.inertia) @ R.T, robot.inertia, atol=1e-12)
    assert np.allclose(body.ipos, robot.platform.wrench_point)
    assert np.allclose(m.opt.gravity, [0, 0, -9.81])
    lo, hi = robot.tension_bounds
    assert np.array_equal(m.actuator_ctrlrange, np.stack([lo, hi], 1))
    assert np.all(m.actuator_gear[:, 0] == -1)
    assert np.array_equal(m.site_pos[[m.site(f"exit{i}").id for i in range(1, 9)]], robot.exits)


def test_any_robot_name_is_valid_xml():
    robot = ROBOTS["planar point mass"]().model_copy(update={"name": 'a <b> & "c" -- d'})
    m, _ = model_of(robot)
    assert m.nu == 4


def test_length_bounds_are_tendon_ranges_and_infinite_tension_bounds_stay_infinite():
    data = robot_to_dict(ROBOTS["planar-4cable"]())
    data["cables"][0]["length"] = [0.5, 2.5]
    data["cables"][1]["tension"] = [0, math.inf]
    robot = robot_from_dict(data)
    m, _ = model_of(robot)
    assert m.tendon_limited.tolist() == [1, 0, 0, 0]
    assert m.tendon_range[0].tolist() == [0.5, 2.5]
    assert m.actuator_ctrlrange[1].tolist() == [0, math.inf]


def test_point_mass_rotational_inertia_does_not_act():
    """A point mass's body gets a tiny rotational inertia for MuJoCo's sake; its slide joints'
    mass matrix is the mass alone."""
    robot = ROBOTS["spatial point mass"]()
    m, data = model_of(robot)
    mujoco.mj_forward(m, data)
    assert np.array_equal(mass_matrix(m, data), 1.5 * np.eye(3))


@settings(max_examples=200, deadline=None)
@given(
    st.lists(st.floats(-10.0, 10.0), min_size=3, max_size=3),
    st.sampled_from(CONVENTIONS),
)
def test_quaternion_is_mujoco_rotation(angles, convention):
    R = rotation_matrix(angles, convention)
    q = quaternions(R)
    out = np.zeros(9)
    mujoco.mju_quat2Mat(out, q)
    assert np.isclose(np.linalg.norm(q), 1, atol=1e-15)
    assert q[0] >= 0
    assert np.allclose(out.reshape(3, 3), R, atol=1e-14)
