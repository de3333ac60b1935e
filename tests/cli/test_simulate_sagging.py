"""``taut simulate`` on a robot with sagging cables (cogiro-sagging), through real subprocesses:
it names its cable model, and its figures are the library's."""

import numpy as np

import taut
from taut.dynamics import simulate_control
from taut.kinematics import anchor_points
from taut.motion import trajectory_from_waypoints

ARGS = ("simulate", "cogiro-sagging", "--waypoints", "0,0,2;0.4,0.2,2.2", "--duration", "1", "--rate", "50")


def test_simulate_names_the_catenary_model_and_reports_both_ends(taut_cli, tmp_path):
    run = taut_cli(*ARGS, "--json", "--out", str(tmp_path / "run.csv"))
    assert run.code == 0 and run.err == ""
    d = run.json()
    assert d["cable_model"] == "quasi-static elastic catenary"
    assert d["sagging_cables"] == list(range(1, 9))
    assert d["feasible"] is True
    robot = taut.example("cogiro-sagging")
    lib = simulate_control(
        robot, trajectory_from_waypoints(robot, [[0, 0, 2, 0, 0, 0], [0.4, 0.2, 2.2, 0, 0, 0]], duration=1), rate_hz=50
    )
    assert np.allclose(d["tracking_error_max"], lib.tracking_error_max, rtol=1e-9, atol=1e-15)
    tensions, exits = np.array(d["tensions"]), np.array(d["exit_tensions"])
    # a catenary's tension grows by the weight of its rise (Irvine 1981, §1.2; to the strain T/EA)
    rise = robot.exits[None, :, 2] - anchor_points(robot, np.array(d["pose"]))[..., 2]
    assert np.allclose(exits - tensions, 2.45 * rise, rtol=1e-3)
    # the CSV holds both ends, the same samples
    head = (tmp_path / "run.csv").read_text().splitlines()[0].split(",")
    table = np.loadtxt(tmp_path / "run.csv", delimiter=",", skiprows=1)
    assert head[-10:-1] == ["tau8"] + [f"exit_tau{i}" for i in range(1, 9)]
    assert np.allclose(table[:, -9:-1], exits, rtol=1e-8) and np.allclose(table[:, -17:-9], tensions, rtol=1e-8)
    human = taut_cli(*ARGS)
    assert human.code == 0 and "quasi-static elastic catenary" in human.out and "Irvine 1981" in human.out
