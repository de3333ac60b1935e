"""Swivelling pulleys in the MuJoCo model, checked by MuJoCo itself: over each pulley's body,
turned to taut's swivel angle, the tendon wraps the arc that taut's cable wraps (same length,
same tangent point), taut's tensions hold the platform still, and the cable puts no moment on
the pulley's hinge; the poses refused are the ones MuJoCo would wrap the other way."""

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import taut
from taut.errors import InfeasiblePoseError
from taut.geometry import rotation_matrix
from taut.kinematics import anchor_points, inverse_kinematics, swivel_parameters, swivel_paths
from taut.model import load_robot, robot_from_dict, robot_to_dict
from taut.model._mjcf import (
    PULLEY_MASS_RATIO,
    SIDE_SITE_ANGLE,
    mjcf_text,
    pose_to_qpos,
    swivel_frames,
    swivel_wraps_agree,
)
from taut.statics import distribute_tensions, external_wrench

mujoco = pytest.importorskip("mujoco")

FIXTURES = Path(__file__).parent / "fixtures"


def with_inertia(robot, seed):
    """``robot`` with a mass (if it has none) and the inertia of a solid box of random sides
    turned by a random rotation (the WireX fixtures give none)."""
    rng = np.random.default_rng(seed)
    data = robot_to_dict(robot)
    plat = dict(data["platform"])
    plat.setdefault("mass", 3.0)
    plat.setdefault("gravity", [0.0, 0.0, -9.81])
    if plat.get("kind", "rigid") == "rigid":
        a, b, c = rng.uniform(0.05, 0.6, 3)
        moments = plat["mass"] / 12 * np.array([b * b + c * c, a * a + c * c, a * a + b * b])
        Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        inertia = Q @ np.diag(moments) @ Q.T
        plat["inertia"] = [inertia[0, 0], inertia[1, 1], inertia[2, 2], inertia[0, 1], inertia[0, 2], inertia[1, 2]]
    data["platform"] = plat
    return robot_from_dict(data)


def odd_swivels(seed, point_mass=False):
    """spatial-8cable with a swivelling pulley of random axis and radius on each cable."""
    rng = np.random.default_rng(seed)
    data = robot_to_dict(taut.example("spatial-8cable"))
    for cable in data["cables"]:
        cable["swivel"] = {"axis": rng.normal(size=3).tolist(), "radius": float(rng.uniform(0.01, 0.1))}
        if point_mass:
            cable.pop("anchor")
    if point_mass:
        data["platform"] = {"kind": "point-mass", "mass": 2.0, "gravity": [0, 0, -9.81]}
        data.pop("reference")
    return robot_from_dict(data)


ROBOTS = {
    "IPAnema (WireX)": lambda: with_inertia(load_robot(FIXTURES / "wirex" / "IPAnema.wcrfx"), 1),
    "CoGiRo (WireX)": lambda: with_inertia(load_robot(FIXTURES / "wirex" / "CoGiRo.wcrfx"), 2),
    "pulleys 3R3T (WireX)": lambda: load_robot(FIXTURES / "wirex" / "pulleys_3r3t.wcrfx"),
    "pulley (CASPR, tilted axes)": lambda: load_robot(FIXTURES / "caspr" / "pulley_bodies.xml"),
    "random axes": lambda: with_inertia(odd_swivels(3), 4),
    "random axes, point mass": lambda: odd_swivels(5, point_mass=True),
}


def random_poses(robot, n, rng, spread=0.8, tilt=math.pi):
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    centre, half = (lo + hi) / 2, np.maximum((hi - lo) / 2, 1.0)
    pos = centre + spread * half * rng.uniform(-1, 1, (n, 3))
    if robot.is_point_mass:
        return pos
    return np.concatenate([pos, rng.uniform(-tilt, tilt, (n, 3))], axis=1)


def hanging_poses(robot, n, rng):
    """Poses below the exit points, along gravity, where a suspended robot holds its weight."""
    g = robot.weight / np.linalg.norm(robot.weight)
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    drop = np.outer(rng.uniform(0.2, 0.6, n) * (hi - lo).max() / 2, g)
    return random_poses(robot, n, rng, spread=0.3, tilt=0.2) + np.pad(drop, ((0, 0), (0, robot.pose_size - 3)))


def model_of(robot):
    m = mujoco.MjModel.from_xml_string(mjcf_text(robot))
    return m, mujoco.MjData(m)


def platform_dofs(robot):
    return 3 if robot.is_point_mass else 6


def generalised(robot, wrench, pose):
    """A platform wrench as MuJoCo's generalised force on the platform's joints (the
    freejoint takes the moment in the body frame)."""
    if robot.is_point_mass:
        return wrench
    R = rotation_matrix(pose[3:6], robot.orientation)
    return np.concatenate([wrench[:3], R.T @ wrench[3:]])


@pytest.mark.parametrize("name", list(ROBOTS))
def test_tendons_over_swivelling_pulleys_have_taut_lengths_and_tangent_points(name):
    """At 1,000 random poses (all but a few of 1,000 drawn, as few as the thin refused wedge
    allows) MuJoCo's tendon lengths equal taut's to 1e-9 m, and the point where MuJoCo's tendon
    leaves each pulley is taut's tangent point (which moves to first order with the swivel
    angle, where the length does not)."""
    robot = ROBOTS[name]()
    assert robot.swivel_cables
    rng = np.random.default_rng(31)
    poses = random_poses(robot, 1010, rng)
    agree = swivel_wraps_agree(robot, poses)
    assert agree.sum() >= 1000
    poses = poses[agree][:1000]
    expected = inverse_kinematics(robot, poses).lengths
    idx, axes, radii = swivel_parameters(robot)
    paths = swivel_paths(robot.exits[idx], axes, radii, anchor_points(robot, poses)[:, idx])
    m, data = model_of(robot)
    got = np.empty_like(expected)
    tangent = np.full(paths.tangent_points.shape, np.nan)
    for k, q in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = q
        mujoco.mj_fwdPosition(m, data)
        got[k] = data.ten_length
        for j, i in enumerate(idx):
            adr, num = data.ten_wrapadr[i], data.ten_wrapnum[i]
            if num == 4:  # exit site, the two tangent points on the wheel, anchor site
                tangent[k, j] = data.wrap_xpos.reshape(-1, 3)[adr + 2]
    assert np.abs(got - expected).max() < 1e-9
    wrapped = paths.wrap > 1e-3
    assert wrapped.mean() > 0.9
    assert not np.isnan(tangent[wrapped]).any()
    assert np.abs(tangent[wrapped] - paths.tangent_points[wrapped]).max() < 1e-9


@pytest.mark.parametrize("name", list(ROBOTS))
def test_taut_tensions_hold_the_platform_and_put_no_moment_on_the_pulleys(name):
    """At wrench-feasible poses taut's tension distribution, applied as the actuators'
    controls, gives MuJoCo's actuator force ``G(W τ)`` on the platform's joints and none on
    the pulleys' hinges; ``mj_inverse`` at rest asks for ``−w_ext`` on the platform and nothing
    of the hinges (each pulley's centre of mass is on its axis); so the residual
    ``qfrc_inverse − qfrc_actuator`` is taut's equilibrium residual on the platform and 0 on
    the hinges, to rounding."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(32)
    poses = np.concatenate([random_poses(robot, 200, rng, spread=0.3, tilt=0.3), hanging_poses(robot, 200, rng)])
    poses = poses[swivel_wraps_agree(robot, poses)]
    result = distribute_tensions(robot, poses)
    feasible = np.asarray(result.feasible)
    assert feasible.sum() >= 20, f"only {feasible.sum()} wrench-feasible poses"
    poses, tau = poses[feasible], result.tensions[feasible]
    W = inverse_kinematics(robot, poses).structure_matrix
    w = external_wrench(robot, poses)
    m, data = model_of(robot)
    n = platform_dofs(robot)
    assert m.nv == n + len(robot.swivel_cables)
    for k, q in enumerate(pose_to_qpos(robot, poses)):
        data.qpos[:] = q
        data.qvel[:] = 0
        data.ctrl[:] = tau[k]
        mujoco.mj_forward(m, data)
        actuator = data.qfrc_actuator.copy()
        data.qacc[:] = 0
        mujoco.mj_inverse(m, data)
        scale = np.abs(tau[k]).sum() + np.abs(w[k]).max()
        assert np.allclose(actuator[:n], generalised(robot, W[k] @ tau[k], poses[k]), rtol=0, atol=1e-12 * scale)
        assert np.allclose(data.qfrc_inverse[:n], generalised(robot, -w[k], poses[k]), rtol=0, atol=1e-12 * scale)
        residual = data.qfrc_inverse - actuator
        taut_residual = generalised(robot, W[k] @ tau[k] + w[k], poses[k])
        assert np.abs(taut_residual).max() <= 1e-9 * scale
        assert np.allclose(-residual[:n], taut_residual, rtol=0, atol=1e-12 * scale)
        assert np.abs(residual[n:]).max() <= 1e-12 * scale


def test_a_wrong_swivel_angle_puts_a_moment_on_the_hinge():
    """The hinge check above can fail: 0.01 rad off taut's swivel angle the cable turns the
    pulley with a moment of order ``τ r δq``, and the length changes only to second order,
    by ``moment · δq / (2 τ)`` (the length is quadratic in ``δq`` about taut's angle)."""
    robot = ROBOTS["pulleys 3R3T (WireX)"]()
    pose = np.array([0.1, -0.1, 1.0, 0.1, -0.2, 0.1])
    m, data = model_of(robot)
    tau, dq, r = 100.0, 0.01, robot.cables[0].swivel.radius
    data.qpos[:] = pose_to_qpos(robot, pose)
    data.ctrl[:] = tau
    mujoco.mj_forward(m, data)
    assert np.abs(data.qfrc_actuator[6:]).max() < 1e-12 * tau * r
    length = data.ten_length[0]
    data.qpos[7] += dq
    mujoco.mj_forward(m, data)
    moment = data.qfrc_actuator[6]
    assert abs(moment) > 0.1 * tau * r * dq
    assert np.abs(data.qfrc_actuator[7:]).max() < 1e-12 * tau * r
    assert abs(data.ten_length[0] - length) == pytest.approx(abs(moment) * dq / (2 * tau), rel=0.02)


def test_the_model_holds_the_pulleys_numbers():
    robot = ROBOTS["pulley (CASPR, tilted axes)"]()
    m, data = model_of(robot)
    idx, axes, e0, radii = swivel_frames(robot)
    data.qpos[:] = pose_to_qpos(robot, np.array([0.0, 0.0, 1.0, 0.0, 0.0, 0.0]))
    mujoco.mj_kinematics(m, data)
    for j, i in enumerate(idx):
        c = i + 1
        hinge = m.joint(f"swivel{c}")
        assert np.allclose(data.xaxis[hinge.id], axes[j], atol=1e-15)
        assert np.allclose(data.xanchor[hinge.id], robot.exits[i], atol=1e-15)
        body = m.body(f"pulley{c}")
        assert body.mass[0] == pytest.approx(PULLEY_MASS_RATIO * robot.platform.mass)
        # the centre of mass on the axis: the weight has no moment about the hinge
        assert np.allclose(data.xipos[body.id], robot.exits[i], atol=1e-15)
        wheel = m.geom(f"wheel{c}")
        assert wheel.size[0] == radii[j]
        assert abs(data.geom_xmat[wheel.id].reshape(3, 3)[:, 2] @ axes[j]) < 1e-15  # wheel axis normal to k
        assert np.isclose(np.linalg.norm(data.site(f"exit{c}").xpos - data.geom_xpos[wheel.id]), radii[j] * (1 + 1e-8))
        assert np.linalg.norm(data.site(f"exit{c}").xpos - robot.exits[i]) < 1e-8 * radii[j] + 1e-15


def test_convert_writes_the_swivelling_pulleys(taut_cli, tmp_path):
    """``taut convert`` of CASPR's pulley model, as a user runs it: MuJoCo loads the file and,
    at the qpos of a pose, its tendon lengths are those ``taut ik`` prints."""
    out = tmp_path / "pulley.mjcf.xml"
    source = str(FIXTURES / "caspr" / "pulley_bodies.xml")
    assert taut_cli("convert", source, str(out), "--json").json()["format"] == "mujoco"
    m = mujoco.MjModel.from_xml_path(str(out))
    assert (m.nbody, m.njnt, m.ntendon, m.nu) == (10, 9, 8, 8)
    pose = np.array([0.1, -0.2, 1.1, 0.2, -0.1, 0.3])
    data = mujoco.MjData(m)
    data.qpos[:] = pose_to_qpos(load_robot(source), pose)
    mujoco.mj_fwdPosition(m, data)
    ik = taut_cli("ik", source, "--pose", ",".join(map(str, pose)), "--json").json()
    np.testing.assert_allclose(data.ten_length, ik["lengths"], rtol=0, atol=1e-9)


def one_cable(axis, radius=0.1):
    """A point mass on one cable over a swivelling pulley at the origin."""
    return robot_from_dict(
        {
            "format": "taut/1",
            "name": "one pulley",
            "dimension": 3,
            "platform": {"kind": "point-mass", "mass": 1.0, "gravity": [0, 0, -9.81]},
            "cables": [{"exit": [0, 0, 0], "swivel": {"axis": axis, "radius": radius}}],
        }
    )


@pytest.mark.parametrize("angle, agrees", [(0.5 * SIDE_SITE_ANGLE, False), (1.5 * SIDE_SITE_ANGLE, True)])
def test_the_refused_wedge_is_where_mujoco_wraps_the_other_way(angle, agrees):
    """An anchor just outside the pulley rim, behind the exit point and nearer the axis than
    the pulley centre: within the side site's angle below ``−e`` MuJoCo's tendon goes round
    the other way (a length far from taut's), and ``pose_to_qpos`` refuses the pose; just
    beyond that angle it agrees with taut."""
    r = 0.1
    robot = one_cable([0.3, -0.2, 0.9], r)
    _, k, e0, _ = swivel_frames(robot)
    k, e0 = k[0], e0[0]
    rho = r * (1 + 1 / math.cos(angle)) / 2  # outside the rim, nearer the axis than the centre
    anchor = r * e0 + rho * (-math.cos(angle) * e0 - math.sin(angle) * k)
    assert swivel_wraps_agree(robot, anchor) == agrees
    expected = inverse_kinematics(robot, anchor).lengths[0]
    m, data = model_of(robot)
    data.qpos[:] = np.append(anchor, 0.0)  # the anchor lies in the plane of the hinge angle 0
    mujoco.mj_fwdPosition(m, data)
    if agrees:
        assert abs(data.ten_length[0] - expected) < 1e-9
        assert np.allclose(pose_to_qpos(robot, anchor), data.qpos, rtol=0, atol=1e-15)
    else:
        assert abs(data.ten_length[0] - expected) > 0.1 * r
        with pytest.raises(
            InfeasiblePoseError,
            match="anchor of cable 1 is on or inside its swivelling pulley's circle, or just outside it behind",
        ):
            pose_to_qpos(robot, anchor)


def test_an_anchor_inside_the_pulley_circle_is_refused():
    robot = one_cable([0, 0, 1], 0.1)
    _, _, e0, _ = swivel_frames(robot)
    anchor = 0.1 * e0[0] + np.array([0, 0, 0.05])
    assert not swivel_wraps_agree(robot, anchor)
    with pytest.raises(InfeasiblePoseError, match="at pose 2 the anchor of cable 1"):
        pose_to_qpos(robot, np.stack([anchor + [0, 0, 1], anchor]))


@pytest.mark.slow
@settings(max_examples=300, deadline=None)
@given(
    st.lists(st.floats(-1.0, 1.0), min_size=3, max_size=3).filter(lambda v: np.linalg.norm(v) > 0.1),
    st.floats(1e-3, 1.0),
    # half the draws near the refused wedge, just below -e
    st.one_of(st.floats(-math.pi, math.pi), st.floats(-math.pi, -math.pi + 2 * SIDE_SITE_ANGLE)),
    st.one_of(st.floats(1e-6, 100.0), st.floats(1e-6, 0.05)),
)
def test_mujoco_wraps_as_taut_exactly_where_swivel_wraps_agree_says(axis, r, phi, gap):
    """Any axis, radius and anchor in the pulley plane (the anchor at ``r (1 + gap)`` from the
    pulley centre, at the angle ``φ`` from ``e`` towards ``k``): where ``swivel_wraps_agree``
    holds MuJoCo's tendon has taut's length; where it does not, MuJoCo's length is far off."""
    robot = one_cable(axis, r)
    _, k, e0, _ = swivel_frames(robot)
    rho = r * (1 + gap)
    assume(rho * math.cos(phi) > -r * (1 - 1e-6))  # the anchor on the pulley centre's side of the axis
    anchor = r * e0[0] + rho * (math.cos(phi) * e0[0] + math.sin(phi) * k[0])
    expected = inverse_kinematics(robot, anchor).lengths[0]
    m, data = model_of(robot)
    data.qpos[:] = np.append(anchor, 0.0)
    mujoco.mj_fwdPosition(m, data)
    if swivel_wraps_agree(robot, anchor):
        assert abs(data.ten_length[0] - expected) < 1e-9
    else:
        assert abs(data.ten_length[0] - expected) > 1e-3 * r
