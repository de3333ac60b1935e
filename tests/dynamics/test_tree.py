"""Forward and inverse dynamics and control of jointed platforms (the compiled tree of
``taut.dynamics._tree`` behind ``acceleration``, ``forward_dynamics``, ``inverse_dynamics`` and
``simulate_control``), checked against the equations of motion of ``taut.dynamics._jointed``
(MuJoCo's to 1e-15: ``test_jointed.py``), against the conservation of energy with the kinetic
energy from finite differences of taut's body frames, and against the jointed structure
matrix of ``taut.kinematics``."""

from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from jointed_robots import SPIDERBOT, adjustable, branching, planar

from taut.dynamics import (
    WrenchSteps,
    acceleration,
    bias_forces,
    forward_dynamics,
    generalized_forces,
    inverse_dynamics,
    mass_matrix,
    simulate_control,
    with_mass_error,
)
from taut.errors import PoseError, UnsupportedRobotError
from taut.kinematics import body_frames, jointed_structure_matrix
from taut.model import load_robot
from taut.motion import trajectory_from_waypoints
from taut.statics import METHODS

ROBOTS = {"adjustable-8cable": adjustable, "branching tree": branching, "planar slider and arm": planar}
#: CASPR's SpiderBot: a 6-joint arm on a platform whose cables leave through swivelling pulleys.
WITH_PULLEYS = {"SpiderBot_UR3": lambda: load_robot(SPIDERBOT)}


def random_states(robot, n, rng, spread=0.3, tilt=0.5):
    """States around the centre of the exit points, joints strictly inside their limits."""
    lo, hi = robot.exits.min(0), robot.exits.max(0)
    d = robot.dimension
    pos = (lo + hi) / 2 + spread * (hi - lo) / 2 * rng.uniform(-1, 1, (n, d))
    ang = rng.uniform(-tilt, tilt, (n, robot.wrench_dim - d))
    limits = robot.joint_limits
    joints = limits[:, 0] + (limits[:, 1] - limits[:, 0]) * rng.uniform(0.1, 0.9, (n, robot.n_joints))
    q = np.concatenate([pos, ang, joints], axis=1)
    return q, rng.normal(0, 1, q.shape)


def cable_columns(robot, q):
    return jointed_structure_matrix(robot, q)[..., : robot.n_cables]


@pytest.mark.parametrize("name", list(ROBOTS | WITH_PULLEYS))
def test_accelerations_solve_the_equations_of_motion(name):
    """``M q̈ + h = Tᵀ (A τ + w)`` with taut's NumPy ``M``, ``h`` and ``T`` and the cable
    columns of the jointed structure matrix (through the pulleys' tangent points, SpiderBot),
    ``w`` a platform wrench and joint forces; measured 1e-15 relative."""
    robot = (ROBOTS | WITH_PULLEYS)[name]()
    rng = np.random.default_rng(50)
    q, qd = random_states(robot, 40, rng)
    tau = rng.uniform(10, 200, (40, robot.n_cables))
    w = rng.normal(0, 20, q.shape)
    qdd = acceleration(robot, q, qd, tau, wrench=w)
    Q = generalized_forces(robot, q, np.einsum("kij,kj->ki", cable_columns(robot, q), tau) + w)
    lhs = np.einsum("kij,kj->ki", mass_matrix(robot, q), qdd) + bias_forces(robot, q, qd)
    assert np.abs(lhs - Q).max() < 1e-11 * np.abs(Q).max()


def kinetic_energy(robot, q, qd, step=1e-6):
    """``Σ ½ m |ċ|² + ½ ωᵀ I ω`` with the velocities of the centres of mass and the angular
    velocities (``[ω]× = Ṙ Rᵀ``) by central differences of taut's body frames along ``q̇``."""
    plat = robot.platform
    # a massless frame between two joints of a chain has no mass and no inertia
    masses = np.array([plat.mass] + [b.mass or 0.0 for b in plat.bodies])
    zero = (0.0,) if robot.dimension == 2 else (0.0,) * 6
    inertias = [plat.inertia] + [b.inertia or zero for b in plat.bodies]
    d = robot.dimension
    com0 = np.zeros(d) if plat.wrench_point is None else np.array(plat.wrench_point)
    coms = np.concatenate([com0[None], robot.body_coms])

    def frames(x):
        pos, rot = body_frames(robot, x[None])
        return pos[0] + np.einsum("bij,bj->bi", rot[0], coms), rot[0]

    cp, Rp = frames(q + step * qd)
    cm, Rm = frames(q - step * qd)
    c0, R0 = frames(q)
    v = (cp - cm) / (2 * step)
    S = (Rp - Rm) / (2 * step) @ np.swapaxes(R0, 1, 2)
    energy = 0.5 * np.sum(masses * np.sum(v * v, axis=1))
    for b, values in enumerate(inertias):
        if d == 2:
            energy += 0.5 * values[0] * S[b, 1, 0] ** 2
            continue
        xx, yy, zz, xy, xz, yz = values
        w = R0[b].T @ np.array([S[b, 2, 1], S[b, 0, 2], S[b, 1, 0]])
        energy += 0.5 * w @ np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]) @ w
    potential = -np.sum(masses[:, None] * robot.gravity[None, :] * c0)
    return energy, potential


@pytest.mark.parametrize("name", ["branching tree", "planar slider and arm"])
def test_energy_is_conserved_without_cables(name):
    """Slack cables: the tree tumbles and falls; its kinetic energy (from finite differences
    of the body frames, not from ``M``) plus the potential of the weights stays constant over
    0.5 s of DOP853 (measured 2e-9 of the kinetic energy's range).  Wrong Coriolis or
    centripetal terms would pump energy in or out."""
    robot = ROBOTS[name]()
    rng = np.random.default_rng(51)
    q0, qd0 = random_states(robot, 1, rng)
    limits = robot.joint_limits
    q0[0, robot.wrench_dim :] = limits.mean(axis=1)
    qd0 = 3.0 * qd0
    n = robot.n_cables
    res = forward_dynamics(
        robot, q0[0], qd0[0], 0.5, tensions=lambda t: np.zeros(n), rtol=1e-12, atol=1e-12, times=np.linspace(0, 0.5, 11)
    )
    energies = np.array([sum(kinetic_energy(robot, q, v)) for q, v in zip(res.poses, res.velocity)])
    kinetic = np.array([kinetic_energy(robot, q, v)[0] for q, v in zip(res.poses, res.velocity)])
    assert np.ptp(kinetic) > 1.0  # energy moves between kinetic and potential
    assert np.ptp(energies) < 1e-7 * np.abs(kinetic).max(), np.ptp(energies)


def test_energy_is_conserved_through_massless_joint_frames():
    """CASPR's universal, spherical and planar-translation joints are chains of one-DOF joints
    through massless frames (``multidof_bodies.xml``): with slack cables the arm tumbles and
    its energy (finite differences of the body frames, the frames' zero masses counted as
    nothing) stays constant over 0.3 s of DOP853.  The joints' limits are widened: the
    model has no joint stops and the energy check takes the frames anywhere."""
    fixture = Path(__file__).parents[1] / "model" / "fixtures" / "caspr" / "multidof_bodies.xml"
    robot = load_robot(fixture)
    assert any(b.mass is None for b in robot.platform.bodies)
    free = tuple(
        b.model_copy(update={"joint": b.joint.model_copy(update={"limits": (-50.0, 50.0)})})
        for b in robot.platform.bodies
    )
    robot = robot.model_copy(update={"platform": robot.platform.model_copy(update={"bodies": free})})
    rng = np.random.default_rng(7)
    q0 = np.concatenate([[0.0, 0.0, 1.0, 0.1, -0.1, 0.05], rng.uniform(-0.3, 0.3, robot.n_joints)])
    qd0 = rng.normal(0, 1.0, robot.pose_size)
    n = robot.n_cables
    res = forward_dynamics(
        robot, q0, qd0, 0.3, tensions=lambda t: np.zeros(n), rtol=1e-12, atol=1e-12, times=np.linspace(0, 0.3, 7)
    )
    energies = np.array([sum(kinetic_energy(robot, q, v)) for q, v in zip(res.poses, res.velocity)])
    kinetic = np.array([kinetic_energy(robot, q, v)[0] for q, v in zip(res.poses, res.velocity)])
    assert np.ptp(kinetic) > 1.0
    assert np.ptp(energies) < 1e-7 * np.abs(kinetic).max(), np.ptp(energies)


@settings(max_examples=30, deadline=None)
@given(method=st.sampled_from(sorted(METHODS)), seed=st.integers(0, 2**32 - 1))
def test_inverse_dynamics_gives_the_generalized_force_with_the_jointed_structure_matrix(method, seed):
    """For every distribution method: the required generalized force is ``T⁻ᵀ (M q̈ + h)``
    (NumPy ``M``, ``h``), and the tensions of every feasible sample, within their bounds,
    give it through the cable columns of the jointed structure matrix."""
    robot = adjustable()
    rng = np.random.default_rng(seed)
    q, qd = random_states(robot, 8, rng, spread=0.1, tilt=0.1)
    q[:, 2], q[:, 6] = rng.uniform(1.0, 2.0, 8), rng.uniform(0.6, 1.5, 8)  # upper anchors below z = 4
    qdd = rng.normal(0, 0.5, q.shape)
    bounds = (5.0, 3000.0)
    res = inverse_dynamics(robot, q, 0.2 * qd, qdd, method=method, tension_bounds=bounds)
    need = np.einsum("kij,kj->ki", mass_matrix(robot, q), qdd) + bias_forces(robot, q, 0.2 * qd)
    assert np.abs(generalized_forces(robot, q, res.wrench) - need).max() < 1e-10 * np.abs(need).max()
    ok = res.feasible
    assert ok.any()
    tau = res.tensions[ok]
    assert (tau >= bounds[0] - 1e-9).all() and (tau <= bounds[1] + 1e-9).all()
    given_force = np.einsum("kij,kj->ki", cable_columns(robot, q[ok]), tau)
    assert np.abs(given_force - res.wrench[ok]).max() < 1e-7 * np.abs(res.wrench).max()


def test_a_sample_beyond_a_joint_limit_is_refused():
    robot = adjustable()
    with pytest.raises(PoseError, match=r"joint s23 = 0.3 is outside its limits \[0.4, 4.5\]"):
        inverse_dynamics(robot, [5, 5, 1, 0, 0, 0, 0.3], np.zeros(7), np.zeros(7))


def test_forward_dynamics_reports_a_joint_beyond_its_limit():
    """Slack cables, the upper body sliding down its joint at 1 m/s: in free fall nothing acts
    along the joint, so ``s23 = 0.6 − t`` (RK4 is exact on it) and it passes the lower limit
    0.4 at 0.2 s, which the result reports (the dynamics has no joint stops)."""
    robot = adjustable()
    q0, qd0 = np.array([5, 5, 1.5, 0, 0, 0, 0.6]), np.zeros(7)
    qd0[6] = -1.0
    res = forward_dynamics(robot, q0, qd0, 0.3, tensions=lambda t: np.zeros(8), method="RK4", step=1e-3)
    s23 = res.poses[:, 6]
    assert np.abs(s23 - (0.6 - res.times)).max() < 1e-9
    assert np.abs(res.poses[:, 3:6]).max() < 1e-9
    assert np.array_equal(res.beyond_limits[:, 0], s23 < 0.4)
    assert abs(res.times[np.argmax(res.beyond_limits[:, 0])] - 0.2) <= 1.5e-3


def test_control_tracks_the_joints_too():
    """Computed-torque control of the adjustable platform (8 cables, 7 coordinates: its joint
    is moved by the cables acting across it) with the jointed distribution in the loop, exact
    model: every coordinate, the joint's included, within 1e-6 of the reference (measured
    1.3e-7); a model 10 % heavy (bodies too) leaves errors within a few mm."""
    robot = adjustable()
    waypoints = [[5, 5, 1.5, 0, 0, 0, 1.5], [5.3, 5.2, 1.2, 0.05, 0, 0.1, 2.0]]
    motion = trajectory_from_waypoints(robot, waypoints, duration=1.0)
    run = simulate_control(robot, motion, method="qp")
    assert run.pose_names == tuple(robot.pose_names)
    assert run.all_feasible and run.tracking_error_max.shape == (robot.pose_size,)
    assert run.tracking_error_max.max() < 1e-6, run.tracking_error_max
    assert np.isclose(run.lower_margin, (run.tensions - run.tension_min).min())
    assert run.joint_limit_violations == 0 and run.first_joint_limit_time is None
    heavy = simulate_control(robot, motion, model=with_mass_error(robot, 0.1), method="qp")
    assert 1e-6 < heavy.tracking_error_max.max() < 5e-3


def test_control_reports_a_joint_pushed_beyond_its_limit():
    """Near its lower limit (0.45) the upper body is pushed down its joint by 400 N from
    0.5 s: the controller's static error ``F / (m K_p)`` (8 kg, K_p = 400: 0.125 m) takes it
    past 0.4, and the run says when."""
    robot = adjustable()
    motion = trajectory_from_waypoints(robot, [[5, 5, 1.5, 0, 0, 0, 0.45], [5, 5, 1.5, 0, 0, 0, 0.46]], duration=1.0)
    push = WrenchSteps.step(0.5, [0, 0, 0, 0, 0, 0, -400.0])
    run = simulate_control(robot, motion, disturbance=push, method="qp")
    assert run.joint_limit_violations > 0
    assert 0.5 < run.first_joint_limit_time < 1.0
    assert run.as_dict()["joint_limit_violations"] == run.joint_limit_violations


def test_a_body_without_mass_is_named():
    robot = adjustable()
    upper = robot.platform.bodies[0].model_copy(update={"mass": None, "com": None, "inertia": None})
    bare = robot.model_copy(update={"platform": robot.platform.model_copy(update={"bodies": (upper,)})})
    q = np.array([5, 5, 1.5, 0, 0, 0, 1.5])
    for call in (
        lambda: inverse_dynamics(bare, q, np.zeros(7), np.zeros(7)),
        lambda: forward_dynamics(bare, q, np.zeros(7), 0.1, tensions=lambda t: np.zeros(8)),
    ):
        with pytest.raises(UnsupportedRobotError, match=r"platform.bodies\[1\] \(upper\) has no mass"):
            call()
