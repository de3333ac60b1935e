"""``taut igp``: the JSON contract, the human tables, and bad input (exit status 2)."""

import json

import numpy as np
import pytest


def test_igp_json_table_4_3(cli):
    code = cli.main(["igp", "suspended-3cable", "--taut", "3,1,2", "--fix", "x=2.7505,y=3.9798,z=5.5061", "--json"])
    out, err = cli.readouterr()
    assert code == 0, err
    assert "Traceback" not in err and "Warning" not in err
    d = json.loads(out)  # stdout is the JSON document alone (tests/cli/test_json_stdout.py)
    assert d["robot"] == "suspended 3-cable robot" and d["taut"] == [1, 2, 3] and d["elapsed_s"] > 0
    assert d["assigned"] == {"x": 2.7505, "y": 3.9798, "z": 5.5061}
    assert d["undecided_boxes"] == 0 and not d["exhausted"] and len(d["solutions"]) == 4
    for s in d["solutions"]:
        assert {"taut", "position", "orientation", "tensions", "lengths", "stable"} <= set(s)
        assert s["taut"] == [1, 2, 3] and s["position"] == [2.7505, 3.9798, 5.5061]
        assert len(s["tensions"]) == len(s["lengths"]) == 3 and min(s["tensions"]) > 0
    (stable,) = [s for s in d["solutions"] if s["stable"]]
    assert np.allclose(stable["lengths"], [7.5, 10, 9.5], atol=1e-3)
    assert np.allclose(stable["orientation"], [3.0064, 0.3417, 0.1089], atol=1e-3)


def test_igp_angles_in_degrees_and_slack_cables(cli):
    code = cli.main(
        [
            "igp",
            "teaching-prototype",
            "--taut",
            "1,2,3,4,6",
            "--fix",
            "x=0.363,y=0.454,z=0.122,phix=-2.42,phiy=23.262deg",
            "--json",
        ]
    )
    out, err = cli.readouterr()
    assert code == 0, err
    d = json.loads(out)
    assert np.isclose(d["assigned"]["b"], np.radians(23.262))
    assert len(d["solutions"]) == 2
    for s in d["solutions"]:
        assert s["slack"] == [5] and s["tensions"][4] == 0 and s["length_violations"] == []


@pytest.mark.slow
def test_igp_human_output(cli):
    code = cli.main(["igp", "suspended-3cable", "--taut", "1,2,3", "--fix", "x=2.7505,y=3.9798,z=5.5061"])
    out, err = cli.readouterr()
    assert code == 0, err
    assert "4 equilibria" in out and "free coordinates and tensions" in out and "cable lengths" in out
    assert "7.4999" in out and "yes" in out
    code = cli.main(["igp", "cogiro", "--taut", "3,4,6,7", "--fix", "x=0.255,y=-0.039,z=0.828,a=0.033"])
    out, _ = cli.readouterr()
    assert code == 0 and "≥" in out  # the spans of the slack cables


def test_igp_reports_an_exhausted_budget(cli):
    code = cli.main(
        ["igp", "robocrane", "--taut", "1,3,5", "--fix", "x=0,y=0,phi=2.8797932657906435", "--max-boxes", "500"]
    )
    out, err = cli.readouterr()
    assert code == 0, err
    assert "0 equilibria" in out and "ran out" in out


@pytest.mark.parametrize(
    "argv, words",
    [
        (["suspended-3cable", "--taut", "1,2,3", "--fix", "x=1,y=2"], "exactly 3"),
        (["suspended-3cable", "--taut", "1,2", "--fix", "x=1,w=2"], "unknown pose coordinate"),
        (["suspended-3cable", "--taut", "1,2", "--fix", "x=1,y"], "give a value"),
        (["suspended-3cable", "--taut", "1,2", "--fix", "x=1,y=nan"], "not finite"),
        (["suspended-3cable", "--taut", "1,2", "--fix", "x=1,x=2"], "twice"),
        (["suspended-3cable", "--taut", "1,9", "--fix", "x=1,y=2"], "--taut: no cable 9; the robot has cables 1..3"),
        (["suspended-3cable", "--taut", "0,1", "--fix", "x=1,y=2"], "--taut: no cable 0;"),
        (["suspended-3cable", "--taut", "1,1", "--fix", "x=1,y=2"], "twice"),
        (["suspended-3cable", "--taut", "1,two", "--fix", "x=1,y=2"], "cable numbers"),
        (["suspended-3cable", "--taut", "1,2", "--fix", "x=1,a=2", "--box", "0,0,0"], "--box"),
        (["suspended-3cable", "--taut", "1,2", "--fix", "x=1,a=2", "--max-boxes", "0"], "--max-boxes"),
        (["planar-4cable", "--taut", "1,2,3,4", "--fix", "x=1,y=2,theta=0"], "1 to 3 taut cables"),
        (["planar-4cable", "--taut", "1,2", "--fix", "x=1,y=2", "--box", "0,0,0,1,1,1"], "xmin,ymin,xmax,ymax"),
    ],
)
def test_igp_bad_input_exits_2(argv, words, cli):
    code = cli.main(["igp", *argv])
    _, err = cli.readouterr()
    assert code == 2 and err.startswith("taut: error: ") and words in err and "Traceback" not in err


def test_fk_json_numbers_cables_from_1(cli):
    """The library's 0-based taut sets come out of the CLI 1-based: an equilibrium's taut
    cables are those with a non-zero tension, counted from 1."""
    # cables 1 and 3 long enough to stay slack: the platform hangs from cable 2
    assert cli.main(["fk", "suspended-3cable", "--max-taut", "1", "--lengths", "30,5,30", "--json"]) == 0
    sols = json.loads(cli.readouterr().out)["solutions"]
    assert len(sols) == 2
    for s in sols:
        assert s["taut"] == [2]
        assert [k + 1 for k, t in enumerate(s["tensions"]) if t > 0] == s["taut"]
