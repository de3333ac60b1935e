"""``--json`` is one JSON document on stdout and nothing else, for every command and every
method, condition and mode, with the solver, numba, dask and matplotlib all in play.

Each case runs ``python -m taut`` in a subprocess, as a user or a pipe does (HiGHS writes its
banner from C, where an in-process capture would not see it)."""

from __future__ import annotations

import re
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

import taut
from taut.kinematics import structure_matrix
from taut.statics import METHODS, external_wrench
from taut.workspace import CONDITIONS

#: Lengths measured on a printer built off its drawing (tests/calibration).
CALIBRATION_DATA = Path(__file__).parents[1] / "calibration" / "fixtures" / "printer-5cable.csv"

#: Asserts on the JSON document (and files in the temporary directory); a check written as
#: one expression returns its truth instead.
Check = Callable[[dict, Path], object]


def _no_check(d: dict, tmp: Path) -> None:
    assert isinstance(d, dict) and d


def _tensions(method: str) -> Check:
    def check(d: dict, tmp: Path) -> None:
        assert d["method"] == method and d["feasible"] is True and d["status"] == "optimal"
        tau = np.array(d["tensions"])
        robot = taut.example("spatial-8cable")
        lo, hi = robot.tension_bounds
        assert tau.shape == (8,) and np.all(tau >= lo - 1e-9) and np.all(tau <= hi + 1e-9)
        w = external_wrench(robot, d["pose"])
        np.testing.assert_allclose(structure_matrix(robot, d["pose"]) @ tau + w, 0, atol=1e-7 * np.abs(w).max())

    return check


def _workspace(condition: str) -> Check:
    def check(d: dict, tmp: Path) -> None:
        assert d["condition"] == condition and d["poses"] == 4**2
        assert 0 <= d["inside"] <= d["poses"]

    return check


def _trajectory(d: dict, tmp: Path) -> None:
    assert d["samples"] == len(d["times"]) > 1 and isinstance(d["tension_feasible"], bool)
    assert (tmp / "t.csv").read_text().startswith("time,x,y")
    assert (tmp / "t.png").stat().st_size > 1000


def _simulate(d: dict, tmp: Path) -> None:
    """A 1 s move of spatial-8cable with a 10 % mass error and a 5 N step along x at 0.5 s:
    the error of x stays below the bound of the error dynamics, 5 N / (5 kg · 1.1 · 400/s²)
    plus the weight error's share (z: 0.1 · 9.81 / (1.1 · 400) m), see
    tests/dynamics/test_control.py."""
    assert d["robot"] == "spatial 8-cable robot" and d["feasible"] is True and d["distribution_failures"] == 0
    assert len(d["time"]) == len(d["pose"]) == len(d["tensions"]) == d["samples"] == 101
    assert np.array(d["tensions"]).shape == (101, 8) and d["min_tension_margin"] > 0
    assert 0 < d["tracking_error_max"][2] <= 1.05 * 0.1 * 9.81 / (1.1 * 400)
    assert isinstance(d["slack_events"], int) and d["first_failure_time"] is None
    assert (tmp / "s.csv").read_text().startswith("time,x,y,z,a,b,c,ref_x")
    assert (tmp / "s.png").stat().st_size > 1000


def _ik(d: dict, tmp: Path) -> None:
    u = np.array(d["directions"])
    np.testing.assert_allclose(np.linalg.norm(u, axis=1), 1.0)
    assert (tmp / "ik.png").stat().st_size > 1000 and d["plot"] == str(tmp / "ik.png")


#: (id, argv, check); ``{tmp}`` in an argument is replaced by the test's temporary directory.
CASES: list[tuple[str, list[str], Check]] = [
    ("examples", ["examples"], lambda d, tmp: d["examples"] and d["examples"][0]["name"]),
    ("schema", ["schema"], lambda d, tmp: d["type"] == "object"),
    ("ik", ["ik", "planar-4cable", "--pose=0.1,0,5deg", "--plot", "{tmp}/ik.png"], _ik),
    *(
        (
            f"tensions-{m}",
            ["tensions", "spatial-8cable", "--pose", "0.1,0.1,0,0,0,0", "--method", m],
            _tensions(m),
        )
        for m in METHODS
    ),
    (
        "tensions-infeasible",
        ["tensions", "planar-4cable", "--pose", "0,0,0", "--wrench", "0,1e6,0"],
        lambda d, tmp: d["feasible"] is False and d["tensions"] is None,
    ),
    *(
        (
            f"workspace-{c}",
            ["workspace", "planar-4cable", "--condition", c, "--grid", "4", "--orientation", "0"],
            _workspace(c),
        )
        for c in CONDITIONS
    ),
    (
        "workspace-out-plot",
        ["workspace", "vscr-four-cable", "--condition", "static", "--grid", "4"]
        + ["--out", "{tmp}/w.npz", "--plot", "{tmp}/w.png"],
        lambda d, tmp: (tmp / "w.npz").is_file() and (tmp / "w.png").is_file() and d["out"].endswith("w.npz"),
    ),
    (
        "calibrate",
        ["calibrate", "printer-5cable", "--data", str(CALIBRATION_DATA)] + ["--out", "{tmp}/cal.yaml"],
        lambda d, tmp: d["identifiable"] is True and len(d["exits"]) == 5 and (tmp / "cal.yaml").is_file(),
    ),
    (
        "calibrate-plan",
        ["calibrate", "--plan", "8", "printer-5cable"],
        lambda d, tmp: len(d["poses"]) == 8,
    ),
    (
        "sag",
        ["sag", "cogiro-sagging", "--grid", "2", "--method", "qp", "--plot", "{tmp}/sag.png"],
        lambda d, tmp: d["summary"]["poses"] == 8 == len(d["poses"]) and (tmp / "sag.png").stat().st_size > 1000,
    ),
    (
        "fk",
        ["fk", "suspended-3cable", "--max-taut", "2"],
        # Table 4.3 of the thesis: no equilibrium with at most 2 taut cables, 6 sub-problems
        lambda d, tmp: (
            d["complete"] is True
            and d["undecided_boxes"] == 0
            and d["undecided_enclosures"] == []
            and d["solutions"] == []
            and d["subproblems"] == 6
        ),
    ),
    (
        "igp",
        ["igp", "suspended-3cable", "--taut", "3,1,2", "--fix", "x=2.7505,y=3.9798,z=5.5061"],
        lambda d, tmp: len(d["solutions"]) == 4,
    ),
    (
        "trajectory",
        ["trajectory", "vscr-single-cable", "--out", "{tmp}/t.csv", "--plot", "{tmp}/t.png"],
        _trajectory,
    ),
    *(
        (
            f"atlas-{c}",
            ["atlas", "vscr-agriculture", "--start", "0,0.991", "--theta", "0", "--condition", c],
            lambda d, tmp: d["charts"] >= 1 and d["reachable_area"] > 0,
        )
        for c in ("wrench-feasible", "wrench-closure", "static")
    ),
    *(
        (
            f"check-{m}",
            ["check", "adjustable-8cable", "--trajectory", "sim-d", "--method", m],
            lambda d, tmp: d["summary"]["poses"] == len(d["steps"]) > 0,
        )
        for m in ("fast", "lp")
    ),
    (
        "plan",
        ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", "x=0,y=0,z=2,sigma=35deg"]
        + ["--out", "{tmp}/p.csv", "--plot", "{tmp}/p.png"],
        lambda d, tmp: d["found"] and d["verified"] and (tmp / "p.csv").is_file() and (tmp / "p.png").is_file(),
    ),
    *(
        (
            f"plan-{p}",
            ["plan", "robocrane", "--start", "q1", "--goal", "q2", "--fix", "x=0,y=0,z=2,sigma=35deg", "--planner", p],
            lambda d, tmp, p=p: d["found"] and d["verified"] and d["planner"] == p and not d["no_path"],
        )
        for p in ("atlasrrt", "astar")
    ),
    (
        "simulate",
        ["simulate", "spatial-8cable", "--waypoints", "0,0,0;0.2,0.1,0.1", "--duration", "1", "--mass-error", "0.1"]
        + ["--disturbance", "0.5:5,0,0,0,0,0", "--out", "{tmp}/s.csv", "--plot", "{tmp}/s.png"],
        _simulate,
    ),
    (
        "simulate-infeasible",
        # 0.8 m out and back in 0.3 s: more than 8 cables of 500 N can give
        ["simulate", "spatial-8cable", "--waypoints", "0,0,0;0.6,0.3,0.4;0,0,0", "--duration", "0.3"],
        lambda d, tmp: (
            d["feasible"] is False
            and d["distribution_failures"] > 0
            and 0 < d["first_failure_time"] < 0.3
            and d["min_tension_margin"] >= 0
        ),
    ),
    (
        "view",
        ["view", "spatial-8cable", "--pose", "0.1,0,0.2,0,0,0", "--out", "{tmp}/v.html", "--plotlyjs", "beside"],
        lambda d, tmp: d["view"] == "robot" and (tmp / "v.html").stat().st_size == d["bytes"] and d["cables"] == 8,
    ),
    (
        "convert",
        ["convert", "cogiro", "{tmp}/c_bodies.xml"],
        lambda d, tmp: d["format"] == "caspr" and (tmp / "c_bodies.xml").is_file() and (tmp / "c_cables.xml").is_file(),
    ),
]

#: Commands whose JSON is checked elsewhere (``demo``: tests/cli/test_cli.py, a minute long).
ELSEWHERE = {"demo"}


def _commands() -> set[str]:
    """The commands ``taut --help`` lists."""
    out = subprocess.run([sys.executable, "-m", "taut", "--help"], capture_output=True, text=True, check=True).stdout
    return set(re.search(r"\{([a-z,-]+)\}", out).group(1).split(","))


def test_every_command_has_a_case():
    assert _commands() == {argv[0] for _, argv, _ in CASES} | ELSEWHERE


#: Cases of the quick suite: every command once, and the modes that run HiGHS (whose banner
#: was the historical stdout pollution); the slow suite runs every case.  ``igp``: the same
#: command is tests/cli/test_igp.py::test_igp_json_table_4_3.
QUICK = {
    "examples",
    "calibrate",
    "schema",
    "ik",
    "tensions-lp",
    "tensions-qp",
    "tensions-infeasible",
    "workspace-wrench-feasible",
    "workspace-out-plot",
    "fk",
    "trajectory",
    "atlas-wrench-feasible",
    "check-lp",
    "plan",
    "plan-atlasrrt",
    "simulate",
    "view",
    "convert",
}


@pytest.mark.parametrize(
    ("argv", "check"), [pytest.param(a, c, id=i, marks=() if i in QUICK else pytest.mark.slow) for i, a, c in CASES]
)
def test_stdout_is_json_alone(argv, check, taut_cli, tmp_path):
    run = taut_cli(*(a.replace("{tmp}", str(tmp_path)) for a in argv), "--json")
    assert run.code == 0, run.err
    verdict = check(run.json(), tmp_path)
    assert verdict is None or verdict, "the JSON fields are not as expected"
    assert "Traceback" not in run.err and "Warning" not in run.err
