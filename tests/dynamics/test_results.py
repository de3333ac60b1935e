"""The results of taut.dynamics follow docs/architecture.md §2.7: frozen, read-only arrays,
``as_dict()`` in plain JSON types holding the fields (``times``, ``poses``, ``feasible``,
``elapsed_s``, ``complete`` where the work is a simulation)."""

import math

import numpy as np
from result_checks import check_result, same

import taut
from taut.dynamics import (
    WrenchSteps,
    forward_dynamics,
    inverse_dynamics,
    platform_dynamics,
    required_wrench,
    simulate_control,
)
from taut.motion import trajectory_from_waypoints

ROBOT = taut.example("spatial-8cable")


def test_platform_dynamics(loaded):
    pd = platform_dynamics(loaded)
    d = check_result(pd)
    assert d["mass"] == loaded.platform.mass and d["dof"] == 6 and d["orientation"] == loaded.orientation
    same(d["force"], loaded.weight + np.array(loaded.platform.wrench[:3]))
    same(d["moment"], loaded.platform.wrench[3:])
    same(d["com"], loaded.platform.wrench_point)


def test_inverse_dynamics_result(spatial):
    t = np.linspace(0.0, 1.0, 6)
    q = np.outer(np.sin(t), [0.1, 0.05, 0.1, 0.05, 0.05, 0.1])
    qd = np.outer(np.cos(t), [0.1, 0.05, 0.1, 0.05, 0.05, 0.1])
    qdd = -q
    qdd[-1, 2] = 400.0  # no admissible tensions there
    res = inverse_dynamics(spatial, q, qd, qdd, method="qp", times=t)
    d = check_result(res)
    assert set(d) == {"times", "wrench", "tensions", "feasible", "status", "reasons", "method", "actuator_forces"}
    same(d["times"], t)
    same(d["wrench"], required_wrench(spatial, q, qd, qdd))
    assert d["feasible"] == [True] * 5 + [False] and d["status"][-1] == "infeasible" and d["reasons"][0] == ""
    one = check_result(inverse_dynamics(spatial, q[0], qd[0], qdd[0], method="qp"))
    assert one["times"] is None and one["feasible"] is True and one["status"] == "optimal"
    np.testing.assert_allclose(one["tensions"], d["tensions"][0], rtol=1e-9)


def test_forward_dynamics_result(spatial):
    q0 = np.array([0.05, -0.02, 0.1, 0.02, -0.03, 0.05])
    res = forward_dynamics(spatial, q0, np.zeros(6), 0.01, tensions=lambda t: np.full(8, 20.0), method="RK4", step=1e-3)
    d = check_result(res)
    assert set(d) == {
        "times",
        "poses",
        "velocity",
        "tensions",
        "slack",
        "beyond_limits",
        "method",
        "evaluations",
        "elapsed_s",
        "complete",
    }
    same(d["times"], np.arange(11) * 1e-3)
    same(d["poses"], res.poses)
    np.testing.assert_array_equal(d["poses"][0], q0)
    assert d["beyond_limits"] == [[]] * 11  # no joints
    assert d["complete"] is True and d["elapsed_s"] > 0 and d["evaluations"] == 40 and d["method"] == "RK4"


def test_control_result():
    motion = trajectory_from_waypoints(ROBOT, [[0, 0, 0, 0, 0, 0], [0.05, 0, 0.02, 0, 0, 0.05]], duration=0.05)
    steps = WrenchSteps.step(0.02, [1.0, 0, 0, 0, 0, 0])
    assert check_result(steps) == {"steps": [[0.02, None, [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]]]}
    res = simulate_control(ROBOT, motion, rate_hz=200, disturbance=steps)
    d = check_result(res)
    assert {"times", "poses", "feasible", "elapsed_s", "complete", "all_feasible", "failures"} <= set(d)
    assert "admissible" not in d and "time" not in d and "pose" not in d
    same(d["times"], np.linspace(0.0, 0.05, 11))
    same(d["poses"], res.poses)
    same(d["tension_max"], res.tension_max)  # inf: no upper limit becomes None
    assert d["feasible"] == [True] * 11 and d["all_feasible"] is True and d["failures"] == 0
    assert d["disturbance"][3] == [0.0] * 6 and d["disturbance"][4] == [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]
    assert d["complete"] is True and d["elapsed_s"] > 0
    np.testing.assert_allclose(d["tracking_error_max"], np.abs(res.reference - res.poses).max(axis=0))
    upper = d["upper_margin"]
    assert (upper is None) == math.isinf(res.upper_margin)
