"""``taut simulate`` on a jointed platform (adjustable-8cable, with the masses its description
states as assumed where the source gives none), through real subprocesses."""

from pathlib import Path

import numpy as np
import yaml

import taut
from taut.dynamics import WrenchSteps, simulate_control
from taut.model import load_robot, robot_to_dict
from taut.motion import trajectory_from_waypoints

WAYPOINTS = "--waypoints=5,5,1.5,0,0,0,1.5;5.3,5.2,1.2,0.05,0,0.1,2"


def test_a_jointed_robot_without_masses_is_one_line_naming_the_body(taut_cli, tmp_path):
    data = robot_to_dict(taut.example("adjustable-8cable"))
    for field in ("mass", "inertia", "wrench_point"):
        data["platform"].pop(field)
    bare = tmp_path / "bare.yaml"
    bare.write_text(yaml.safe_dump(data, allow_unicode=True))
    run = taut_cli("simulate", str(bare), WAYPOINTS, "--duration", "1", "--json")
    assert run.code == 2 and run.out == ""
    assert run.err.splitlines() == [
        "taut: error: adjustable 8-cable robot: the dynamics needs the platform's mass (platform.mass)"
    ]
    data = robot_to_dict(taut.example("adjustable-8cable"))
    for field in ("mass", "com", "inertia"):
        data["platform"]["bodies"][0].pop(field)
    bare.write_text(yaml.safe_dump(data, allow_unicode=True))
    run = taut_cli("simulate", str(bare), WAYPOINTS, "--duration", "1", "--json")
    assert run.code == 2 and run.out == "" and len(run.err.splitlines()) == 1
    assert "platform.bodies[1] (upper) has no mass" in run.err


def test_simulate_reports_every_coordinate_joints_included(taut_cli):
    """The command's figures are the library's, per coordinate (s23 the joint's), with a push
    on the platform (6 components: the joint unloaded) that the controller rejects."""
    run = taut_cli(
        "simulate", "adjustable-8cable", WAYPOINTS, "--duration", "1", "--disturbance", "0.5:20,0,0,0,0,0", "--json"
    )
    d = run.json()
    assert d["pose_names"] == ["x", "y", "z", "a", "b", "c", "s23"]
    assert len(d["tracking_error_max"]) == 7 and len(d["tracking_error_rms"]) == 7
    assert d["feasible"] is True and d["slack_events"] == 0 and d["min_tension_margin"] > 0
    assert d["joint_limit_violations"] == 0 and d["first_joint_limit_time"] is None
    robot = taut.example("adjustable-8cable")
    motion = trajectory_from_waypoints(robot, [[5, 5, 1.5, 0, 0, 0, 1.5], [5.3, 5.2, 1.2, 0.05, 0, 0.1, 2]], duration=1)

    push = WrenchSteps.step(0.5, [20, 0, 0, 0, 0, 0, 0])
    lib = simulate_control(robot, motion, disturbance=push)
    assert np.allclose(d["tracking_error_max"], lib.tracking_error_max, rtol=1e-9, atol=1e-15)
    # 20 N on 28 kg with K_p = 400: millimetres of static error along x (more than 20/(28·400)
    # = 1.8 mm, the push also turning the platform about its offset centre of mass)
    assert 1e-3 < d["tracking_error_max"][0] < 1e-2
    assert np.isclose(d["min_tension_margin"], lib.min_tension_margin)


def test_a_joint_force_disturbance_pushes_the_joint_past_its_limit(taut_cli):
    run = taut_cli(
        "simulate",
        "adjustable-8cable",
        "--waypoints=5,5,1.5,0,0,0,0.45;5,5,1.5,0,0,0,0.46",
        "--duration",
        "1",
        "--disturbance",
        "0.5:0,0,0,0,0,0,-400",
        "--json",
    )
    d = run.json()
    assert d["joint_limit_violations"] > 0 and 0.5 < d["first_joint_limit_time"] < 1
    run = taut_cli("simulate", "adjustable-8cable", WAYPOINTS, "--duration", "1", "--disturbance", "0:1,2,3")
    assert run.code == 2 and "takes a wrench of 6 components (or 7 with its joint forces)" in run.err


SPIDERBOT = Path(__file__).parents[1] / "model" / "fixtures" / "caspr" / "real" / "SpiderBot_UR3_bodies.xml"
SPIDER_WAYPOINTS = (
    "--waypoints=1.445,1.0005,0.9025,0,0,0,0,0,0,0,-1.5708,0;1.545,1.05,0.95,0,0,0.05,0.3,-0.4,0.5,0.2,-1.5708,0.1"
)


def test_simulate_spiderbot_with_its_joint_motors(taut_cli, tmp_path):
    """CASPR's SpiderBot (the file's masses; its default cable set, through swivelling
    pulleys): the base moves and the UR3's joints turn, driven by their motors (CASPR's
    actuated joints); the report has every coordinate's error, the cables' margins and the
    motors' forces, as the library computes them.  Without motors the arm, which no cable
    reaches, cannot be held: one line, exit 2."""
    run = taut_cli("simulate", str(SPIDERBOT), SPIDER_WAYPOINTS, "--duration", "1", "--json")
    assert run.code == 0, run.err
    d = run.json()
    robot = load_robot(SPIDERBOT)
    assert d["pose_names"] == robot.pose_names and len(d["tracking_error_max"]) == 12
    assert d["actuated_joints"] == robot.pose_names[6:]
    assert d["feasible"] is True and d["slack_events"] == 0 and d["min_tension_margin"] > 0
    assert max(d["tracking_error_max"]) < 1e-5
    W = np.array([[float(x) for x in p.split(",")] for p in SPIDER_WAYPOINTS.split("=", 1)[1].split(";")])
    lib = simulate_control(robot, trajectory_from_waypoints(robot, W, duration=1.0), rate_hz=1000)
    np.testing.assert_allclose(d["tracking_error_max"], lib.tracking_error_max, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(d["actuator_force_max"], lib.actuator_peak, rtol=1e-12)
    assert (lib.actuator_peak >= np.abs(lib.actuator_forces).max(axis=0)).all()
    assert d["actuator_margin"] == [None] * 6  # unbounded, as CASPR's motors are
    assert min(d["tension_margin_per_cable"]) == d["min_tension_margin"]
    np.testing.assert_allclose(d["tension_margin_per_cable"], lib.cable_margin, rtol=1e-9)
    assert d["slack_events_per_cable"] == [0] * 8
    assert 15 < d["actuator_force_max"][1] < 20  # the upper arm holds the arm's weight
    passive = tmp_path / "spiderbot_passive.yaml"
    convert = taut_cli("convert", str(SPIDERBOT), str(passive))
    assert convert.code == 0
    passive.write_text("\n".join(line for line in passive.read_text().splitlines() if "actuator" not in line))
    run = taut_cli("simulate", str(passive), SPIDER_WAYPOINTS, "--duration", "1", "--rate", "100", "--json")
    assert run.code == 2 and run.out == "" and len(run.err.splitlines()) == 1
    assert "no admissible tensions at the start" in run.err
