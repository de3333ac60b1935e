"""A robot with swivelling exit pulleys through the command line: `taut ik`, `taut workspace`,
`taut check` and `taut fk` model the pulleys; `taut fk` refuses a pulley larger than its
cable with one line and status 2."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from taut.kinematics import inverse_kinematics
from taut.model import load_robot
from taut.statics import wrench_closure

ROBOT_YAML = """\
format: taut/1
name: swivel test robot
description: spatial 8-cable test robot whose cables leave the frame through swivelling pulleys
dimension: 3
orientation: xyz-fixed
platform:
  kind: rigid
  mass: 5.0
  wrench_point: [0, 0, 0]
  shape:
    capsules:
      - {a: [-0.15, 0, 0], b: [0.15, 0, 0], radius: 0.1}
cables:
  - {exit: [-1.5, -1, -1], anchor: [0.15, -0.1, 0.05], tension: [5, 500], swivel: {axis: [0, 0, 1], radius: 0.08}}
  - {exit: [1.5, -1, -1], anchor: [-0.15, -0.1, 0.05], tension: [5, 500], swivel: {axis: [0, 0, 1], radius: 0.08}}
  - {exit: [1.5, 1, -1], anchor: [-0.15, 0.1, 0.05], tension: [5, 500], swivel: {axis: [0, 0, 1], radius: 0.08}}
  - {exit: [-1.5, 1, -1], anchor: [0.15, 0.1, 0.05], tension: [5, 500], swivel: {axis: [0, 0, 1], radius: 0.08}}
  - {exit: [-1.5, -1, 1], anchor: [0.15, -0.1, -0.05], tension: [5, 500], swivel: {axis: [0, 0, -1], radius: 0.08}}
  - {exit: [1.5, -1, 1], anchor: [-0.15, -0.1, -0.05], tension: [5, 500], swivel: {axis: [0, 0, -1], radius: 0.08}}
  - {exit: [1.5, 1, 1], anchor: [-0.15, 0.1, -0.05], tension: [5, 500], swivel: {axis: [0, 0, -1], radius: 0.08}}
  - {exit: [-1.5, 1, 1], anchor: [0.15, 0.1, -0.05], tension: [5, 500], swivel: {axis: [0, 0, -1], radius: 0.08}}
"""


@pytest.fixture
def robot_file(tmp_path: Path) -> Path:
    path = tmp_path / "swivel.yaml"
    path.write_text(ROBOT_YAML, encoding="utf-8")
    return path


def test_ik_includes_the_pulleys(robot_file: Path, taut_cli: Callable) -> None:
    pose = [0.2, -0.1, 0.3, 0.1, -0.05, 0.2]
    res = taut_cli("ik", str(robot_file), "--pose", ",".join(map(str, pose)), "--json").json()
    robot = load_robot(robot_file)
    ik = inverse_kinematics(robot, pose)
    np.testing.assert_allclose(res["lengths"], ik.lengths, rtol=1e-12)
    np.testing.assert_allclose(res["directions"], ik.directions, atol=1e-12)
    np.testing.assert_allclose(res["structure_matrix"], ik.structure_matrix, atol=1e-12)
    # the arc and the offset tangent point make every cable longer than the straight line
    straight = np.linalg.norm(robot.exits - ik.anchors, axis=1)
    assert (np.asarray(res["lengths"]) > straight).all()


def test_workspace_uses_the_pulley_structure_matrix(robot_file: Path, tmp_path: Path, taut_cli: Callable) -> None:
    out = tmp_path / "ws.npz"
    res = taut_cli(
        "workspace",
        str(robot_file),
        "--condition",
        "wrench-closure",
        "--grid=-1.8:1.8:7;-0.8:0.8:5;-0.8:0.8:5",
        "--orientation",
        "0,0,0",
        "--out",
        str(out),
        "--json",
    ).json()
    assert res["poses"] == 7 * 5 * 5
    data = np.load(out)
    grid = np.meshgrid(data["axis_0"], data["axis_1"], data["axis_2"], indexing="ij")
    poses = np.column_stack([g.reshape(-1) for g in grid] + [np.zeros((grid[0].size, 3))])
    inside = data["inside"]
    W = inverse_kinematics(load_robot(robot_file), poses).structure_matrix
    np.testing.assert_array_equal(inside, wrench_closure(W))
    assert res["inside"] == int(inside.sum()) and 0 < res["inside"] < res["poses"]


def test_check_runs_on_the_tangent_points(robot_file: Path, tmp_path: Path, taut_cli: Callable) -> None:
    traj = tmp_path / "traj.yaml"
    traj.write_text("waypoints: [[0, 0, 0, 0, 0, 0], [0.3, 0.2, 0.1, 0, 0, 0.2]]\nsteps: [10]\n", encoding="utf-8")
    res = taut_cli("check", str(robot_file), "--trajectory", str(traj), "--json").json()
    assert len(res["steps"]) == 11


def test_fk_refuses_a_pulley_larger_than_its_cable_with_one_line(robot_file: Path, taut_cli: Callable) -> None:
    """A pulley radius (0.08 m) not smaller than its cable's length, the anchor's reach from
    the exit point: one line, status 2."""
    run = taut_cli("fk", str(robot_file), "--lengths", ",".join(["0.05"] + ["2.0"] * 7))
    assert run.code == 2
    assert run.err.count("\n") == 1 and run.err.startswith("taut: error: ")
    assert "cable 1's pulley radius 0.08 m is not smaller than the cable's length 0.05 m" in run.err
    assert "Traceback" not in run.err


def test_fk_models_the_pulleys(taut_cli: Callable) -> None:
    """`taut fk` on the built-in pulley robot with cable 1 alone taut: the equilibria hang
    from its exit point by its whole length (the load is along the swivel axis), numbered
    from 1, complete."""
    res = taut_cli("fk", "suspended-3pulley", "--lengths", "7.5,30,30", "--max-taut", "1", "--json").json()
    assert res["complete"] and len(res["solutions"]) == 2
    from taut.model import example

    robot = example("suspended-3pulley")
    for s in res["solutions"]:
        assert s["taut"] == [1]
        anchor = np.asarray(s["position"]) + _rotation(s["orientation"]) @ robot.anchors[0]
        np.testing.assert_allclose(anchor - robot.exits[0], [0, 0, 7.5], atol=1e-9)


def _rotation(angles: list[float]) -> np.ndarray:
    from taut.geometry import rotation_matrix

    return rotation_matrix(np.asarray(angles, float), "xyz-fixed")


def test_fk_pairs_of_pulley_cables_complete(taut_cli: Callable) -> None:
    """The two-cable subsets of the pulley robot at its reference lengths hold no equilibrium,
    and the search says so completely."""
    res = taut_cli("fk", "suspended-3pulley", "--max-taut", "2", "--json").json()
    assert res["complete"] and res["solutions"] == [] and res["subproblems"] == 6


@pytest.mark.slow
def test_igp_models_the_pulleys(taut_cli: Callable) -> None:
    """`taut igp` on the built-in pulley robot: the lengths to command are the pulley IK's
    (the stable solution at the reference position has the reference lengths)."""
    from taut.model import example

    robot = example("suspended-3pulley")
    x, y, z = robot.reference.poses["stable"][:3]
    res = taut_cli("igp", "suspended-3pulley", "--taut", "1,2,3", "--fix", f"x={x},y={y},z={z}", "--json").json()
    assert res["complete"] and len(res["solutions"]) == 4
    stable = [s for s in res["solutions"] if s["stable"]]
    assert len(stable) == 1
    np.testing.assert_allclose(stable[0]["lengths"], robot.reference.lengths, atol=2e-6)
    for s in res["solutions"]:
        ik = inverse_kinematics(robot, [*s["position"], *s["orientation"]])
        np.testing.assert_allclose(s["lengths"], ik.lengths, atol=1e-12)


def test_simulate_refuses_an_anchor_within_its_pulley_radius_of_the_axis(tmp_path: Path, taut_cli: Callable) -> None:
    """Cable 1's pulley axis points at the frame's centre: the reference motion brings its
    anchor within the pulley's 0.1 m radius of the axis, which is one line naming the time,
    the cable, the distance and the pose, and exit 2; the same motion the other way is simulated."""
    text = ROBOT_YAML.replace(
        "swivel: {axis: [0, 0, 1], radius: 0.08}}", "swivel: {axis: [1.5, 1, 1], radius: 0.1}}", 1
    ).replace("  mass: 5.0\n", "  mass: 5.0\n  inertia: [0.05, 0.05, 0.08, 0, 0, 0]\n")
    path = tmp_path / "near_axis.yaml"
    path.write_text(text)
    run = taut_cli("simulate", str(path), "--waypoints", "0,0,0,0,0,0;-0.1,0.1,0,0,0,0", "--duration", "1", "--json")
    assert run.code == 2 and run.out == "" and len(run.err.splitlines()) == 1, run.err
    assert "of the reference cable 1's anchor is" in run.err and "within the pulley's radius 0.1 m" in run.err
    assert "Traceback" not in run.err
    # the first such time: the anchor's distance from the axis, along the quintic reference
    robot = load_robot(path)
    t = float(run.err.split("at t = ")[1].split(" s")[0])
    from taut.motion import trajectory_from_waypoints

    motion = trajectory_from_waypoints(robot, [[0.0] * 6, [-0.1, 0.1, 0, 0, 0, 0]], duration=1.0)
    k = np.array([1.5, 1.0, 1.0]) / np.linalg.norm([1.5, 1.0, 1.0])
    exit_, anchor = np.array([-1.5, -1.0, -1.0]), np.array([0.15, -0.1, 0.05])

    def distance(time: float) -> float:
        b = motion.at([time]).poses[0, :3] + anchor
        return float(np.linalg.norm(np.cross(b - exit_, k)))

    assert distance(t) < 0.1 <= distance(t - 1e-3)
    away = taut_cli(
        "simulate",
        str(path),
        "--waypoints",
        "0,0,0,0,0,0;0.1,-0.1,0,0,0,0",
        "--duration",
        "1",
        "--rate",
        "200",
        "--json",
    )
    assert away.code == 0, away.err
