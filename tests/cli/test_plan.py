"""``taut plan``: the Robocrane query q1 → q2 (Bohigas et al. 2013, §5) and bad input."""

import json

import numpy as np
import pytest

SLICE = "x=0,y=0,z=2,sigma=35deg"


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
    assert 0 < d["min_tension_margin"] < 0.5
    path = np.array(d["path"])
    assert np.allclose(path[0], [0, 0, 2, -0.5, 0.9, 7 * np.pi / 36])
    assert np.allclose(path[-1], [0, 0, 2, 2.0, 0.9, 7 * np.pi / 36])
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


def test_plan_q3_q4_and_a_proof_of_no_path(cli):
    assert (
        cli.main(["plan", "robocrane", "--start", "q3", "--goal", "q4", "--fix", SLICE, "--radius", "0.3", "--json"])
        == 0
    )
    d = json.loads(cli.readouterr().out)
    assert d["found"] and d["verified"] and d["length"] > 4
    # two islands of the slice (tests/planning/test_robocrane.py): the atlas of the start's
    # component completes inside the angle window φ ∈ [−π, π], θ ∈ [0, π]
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
                "--json",
            ]
        )
        == 0
    )
    d = json.loads(cli.readouterr().out)
    assert not d["found"] and d["exhausted"] and d["path"] == [] and d["charts"] == d["expanded"]
