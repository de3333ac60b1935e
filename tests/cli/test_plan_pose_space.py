"""``taut plan`` on robots other than the cable hexapod: the planner picked from the robot
(point mass, planar: grid; redundant: rrtconnect), ``--planner`` overriding it, a planner
that does not apply refused in one line, the path from --start to --goal as written."""

import json

import numpy as np
import pytest

from taut.model import example, load_robot
from taut.planning import verify_path

POINT_MASS = """\
format: taut/1
name: planar point mass
description: test fixture, a 1 kg point mass in a 2 m square frame
dimension: 2
platform:
  kind: point-mass
  mass: 1.0
  gravity: [0, -9.81]
cables:
  - {exit: [-1.0, -1.0], tension: [1, 30]}
  - {exit: [1.0, -1.0], tension: [1, 30]}
  - {exit: [1.0, 1.0], tension: [1, 30]}
  - {exit: [-1.0, 1.0], tension: [1, 30]}
"""


@pytest.fixture
def point_mass(tmp_path):
    path = tmp_path / "point-mass.yaml"
    path.write_text(POINT_MASS)
    return path


def fine(robot, path) -> bool:
    d = np.diff(path, axis=0)
    if not robot.is_point_mass:
        d[:, robot.dimension :] = np.mod(d[:, robot.dimension :] + np.pi, 2 * np.pi) - np.pi
    n = max(1, int(np.ceil(np.linalg.norm(d, axis=1).max() / 1e-3)))
    return verify_path(robot, path, subdivide=n).all_feasible


@pytest.mark.slow
def test_point_mass_auto_is_the_grid(cli, point_mass, tmp_path):
    csv = tmp_path / "p.csv"
    argv = ["plan", str(point_mass), "--start=-0.92,0.92", "--goal", "0.92,0.92", "--out", str(csv), "--json"]
    assert cli.main(argv) == 0, cli.readouterr().err
    d = json.loads(cli.readouterr().out)
    assert d["planner"] == "auto" and d["method"] == "grid" and d["found"] and d["verified"]
    assert d["expanded"] > 0 and d["nodes"] is None and d["no_path"] is False
    path = np.array(d["path"])
    assert path[0].tolist() == [-0.92, 0.92] and path[-1].tolist() == [0.92, 0.92]
    assert fine(load_robot(point_mass), path)
    table = np.loadtxt(csv, delimiter=",", skiprows=1)
    lengths = np.linalg.norm(path[:, None, :] - load_robot(point_mass).exits[None], axis=2)
    np.testing.assert_allclose(table, np.hstack([path, lengths]), atol=1e-12)


@pytest.mark.slow
def test_planar_grid_proves_no_path_and_rrtconnect_does_not(cli):
    argv = ["plan", "planar-4cable", "--start", "0,0,0", "--goal", "0,0,3", "--max-nodes", "2000"]
    assert cli.main([*argv, "--json"]) == 0
    d = json.loads(cli.readouterr().out)
    assert d["method"] == "grid" and not d["found"] and d["no_path"] and d["path"] == []
    assert cli.main(argv) == 0
    assert "proved at the lattice's resolution" in cli.readouterr().out
    argv = [*argv[:-2], "--planner", "rrtconnect", "--max-nodes", "60", "--json"]
    assert cli.main(argv) == 0
    d = json.loads(cli.readouterr().out)
    assert d["method"] == "rrtconnect" and not d["found"] and not d["no_path"] and d["nodes"] >= 60


def test_redundant_robot_auto_is_rrtconnect_goal_as_written(cli):
    # the goal written with yaw -3.2 (= 3.083): the short way from yaw 3 is 0.083 rad
    argv = ["plan", "spatial-8cable", "--start", "0,0,0,0,0,3", "--goal", "0,0,0,0,0,-3.2", "--json"]
    assert cli.main(argv) == 0, cli.readouterr().err
    d = json.loads(cli.readouterr().out)
    assert d["method"] == "rrtconnect" and d["found"] and d["verified"] and d["nodes"] >= 2
    path = np.array(d["path"])
    assert path[0].tolist() == [0, 0, 0, 0, 0, 3] and path[-1].tolist() == [0, 0, 0, 0, 0, -3.2]
    assert d["length"] < 0.1
    assert fine(example("spatial-8cable"), path)


@pytest.mark.parametrize(
    ("robot", "argv", "words"),
    [
        ("spatial-8cable", ["--planner", "grid"], "at most 3 coordinates"),
        ("spatial-8cable", ["--planner", "astar", "--start", "0,0,0,0,0,0", "--goal", "0,0,0,0,0,1"], "6-cable"),
        ("planar-4cable", ["--planner", "atlasrrt"], "6-cable"),
        ("planar-4cable", ["--fix", "x=0"], "--fix"),
        ("planar-4cable", ["--planner", "grid", "--step", "0.1"], "--step"),
        ("planar-4cable", ["--lengths", "1,2,3"], "--lengths"),
        ("planar-4cable", ["--start", "0,0"], "x,y,theta"),
        ("planar-4cable", ["--goal", "0,0,3", "--wrench-ellipsoid", "1,2"], "--wrench-ellipsoid"),
        ("planar-4cable", ["--goal", "0.99,0.99,0"], "not valid"),
        ("suspended-3cable", ["--start", "0,0,0,0,0,0", "--goal", "0,0,0,0,0,0"], "as many cables"),
        ("robocrane", ["--start", "q1", "--goal", "q2", "--spacing", "0.1"], "--spacing"),
    ],
)
def test_planner_that_does_not_apply_one_line_exit_2(cli, robot, argv, words):
    base = ["plan", robot, "--start", "0,0,0", "--goal", "0.1,0,0"]
    assert cli.main([*base, *argv]) == 2
    out, err = cli.readouterr()
    lines = err.splitlines()
    assert out == "" and len(lines) == 1 and lines[0].startswith("taut: error: ") and words in lines[0], err


def test_help_says_which_planner_applies_to_what(cli):
    assert cli.main(["plan", "--help"]) == 0
    text = " ".join(cli.readouterr().out.split())
    for words in ("auto = rrtconnect", "auto = grid", "point masses", "redundant", "under-constrained", "refused"):
        assert words in text


def test_rrtconnect_on_the_hexapod_in_tilt_and_torsion_angles(cli):
    # --planner overrides the robot's own (the manifold planners): its pose space, q1 -> q2
    # as written, not a canonical image
    argv = ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--planner", "rrtconnect", "--json"]
    assert cli.main(argv) == 0, cli.readouterr().err
    d = json.loads(cli.readouterr().out)
    robot = load_robot("robocrane")
    path = np.array(d["path"])
    assert d["method"] == "rrtconnect" and d["found"] and d["verified"]
    assert path[0].tolist() == list(robot.reference.poses["q1"]) and path[-1].tolist() == list(
        robot.reference.poses["q2"]
    )
    assert fine(robot, path)
