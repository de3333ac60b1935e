"""The control loop with sagging cables: quasi-static elastic catenaries (Irvine 1981, §1.3)
that pull along their tangents at the platform."""

import numpy as np
import pytest

import taut
from taut.cables import catenary_forces, sagging_ik
from taut.dynamics import IntegrationError, forward_dynamics, loop_model, simulate_control
from taut.errors import UnsupportedRobotError
from taut.kinematics import anchor_points
from taut.motion import trajectory_from_waypoints

HOME = [0.0, 0.0, 2.0, 0.0, 0.0, 0.0]
AWAY = [0.3, 0.2, 2.2, 0.0, 0.0, 0.1]


def with_cables(robot, **fields):
    return robot.model_copy(update={"cables": tuple(c.model_copy(update=fields) for c in robot.cables)})


@pytest.mark.parametrize(
    "name, waypoints, rate",
    [
        ("cogiro-sagging", [HOME, AWAY], 50),
        # a point mass on 4 cables, pulled too fast: cables at their least tension, failed updates
        ("camera-4cable", [[0.0, 0.0, 8.0], [2.0, 1.0, 7.0]], 100),
    ],
)
def test_weightless_stiff_cables_simulate_as_straight_ones(name, waypoints, rate):
    """weight → 0, EA → ∞: every pose and tension of a controlled motion is the straight loop's,
    its failed updates too."""
    robot = taut.example(name)
    light, straight = with_cables(robot, weight=1e-12, stiffness=None), with_cables(robot, weight=None, stiffness=None)
    runs = [
        simulate_control(r, trajectory_from_waypoints(r, waypoints, duration=1.0), rate_hz=rate, substeps=2)
        for r in (light, straight)
    ]
    assert [r.cable_model for r in runs] == ["quasi-static elastic catenary", "straight"]
    sag, ref = runs
    assert np.array_equal(sag.feasible, ref.feasible)
    # the motion moves the platform and changes the tensions: the comparison sees the dynamics
    assert np.abs(ref.poses[-1] - ref.poses[0]).max() > 0.2
    assert np.ptp(ref.tensions, axis=0).max() > 10.0
    assert np.abs(sag.poses - ref.poses).max() <= 1e-9 * np.abs(ref.poses).max()
    assert np.abs(sag.tensions - ref.tensions).max() <= 1e-9 * np.abs(ref.tensions).max()
    assert np.abs(sag.exit_tensions - ref.tensions).max() <= 1e-9 * np.abs(ref.tensions).max()


def test_a_platform_held_by_catenaries_stays_put_and_straight_tensions_let_it_drift():
    """Feed-forward only (zero gains): at a pose of static equilibrium the catenaries' pull
    balances the weight and the platform stays; the straight model's tensions, pulled along the
    tangents, do not balance it and the platform drifts."""
    robot = taut.example("cogiro-sagging")
    assert sagging_ik(robot, HOME).feasible
    run = simulate_control(
        robot, trajectory_from_waypoints(robot, [HOME, HOME], durations=0.5), kp=0.0, kd=0.0, rate_hz=100
    )
    assert run.all_feasible and run.cable_model == "quasi-static elastic catenary"
    assert run.position_error_max < 1e-9 and run.rotation_error_max < 1e-9
    # every cable pulls harder at its exit, by about the weight of its rise (5.5 m less the anchor's height)
    rise = robot.exits[:, 2] - anchor_points(robot, HOME)[:, 2]
    assert np.allclose(run.exit_tensions[0] - run.tensions[0], robot.cable_weights * rise, rtol=0.02)
    # the held tensions are the static IK's least-squares distribution (its qp: the closed form's
    # τ nearest the bounds' middle, here within the bounds), solved apart in a batch iteration;
    # and each cable's unstrained length from it gives that tension back by the forward catenary
    tau = run.tensions[0]
    res = sagging_ik(robot, HOME, method="qp")
    assert res.feasible and np.allclose(res.platform_tensions, tau, rtol=1e-10, atol=1e-7)
    chord = robot.exits - anchor_points(robot, HOME)
    c = catenary_forces(np.hypot(chord[:, 0], chord[:, 1]), chord[:, 2], res.unstrained_lengths, 2.45, 2.8e6)
    assert np.allclose(c.platform_tensions, tau, rtol=1e-9)
    assert np.allclose(c.exit_tensions, run.exit_tensions[0], rtol=1e-9)
    # the straight model's tensions at the same pose, held in the sagging plant
    straight = with_cables(robot, weight=None)
    tau_straight, ok = loop_model(straight).tensions(np.array(HOME), np.zeros(6), np.zeros(6))
    assert ok and np.abs(tau_straight - tau).max() > 1.0
    plant = loop_model(robot)
    q, qd = np.array(HOME), np.zeros(6)
    for _ in range(50):
        q, qd = plant.step(q, qd, tau_straight, 0.01)
    assert np.linalg.norm(q[:3] - HOME[:3]) > 1e-3


def test_sagging_cables_on_a_jointed_platform_are_refused():
    robot = taut.example("adjustable-8cable")
    heavy = robot.model_copy(update={"cables": (robot.cables[0].model_copy(update={"weight": 1.0}), *robot.cables[1:])})
    with pytest.raises(UnsupportedRobotError, match="sagging-cable dynamics handle platforms without joints"):
        loop_model(heavy)


def test_forward_dynamics_under_given_tensions_reduces_to_straight_cables():
    """forward_dynamics pulls a sagging cable with its given (platform-end) tension along its
    tangent: weightless and stiff, the straight cables' motion, fixed-step and adaptive."""
    robot = taut.example("cogiro-sagging")
    light, straight = with_cables(robot, weight=1e-12, stiffness=None), with_cables(robot, weight=None, stiffness=None)
    tau = np.linspace(300.0, 500.0, 8)
    for options in ({"method": "RK4", "step": 0.01}, {"method": "DOP853", "times": np.linspace(0, 0.3, 7)}):
        a, b = (
            forward_dynamics(r, HOME, np.zeros(6), 0.3, tensions=lambda t: tau, **options) for r in (light, straight)
        )
        assert np.abs(b.poses[-1] - b.poses[0]).max() > 0.01
        assert np.abs(a.poses - b.poses).max() <= 1e-9 * np.abs(b.poses).max()
        assert np.array_equal(a.tensions, b.tensions)


def test_forward_dynamics_holds_the_static_ik_lengths_and_not_the_straight_ones():
    """Commanded unstrained lengths: the catenaries of the static IK's lengths hold the platform
    at rest; the lengths of the straight elastic model (chord / (1 + τ/EA)) let it move."""
    robot = taut.example("cogiro-sagging")
    ik = sagging_ik(robot, HOME, method="qp")
    held = forward_dynamics(
        robot, HOME, np.zeros(6), 0.05, lengths=lambda t: ik.unstrained_lengths, method="RK4", step=1e-3
    )
    assert np.abs(held.poses - HOME).max() < 1e-8
    assert np.allclose(held.tensions[0], ik.platform_tensions, rtol=1e-7)
    straight = ik.chord_lengths / (1 + ik.platform_tensions / robot.axial_stiffness)
    moved = forward_dynamics(robot, HOME, np.zeros(6), 0.05, lengths=lambda t: straight, method="RK4", step=1e-3)
    assert np.abs(moved.poses - HOME).max() > 1e-4
    # an inextensible cable shorter than its chord has no catenary: the motion cannot start
    rigid = with_cables(robot, stiffness=None)
    with pytest.raises(IntegrationError, match="not longer than its chord"):
        forward_dynamics(rigid, HOME, np.zeros(6), 0.1, lengths=lambda t: np.full(8, 5.0), method="RK4", step=1e-3)
