"""Statics of jointed platforms (``taut.statics.equilibrium_equations``): a passive joint is
held by the cables acting across it, an actuated one by its motor within its bounds; checked
against the joint forces of the kinematics (Lieskovský 2020, Eq. 3.3.12) and through the
command line.  The MuJoCo check of the same distributions is in
``tests/model/test_mjcf_jointed.py``."""

import numpy as np
import pytest
from jointed_robots import SPIDERBOT

import taut
from taut.errors import TautError, UnsupportedRobotError
from taut.kinematics import joint_forces
from taut.model import load_robot
from taut.statics import METHODS, EllipsoidWrenchSet, distribute_tensions, equilibrium_equations
from taut.workspace import StaticEquilibrium, WrenchFeasible

ADJUSTABLE = taut.example("adjustable-8cable")
#: The README's pose, where cables 5-8 hold the upper body from below their exits.
HELD = np.array([5, 5, 1.5, 0, 0, 0, 1.5])
#: The same platform with the upper body above the exits of cables 5-8 (z = 4): they can only
#: pull it down, so nothing holds the passive joint against the weight.
ABOVE = np.array([5, 5, 4.5, 0, 0, 0, 2.0])
SPIDER_POSE = np.array([1.445, 1.0005, 0.9025, 0, 0, 0, 0, 0, 0, 0, -1.5708, 0])


@pytest.mark.parametrize("method", [m for m in METHODS if m != "barycentric"])
def test_a_passive_joint_is_held_by_the_cables(method):
    res = distribute_tensions(ADJUSTABLE, HELD, method=method)
    assert res.feasible and res.actuator_forces.shape == (0,)
    # the joint needs no force: the cables across it balance the upper body's 78.48 N
    tau = res.tensions
    assert abs(joint_forces(ADJUSTABLE, HELD, tau)[0]) <= 1e-9 * tau.sum()
    assert tau[4:].sum() > 78.48 / 2


def test_the_joint_above_the_exits_cannot_be_held():
    res = distribute_tensions(ADJUSTABLE, ABOVE)
    assert not res.feasible and res.status == "infeasible"
    assert res.as_dict()["tensions"] is None and res.as_dict()["actuator_forces"] is None
    assert StaticEquilibrium().evaluate(ADJUSTABLE, np.array([HELD, ABOVE])).tolist() == [True, False]
    assert WrenchFeasible().evaluate(ADJUSTABLE, np.array([HELD, ABOVE])).tolist() == [True, False]


def test_actuated_joints_carry_their_forces():
    robot = load_robot(SPIDERBOT)
    res = distribute_tensions(robot, SPIDER_POSE, method="qp")
    assert res.feasible and res.actuator_forces.shape == (6,)
    np.testing.assert_allclose(joint_forces(robot, SPIDER_POSE, res.tensions), res.actuator_forces, atol=1e-8)
    assert abs(res.actuator_forces[1]) > 10  # the upper arm's weight


def test_equations_and_bad_input():
    W, w, (lo, hi) = equilibrium_equations(ADJUSTABLE, np.array([HELD, HELD]))
    assert W.shape == (2, 7, 8) and w.shape == (2, 7) and lo.shape == hi.shape == (8,)
    np.testing.assert_allclose(w[:, 6], -8.0 * 9.81)
    # a wrench given replaces the robot's own load, the bodies' weights on the joint included
    _, w0, _ = equilibrium_equations(ADJUSTABLE, HELD, wrench=np.zeros(6))
    assert not w0.any()
    with pytest.raises(TautError, match="wrench must have shape"):
        equilibrium_equations(ADJUSTABLE, HELD, wrench=np.zeros(7))
    with pytest.raises(TautError, match="tension bounds"):
        equilibrium_equations(ADJUSTABLE, HELD, tension_bounds=(np.zeros(3), 10.0))
    ellipsoid = EllipsoidWrenchSet(np.zeros(6), np.eye(6))
    with pytest.raises(UnsupportedRobotError, match="on a jointed platform"):
        WrenchFeasible(ellipsoid).evaluate(ADJUSTABLE, HELD[None])


def test_cli_reports_the_joint_forces(taut_cli):
    run = taut_cli("tensions", "adjustable-8cable", "--pose", ",".join(map(str, HELD)), "--json")
    d = run.json()
    assert run.code == 0 and d["feasible"] is True and d["actuator_forces"] == []
    assert abs(joint_forces(ADJUSTABLE, HELD, np.array(d["tensions"]))[0]) <= 1e-9 * sum(d["tensions"])
    run = taut_cli("tensions", "adjustable-8cable", "--pose", ",".join(map(str, HELD)))
    assert run.code == 0 and "passive: held by the cables" in run.out
    run = taut_cli("tensions", str(SPIDERBOT), "--pose", ",".join(map(str, SPIDER_POSE)), "--json")
    d = run.json()
    assert len(d["actuator_forces"]) == 6 and d["feasible"] is True
