"""Joint actuators in the tension distribution (``joint.actuator``): CASPR's SpiderBot, whose
UR3 arm no cable reaches, is held and moved by its joint motors; the forces are checked
against the statics of the jointed structure matrix (``taut.kinematics.joint_forces``,
Lieskovský 2020 Eq. 3.3.12, a separate implementation from the compiled body tree), their
bounds are respected or the update is reported, and the split of a signed actuator into two
columns gives what the distribution asks for."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from jointed_robots import SPIDERBOT, adjustable

from taut.dynamics import inverse_dynamics, simulate_control
from taut.errors import InfeasiblePoseError
from taut.kinematics import joint_forces, jointed_structure_matrix, structure_matrix
from taut.model import JointActuator, Robot, load_robot
from taut.motion import trajectory_from_waypoints
from taut.statics import external_wrench, solve_inputs

SET = "set_IPAnema_inspired"


def spiderbot() -> Robot:
    return load_robot(SPIDERBOT, cable_set=SET)


def with_actuators(robot: Robot, bounds: dict[int, tuple[float, float] | None]) -> Robot:
    """``robot`` with the actuators of the joints ``bounds`` names set (None: passive)."""
    bodies = list(robot.platform.bodies)
    for k, force in bounds.items():
        actuator = None if force is None else JointActuator(force=force)
        joint = bodies[k].joint.model_copy(update={"actuator": actuator})
        bodies[k] = bodies[k].model_copy(update={"joint": joint})
    return robot.model_copy(update={"platform": robot.platform.model_copy(update={"bodies": tuple(bodies)})})


def rest_pose(data: st.DataObject) -> np.ndarray:
    base = data.draw(st.lists(st.floats(-0.05, 0.05), min_size=6, max_size=6))
    arm = data.draw(st.lists(st.floats(-1.0, 1.0), min_size=6, max_size=6))
    return np.array([0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.5708, 0.0]) + np.concatenate([base, arm])


@pytest.mark.parametrize("method", ["qp", "lp", "inf", "closed-form", "improved-closed-form"])
@settings(max_examples=15, deadline=None)
@given(data=st.data())
def test_spiderbot_at_rest_motors_hold_the_arm(method: str, data: st.DataObject) -> None:
    """At rest the cables hold the weight of the whole robot on the base (the statics'
    structure matrix and external wrench) and the joint motors give exactly the joint forces of
    the statics for those tensions (no cable reaches the arm)."""
    robot = spiderbot()
    q = rest_pose(data)
    res = inverse_dynamics(robot, q, np.zeros(12), np.zeros(12), method=method)
    if not res.feasible:  # the closed forms may give up where the polytope is thin
        assert method in ("closed-form", "improved-closed-form") and res.status == "not-found"
        return
    tau, zeta = res.tensions, res.actuator_forces
    assert zeta.shape == (6,)
    W = structure_matrix(robot, q)
    np.testing.assert_allclose(W @ tau + external_wrench(robot, q), 0.0, atol=1e-7 * max(1.0, np.abs(tau).max()))
    # to the distribution's acceptance of the equilibrium residual (relative to the largest input)
    np.testing.assert_allclose(zeta, joint_forces(robot, q, tau), rtol=1e-9, atol=1e-8 * max(1.0, np.abs(tau).max()))
    lo, hi = robot.tension_bounds
    assert (tau >= lo - 1e-9).all() and (tau <= hi + 1e-9).all()


@settings(max_examples=20, deadline=None)
@given(data=st.data())
def test_actuator_bounds_decide_feasibility(data: st.DataObject) -> None:
    """The arm's joint forces are fixed by its weight: a motor bound that admits the needed
    torque of its joint leaves the pose feasible, one that does not makes it infeasible."""
    robot = spiderbot()
    q = rest_pose(data)
    need = joint_forces(robot, q, np.zeros(robot.n_cables))
    j = data.draw(st.integers(1, 2))  # the upper arm and forearm carry the largest torques
    admits = data.draw(st.booleans())
    margin = data.draw(st.floats(0.05, 2.0))
    if admits:
        force = (need[j] - margin, need[j] + margin)
    else:
        force = (need[j] + margin, need[j] + margin + 1.0)
    bounded = with_actuators(robot, {j: force})
    res = inverse_dynamics(bounded, q, np.zeros(12), np.zeros(12), method="qp")
    assert bool(res.feasible) == admits
    if admits:
        assert force[0] - 1e-9 <= res.actuator_forces[j] <= force[1] + 1e-9
    else:
        assert res.status == "infeasible"


def test_spiderbot_tracks_a_motion_with_its_joint_motors() -> None:
    """The base moves and all six joints turn; with an exact model every coordinate tracks to
    a few micrometres (microradians); without its motors the arm cannot be held (no cable reaches
    it), and a motor too weak for its joint is reported at every update."""
    robot = spiderbot()
    a = [0.0, 0.0, 0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.5708, 0.0]
    b = [0.1, 0.05, 0.35, 0.0, 0.0, 0.05, 0.3, -0.4, 0.5, 0.2, -1.2, 0.1]
    motion = trajectory_from_waypoints(robot, [a, b], duration=0.5)
    run = simulate_control(robot, motion, rate_hz=1000)
    assert run.all_feasible and run.tracking_error_max.max() < 1e-5
    assert run.actuator_forces.shape == (run.times.size, 6)
    np.testing.assert_array_equal(run.actuator_min, -np.inf)
    # at the end, at rest, the motors hold the arm as the statics says
    end = run.poses[-1]
    np.testing.assert_allclose(run.actuator_forces[-1], joint_forces(robot, end, run.tensions[-1]), atol=1e-2)
    passive = with_actuators(robot, dict.fromkeys(range(6)))
    with pytest.raises(InfeasiblePoseError, match="no admissible tensions at the start"):
        simulate_control(passive, motion, rate_hz=200)
    weak = with_actuators(robot, {1: (-1.0, 1.0)})  # the upper arm needs about 18 N m
    with pytest.raises(InfeasiblePoseError, match="no admissible tensions at the start"):
        simulate_control(weak, motion, rate_hz=200)
    # enough for the start (18.3 N m at rest), not for the end (17.0 N m at rest)
    start = joint_forces(robot, a, np.zeros(robot.n_cables))[1]
    tight = with_actuators(robot, {1: (start - 0.5, start + 0.5)})
    run = simulate_control(tight, motion, rate_hz=200)
    assert run.failures > 0 and run.first_failure_time is not None and run.first_failure_time > 0
    assert (run.actuator_forces[:, 1] >= start - 0.5 - 1e-9).all()
    assert (run.actuator_forces[:, 1] <= start + 0.5 + 1e-9).all()
    assert run.actuator_margin[1] < 0.5 and np.isinf(run.actuator_margin[0])


def test_a_bounded_actuator_beside_the_cables_of_the_adjustable_platform() -> None:
    """adjustable-8cable (assumed masses) with a motor of ±30 N on its prismatic joint: the
    cables and the motor share the joint's load; the distribution solves the jointed structure
    matrix (from the kinematics) with the motor's unit column, within every bound."""
    robot = with_actuators(adjustable(), {0: (-30.0, 30.0)})
    motion = trajectory_from_waypoints(
        robot, [[5, 5, 1.5, 0, 0, 0, 1.5], [5.3, 5.2, 1.2, 0.05, 0, 0.1, 2]], duration=1.0
    )
    s = motion.sample(50)
    for method in ("qp", "lp"):
        res = inverse_dynamics(robot, s.poses, s.velocity, s.acceleration, method=method)
        assert res.feasible.all()
        A = jointed_structure_matrix(robot, s.poses)
        n = robot.n_cables
        got = np.einsum("kij,kj->ki", A[:, :, :n], res.tensions)
        got[:, 6] += res.actuator_forces[:, 0]
        np.testing.assert_allclose(got, res.wrench, atol=1e-6 * np.abs(res.wrench).max())
        assert (np.abs(res.actuator_forces) <= 30.0 + 1e-9).all()


@settings(max_examples=60, deadline=None)
@given(data=st.data())
def test_split_actuators_solve_the_signed_problem(data: st.DataObject) -> None:
    """Two cables on a line and a signed motor: every admissible answer of the split problem
    is one of the signed problem, and the signed problem is feasible exactly when some motor
    force within its bounds leaves the cables a tension within theirs."""
    w = float(data.draw(st.integers(-50, 50)))
    lo = float(data.draw(st.integers(-40, 10)))
    hi = lo + data.draw(st.integers(0, 40))
    hi = np.inf if data.draw(st.booleans()) else hi
    W = np.array([[1.0, -1.0, 1.0]])  # cable 1 pulls +, cable 2 pulls −, the motor
    tmax = 20.0
    bounds_lo, bounds_hi = np.array([0.0, 0.0, lo]), np.array([tmax, tmax, hi])
    x, ok, _ = solve_inputs(W, np.array([w]), bounds_lo, bounds_hi, 2, "qp")
    # the motor must give w − (τ1 − τ2) with τ1 − τ2 ∈ [−tmax, tmax]
    possible = max(lo, w - tmax) <= min(hi, w + tmax)
    assert bool(ok) == possible
    if ok:
        assert abs(W[0] @ x - w) <= 1e-7 * max(1.0, abs(w))
        assert (x >= bounds_lo - 1e-9).all() and (x <= bounds_hi + 1e-9).all()
