"""``taut plan``: the Robocrane queries (Bohigas et al. 2013, §5) by the three planners,
"no path" answers, and bad input."""

import json

import numpy as np
import pytest

from taut.kinematics import platform_frame
from taut.model import load_robot
from taut.planning import verify_path

SLICE = "x=0,y=0,z=2,sigma=35deg"
ROBOT = load_robot("robocrane")


def same_pose(a, b) -> bool:
    """Same platform position and rotation (the robot's own orientation convention)."""
    (pa, Ra), (pb, Rb) = (platform_frame(ROBOT, np.asarray(q, float)[None]) for q in (a, b))
    return bool(np.allclose(pa, pb, atol=1e-9) and np.allclose(Ra, Rb, atol=1e-9))


@pytest.mark.slow
def test_plan_q1_q2_json_csv_plot(cli, tmp_path):
    csv, png = tmp_path / "p.csv", tmp_path / "p.png"
    code = cli.main(
        [
            "plan",
            "robocrane",
            "--start",
            "q1",
            "--goal",
            "q2",
            "--fix",
            SLICE,
            "--planner",
            "astar",
            "--out",
            str(csv),
            "--plot",
            str(png),
            "--json",
        ]
    )
    out, err = cli.readouterr()
    assert code == 0, err
    d = json.loads(out)
    assert d["found"] and d["verified"] and d["charts"] > 1 and d["elapsed_s"] > 0
    assert d["planner"] == d["method"] == "astar" and d["expanded"] > 0 and d["nodes"] is None
    assert 0 < d["min_tension_margin"] < 0.5
    path = np.array(d["path"])
    assert np.allclose(path[0], [0, 0, 2, -0.5, 0.9, 7 * np.pi / 36])
    assert same_pose(path[-1], [0, 0, 2, 2.0, 0.9, 7 * np.pi / 36])  # perhaps by other angles
    table = np.loadtxt(csv, delimiter=",", skiprows=1)
    assert table.shape == (len(path), 18) and np.all(table[:, 6:12] > 0) and np.all(table[:, 12:] < 1)
    assert png.stat().st_size > 1000


def test_plan_human_output(cli):
    assert cli.main(["plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", SLICE]) == 0
    assert "independent check: feasible" in cli.readouterr().out


@pytest.mark.parametrize(
    "argv",
    [
        ["--start", "q1", "--goal", "q2", "--fix", "w=1"],
        ["--start", "q1", "--goal", "1,2,3", "--fix", SLICE],
        ["--start", "q1", "--goal", "0,0,2,0.8,-2.4,35deg", "--fix", SLICE],  # not wrench-feasible
        ["--start", "q1", "--goal", "0,0,1,2,0.9,35deg", "--fix", SLICE],  # off the slice
        ["--start", "q1", "--goal", "q2", "--wrench-ellipsoid", "1,2"],
        ["--start", "q1", "--goal", "q2", "--wrench-ellipsoid", "-1"],
    ],
)
def test_plan_bad_input_exit_2(cli, argv):
    assert cli.main(["plan", "robocrane", *argv]) == 2
    assert "taut: error:" in cli.readouterr().err


def test_plan_needs_a_hexapod(cli):
    assert cli.main(["plan", "suspended-3cable", "--start", "0,0,0,0,0,0", "--goal", "0,0,0,0,0,0"]) == 2


@pytest.mark.slow
@pytest.mark.parametrize("extra", [[], ["--shorten"], ["--unidirectional", "--seed", "3"]])
def test_plan_atlasrrt_q3_q4_across_phi_pi(cli, extra):
    argv = ["plan", "robocrane", "--start", "q3", "--goal", "q4", "--fix", SLICE, "--planner", "atlasrrt"]
    assert cli.main([*argv, *extra, "--json"]) == 0, cli.readouterr().err
    d = json.loads(cli.readouterr().out)
    assert d["planner"] == d["method"] == "atlasrrt" and d["nodes"] > 2 and d["expanded"] is None
    assert d["found"] and d["verified"] and not d["no_path"]
    path = np.array(d["path"])
    q3, q4 = (np.array(ROBOT.reference.poses[q]) for q in ("q3", "q4"))
    assert np.allclose(path[0], q3) and same_pose(path[-1], q4)
    assert path[:, 3].min() < -np.pi  # across the seam of the φ window: 2.1 rad instead of 4.2
    assert d["length"] < 3.5
    # our own check of the printed path, finer than the command's
    assert verify_path(ROBOT, path, subdivide=20).all_feasible


@pytest.mark.parametrize(
    "start", ["0,0,2,-0.5,0.9,35deg", "0,0,2,5.783185307179586,0.9,35deg", "0,0,2,2.641592653589793,-0.9,35deg"]
)
def test_plan_path_begins_at_the_start_as_written(cli, start):
    # q1, q1 with φ + 2π, q1 as (φ + π, −θ): the same pose, planned from its canonical lift
    assert cli.main(["plan", "robocrane", f"--start={start}", "--goal", "q2", "--fix", SLICE, "--json"]) == 0
    d = json.loads(cli.readouterr().out)
    path = np.array(d["path"])
    s = [float(v) for v in start.split(",")[:5]]
    np.testing.assert_allclose(path[0, :5], s, atol=1e-12)
    assert same_pose(path[0], ROBOT.reference.poses["q1"]) and same_pose(path[-1], ROBOT.reference.poses["q2"])
    assert np.abs(np.diff(path, axis=0)).max() < 0.2 and d["verified"]
    assert verify_path(ROBOT, path, subdivide=20).all_feasible


@pytest.mark.slow
def test_plan_atlasrrt_budget_runs_out_and_auto_then_proves_no_path(cli):
    islands = ["--start", "0,0,2,-1.3,2.2,35deg", "--goal", "0,0,2,0.6,2.4,35deg", "--fix", SLICE, "--radius", "0.3"]
    assert cli.main(["plan", "robocrane", *islands, "--planner", "atlasrrt", "--max-nodes", "60", "--json"]) == 0
    d = json.loads(cli.readouterr().out)
    assert not d["found"] and not d["no_path"] and d["path"] == [] and d["nodes"] >= 60
    assert cli.main(["plan", "robocrane", *islands, "--planner", "atlasrrt", "--max-nodes", "60"]) == 0
    assert "not a proof" in cli.readouterr().out
    assert cli.main(["plan", "robocrane", *islands, "--planner", "auto", "--max-nodes", "60", "--json"]) == 0
    d = json.loads(cli.readouterr().out)
    assert d["planner"] == "auto" and d["method"] == "astar" and not d["found"] and d["no_path"]


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["--planner", "atlasrrt", "--step", "0.5", "--radius", "0.4"], "--step"),
        (["--planner", "atlasrrt", "--step", "-0.1"], "--step"),
        (["--planner", "atlasrrt", "--max-nodes", "1"], "--max-nodes"),
        (["--planner", "astar", "--shorten"], "--shorten"),
        (["--planner", "rrtstar"], "rrtstar"),
        (["--planner", "atlasrrt", "--goal", "0,0,2,0.8,-2.4,35deg"], "not wrench-feasible"),
        (["--planner", "atlasrrt", "--goal", "0,0,1,2,0.9,35deg"], "slice"),
        (["--planner", "atlasrrt", "--goal", "0,0,2,1"], "x,y,z,phi,theta,sigma"),
    ],
)
def test_plan_atlasrrt_bad_input_one_line_exit_2(cli, argv, words):
    base = ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", SLICE]
    # a later --goal overrides the first (argparse keeps the last value)
    assert cli.main([*base, *argv]) == 2
    out, err = cli.readouterr()
    lines = err.splitlines()
    assert out == "" and len(lines) == 1 and lines[0].startswith("taut: error: ") and words in lines[0], err


@pytest.mark.slow
def test_plan_q3_q4_and_a_proof_of_no_path(cli):
    argv = ["plan", "robocrane", "--start", "q3", "--goal", "q4", "--fix", SLICE, "--radius", "0.3"]
    assert cli.main([*argv, "--planner", "astar", "--json"]) == 0
    d = json.loads(cli.readouterr().out)
    assert d["found"] and d["verified"] and 2.1 < d["length"] < 4  # across φ = −π
    # two islands of the slice (tests/planning/test_robocrane.py): the atlas of the start's
    # component completes (φ, σ periodic, θ ∈ [0, π] modulo the half-turn)
    assert (
        cli.main(
            [
                "plan",
                "robocrane",
                "--start",
                "0,0,2,-1.3,2.2,35deg",
                "--goal",
                "0,0,2,0.6,2.4,35deg",
                "--fix",
                SLICE,
                "--radius",
                "0.3",
                "--planner",
                "astar",
                "--json",
            ]
        )
        == 0
    )
    d = json.loads(cli.readouterr().out)
    assert not d["found"] and d["no_path"] and d["path"] == [] and d["charts"] == d["expanded"]
