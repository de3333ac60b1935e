"""docs/architecture.md §2.7: the ``--json`` of every command is the library result's
``as_dict()``, with the command's context (robot, inputs, files) and 1-based cable numbers.

Each test runs the command in a subprocess and compares its JSON with the ``as_dict()`` of
the same call made here through the public API, its cable, chart, object and step indices
converted here (not by the command line's helper), so that the two cannot drift apart.
Wall-clock times differ between the two runs and are compared only as numbers."""

from __future__ import annotations

import json

import numpy as np
import pytest

from taut.atlas import atlas_workspace, build_atlas
from taut.collision import check_poses, trajectory_poses
from taut.dgp import solve_dgp, solve_igp
from taut.dynamics import DEFAULT_KD, DEFAULT_KP, simulate_control
from taut.kinematics import inverse_kinematics
from taut.model import example
from taut.motion import trajectory_from_waypoints
from taut.planning import WrenchFeasibleManifold, plan_path
from taut.statics import distribute_tensions
from taut.workspace import evaluate_workspace
from taut.wrapping import builtin_trajectory, run_trajectory


def untimed(d: dict, *keys: str) -> dict:
    """``d`` without its wall-clock ``keys`` (``elapsed_s`` by default), each checked to be a
    time."""
    keys = keys or ("elapsed_s",)
    for k in keys:
        assert isinstance(d[k], float) and d[k] >= 0, k
    return {k: v for k, v in d.items() if k not in keys}


def plus1(values: list[int]) -> list[int]:
    return [v + 1 for v in values]


def test_ik(taut_cli):
    robot = example("planar-4cable")
    pose = [0.1, -0.05, 0.2]
    got = taut_cli("ik", "planar-4cable", "--pose", "0.1,-0.05,0.2", "--json").json()
    want = {"robot": robot.name, "pose": pose} | inverse_kinematics(robot, pose).as_dict()
    assert got == want
    assert {"lengths", "directions", "anchors", "structure_matrix"} <= set(got)


@pytest.mark.parametrize(
    ("robot_name", "pose", "method"),
    [("spatial-8cable", None, "qp"), ("planar-4cable", [0.99, 0.99, 0.0], "lp")],
)
def test_tensions(taut_cli, robot_name, pose, method):
    robot = example(robot_name)
    pose = list(robot.reference.poses.values())[0] if pose is None else pose
    text = ",".join(map(repr, map(float, pose)))
    got = taut_cli("tensions", robot_name, f"--pose={text}", "--method", method, "--json").json()
    want = {"robot": robot.name, "pose": [float(x) for x in pose]}
    want |= distribute_tensions(robot, pose, method=method).as_dict()
    assert got == want
    # an infeasible pose prints no tensions, not zeros
    assert (got["tensions"] is None) == (not got["feasible"])


def test_workspace(taut_cli):
    robot = example("planar-4cable")
    got = taut_cli("workspace", "planar-4cable", "--condition", "static", "--grid", "5", "--json").json()
    want = evaluate_workspace(robot, "static", resolution=5).as_dict()
    assert untimed(got) == untimed(want)
    assert got["robot"] == robot.name and got["poses"] == 25


@pytest.mark.slow
def test_fk(taut_cli):
    """A box budget that leaves boxes undecided: solutions and enclosures both numbered."""
    robot = example("suspended-3cable")
    got = taut_cli("fk", "suspended-3cable", "--max-boxes", "3000", "--json").json()
    want = solve_dgp(robot, max_boxes=3000).as_dict()
    for s in want["solutions"]:
        s["taut"] = plus1(s["taut"])
    for b in want["undecided_enclosures"]:
        b["taut"] = plus1(b["taut"])
    assert untimed(got) == {"robot": robot.name} | untimed(want)
    assert got["solutions"] and got["undecided_enclosures"] and got["exhausted"] and not got["complete"]


@pytest.mark.slow
def test_igp(taut_cli):
    robot = example("suspended-3cable")
    fixed = {"x": 2.7505, "y": 3.9798, "z": 5.5061}
    got = taut_cli("igp", "suspended-3cable", "--taut", "3,1,2", "--fix", "x=2.7505,y=3.9798,z=5.5061", "--json").json()
    want = solve_igp(robot, [0, 1, 2], fixed).as_dict()
    for s in want["solutions"]:
        for key in ("taut", "slack", "length_violations"):
            s[key] = plus1(s[key])
    assigned = want.pop("fixed")
    assert untimed(got) == {"robot": robot.name, "taut": [1, 2, 3], "assigned": assigned} | untimed(want)
    assert len(got["solutions"]) == 4


@pytest.mark.slow
def test_simulate(taut_cli):
    robot = example("planar-4cable")
    got = taut_cli(
        "simulate", "planar-4cable", "--waypoints=0,0,0;0.1,0.05,0", "--duration", "0.5", "--rate", "200", "--json"
    ).json()
    motion = trajectory_from_waypoints(robot, [[0, 0, 0], [0.1, 0.05, 0]], duration=0.5, law="quintic")
    res = simulate_control(robot, motion, kp=DEFAULT_KP, kd=DEFAULT_KD, rate_hz=200, method="qp", decimate=2)
    want = res.as_dict()
    renamed = {
        "time": "times",
        "pose": "poses",
        "lower_tension_margin": "lower_margin",
        "upper_tension_margin": "upper_margin",
        "distribution_failures": "failures",
        "feasible": "all_feasible",
    }
    for key, name in renamed.items():
        assert got[key] == want[name], key
    for key in ("kp", "kd", "rate_hz", "substeps", "method", "pose_names", "updates", "reference", "tensions"):
        assert got[key] == want[key], key
    for key in ("tracking_error_max", "tracking_error_rms", "position_error_max", "rotation_error_max"):
        assert got[key] == want[key], key
    for key in ("min_tension_margin", "slack_events", "first_failure_time", "complete"):
        assert got[key] == want[key], key
    assert got["samples"] == len(want["times"]) == 51 and got["updates"] == 101
    assert untimed(got).keys() >= {"robot", "controller", "law", "duration", "mass_error", "disturbance"}


def test_trajectory(taut_cli):
    robot = example("vscr-single-cable")
    got = taut_cli("trajectory", "vscr-single-cable", "--dt", "0.5", "--json").json()
    times, poses = builtin_trajectory(robot, dt=0.5)
    want = run_trajectory(robot, times, poses).as_dict()
    want["transitions"] = [e | {"cable": e["cable"] + 1, "object": e["object"] + 1} for e in want["transitions"]]
    assert got == {"robot": robot.name} | want
    assert got["transitions"]


@pytest.mark.slow
def test_plan(taut_cli):
    robot = example("robocrane")
    fixed = {"x": 0.0, "y": 0.0, "z": 2.0, "sigma": np.radians(35)}
    got = taut_cli(
        "plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", "x=0,y=0,z=2,sigma=35deg", "--planner=astar",
        "--json",
    ).json()  # fmt: skip
    M = WrenchFeasibleManifold.from_robot(robot, E=1e4 * np.eye(6), fixed=fixed)
    start, goal = (np.asarray(robot.reference.poses[q], float) for q in ("q1", "q2"))
    res = plan_path(M.implicit(), M.lift(start), M.lift(goal), method="astar", radius=0.2, metric=M.pose_metric)
    want = untimed(res.as_dict())
    for key in ("method", "found", "no_path", "complete", "charts", "expanded", "length"):
        assert got[key] == want[key], key
    assert got["nodes"] is None  # A* grows no tree
    np.testing.assert_allclose(got["path"], M.align(M.pose(res.path), start), rtol=0, atol=1e-12)
    assert got["fixed"] == pytest.approx(fixed, abs=1e-15)


@pytest.mark.slow
def test_atlas(taut_cli, tmp_path):
    robot = example("vscr-t-shaped")
    out = tmp_path / "atlas.json"
    got = taut_cli("atlas", "vscr-t-shaped", "--condition", "static", "--out", str(out), "--json").json()
    start = np.asarray(robot.reference.poses["initial"], float)
    atlas = build_atlas(robot, start)  # a point mass: the page of theta = 0
    pages, region = atlas.as_dict(), atlas_workspace(atlas, "static").as_dict()
    want = {k: pages[k] for k in ("start", "theta", "charts", "edges", "reachable_area")}
    want |= {"workspace_area": region["area"], "condition": "static", "pruned": plus1(region["pruned"])}
    assert untimed(got, "time") == {"robot": robot.name, "out": str(out)} | want
    full = json.loads(out.read_text())
    charts = [
        c | {"index": c["index"] + 1, "neighbours": plus1(c["neighbours"])}
        | {"structure": [[[k + 1, d] for k, d in s] for s in c["structure"]]}
        for c in pages["chart_list"]
    ]  # fmt: skip
    edges = [
        e | {"charts": plus1(e["charts"]), "cable": e["cable"] + 1, "object": e["object"] + 1}
        for e in pages["edge_list"]
    ]
    assert full["chart_list"] == charts and full["edge_list"] == edges


def test_check(taut_cli):
    robot = example("adjustable-8cable")
    got = taut_cli("check", "adjustable-8cable", "--trajectory", "sim-b", "--json").json()
    want = check_poses(robot, trajectory_poses(robot, "sim-b")).as_dict()
    want["steps"] = [
        s | {"index": s["index"] + 1, "collisions": [plus1(p) for p in s["collisions"]]} for s in want["steps"]
    ]
    summary = want["summary"]
    for key in [k for k in summary if k.startswith("first_")]:
        summary[key] = None if summary[key] is None else summary[key] + 1
    for key in [k for k in summary if k.endswith("_steps")]:
        summary[key] = [plus1(r) for r in summary[key]]
    assert got == {"robot": robot.name, "trajectory": "sim-b"} | want
    assert got["summary"]["force_closure_singular_steps"] and got["summary"]["first_problem"] >= 1
