"""The support matrix of ``docs/architecture.md`` §4.4, run cell by cell through the command line.

The table is read from the document, so that the two cannot disagree: every cell runs one
``taut`` command in a subprocess on a robot of its column's kind. A "supported" cell must exit 0
with a meaningful JSON answer (checked against the robot read here, not against the command's
own numbers); a "refused: REASON" cell must exit 2 with one line on stderr containing REASON.
A command that starts or stops working on a kind fails here until its cell is changed.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass
from functools import cache
from pathlib import Path

import numpy as np
import pytest
from conftest import Run, run_taut

ROOT = Path(__file__).resolve().parents[1]
DOC = ROOT / "docs" / "architecture.md"
FIXTURES = ROOT / "tests" / "model" / "fixtures"
HEADING = "### 4.4 Support matrix"

#: Commands that take no robot, so have no row.
NO_ROBOT = {"examples", "schema", "demo"}


@dataclass(frozen=True)
class Subject:
    """A robot of one kind and the queries the cells run on it."""

    robot: str  #: built-in example name or file
    pose: tuple[float, ...]  #: a pose inside its workspace
    taut: str  #: ``taut igp --taut``
    fix: str  #: ``taut igp --fix``, as many coordinates as taut cables
    reference_lengths: bool = False  #: ``taut fk`` on the robot's reference lengths, not the pose's

    def goal(self, step: float = 0.05) -> tuple[float, ...]:
        """A pose ``step`` along x from :attr:`pose`: the end of a short motion."""
        return (self.pose[0] + step, *self.pose[1:])


def fixture(path: str) -> str:
    return str(FIXTURES / path)


#: One robot per kind (the columns of the table).
SUBJECTS = {
    "point mass 2-D": Subject(fixture("caspr/point_xz_bodies.xml"), (0, 0.2), "1,2", "x=0,y=0.2"),
    "point mass 3-D": Subject(fixture("wirex/point_3t.wcrfx"), (0.2, -0.1, 1), "1,2,3", "x=0.2,y=-0.1,z=1"),
    "planar rigid": Subject(fixture("caspr/planar_xz_bodies.xml"), (0, 0, 0), "1,2", "x=0,y=0"),
    "spatial rigid": Subject(fixture("wirex/spatial_3r3t.wcrfx"), (0, 0, 1, 0, 0, 0), "1,2,3", "x=0,y=0,z=1"),
    "swivelling pulleys": Subject(fixture("wirex/pulleys_3r3t.wcrfx"), (0, 0, 1, 0, 0, 0), "1,2,3", "x=0,y=0,z=1"),
    "jointed": Subject(
        fixture("caspr/jointed_chain_bodies.xml"), (0, 0, 1.45, 0, 0, 0, 0, 0), "1,2,3", "x=0,y=0,z=1.45"
    ),
    "wrapping (VSCR)": Subject(fixture("taut/vscr_weighted.yaml"), (0.75, -0.5), "1,2", "x=0.75,y=-0.5"),
    "routed cables": Subject(fixture("taut/routed.yaml"), (0, 0, 0, 0, 0, 0), "1,2,3", "x=0,y=0,z=0"),
}

#: The geometrico-static problems on a fully-constrained 8-cable robot search every taut subset
#: of up to six cables (minutes); the 3-cable robot of Berti 2015, Table 4.3 answers in seconds.
SUSPENDED = Subject(
    "suspended-3cable", (2.7505, 3.9798, 5.5061, 3.007, 0.340, 0.109), "1,2,3", "x=2.7505,y=3.9798,z=5.5061", True
)
#: The same robot with 0.1 m swivelling pulleys at its exits.
SUSPENDED_PULLEYS = Subject(
    "suspended-3pulley",
    (2.756745, 3.986807, 5.487456, 3.005081, 0.346154, 0.111455),
    "1,2,3",
    "x=2.756745,y=3.986807,z=5.487456",
    True,
)
#: adjustable-8cable with assumed masses: its passive prismatic joint is moved by the cables
#: acting across it, where the chain fixture's two joints have no cable able to hold them.
ADJUSTABLE = Subject("adjustable-8cable", (5, 5, 1.5, 0, 0, 0, 1.5), "", "")
OVERRIDES = {
    ("taut simulate", "jointed"): ADJUSTABLE,
    ("taut fk", "spatial rigid"): SUSPENDED,
    ("taut igp", "spatial rigid"): SUSPENDED,
    ("taut fk", "swivelling pulleys"): SUSPENDED_PULLEYS,
    ("taut igp", "swivelling pulleys"): SUSPENDED_PULLEYS,
}


@cache
def load(name: str):
    from taut.model import example, load_robot

    return load_robot(name) if Path(name).suffix else example(name)


def numbers(values) -> str:
    return ",".join(repr(float(v)) for v in values)


def close(a, b, tol: float = 1e-6) -> bool:
    return bool(np.allclose(np.asarray(a, float), np.asarray(b, float), atol=tol, rtol=0))


# ---- the queries: argv for a subject, and the check of a supported cell's JSON ----------

Check = Callable[[dict, Subject], None]
Query = Callable[[Subject, Path], tuple[list[str], Check]]


def ik(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        robot = load(s.robot)
        assert close(d["pose"], s.pose)
        assert len(d["lengths"]) == robot.n_cables and min(d["lengths"]) > 0
        assert np.shape(d["structure_matrix"])[1] == robot.n_cables

    return ["ik", s.robot, f"--pose={numbers(s.pose)}"], check


def tensions(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert isinstance(d["feasible"], bool)
        if d["feasible"]:
            assert len(d["tensions"]) == load(s.robot).n_cables

    return ["tensions", s.robot, f"--pose={numbers(s.pose)}"], check


def workspace(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert d["poses"] == 2 ** load(s.robot).dimension
        assert 0 <= d["inside"] <= d["poses"]

    return ["workspace", s.robot, "--condition", "wrench-feasible", "--grid", "2"], check


def certified_workspace(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert len(d["axis_names"]) == load(s.robot).dimension
        volumes = d["inner_volume"] + d["outer_volume"] + d["undecided_volume"]
        assert abs(volumes - d["region_volume"]) <= 1e-9 * d["region_volume"]
        assert d["boxes"]["undecided"] > 0 or d["complete"]

    argv = ["workspace", s.robot, "--condition", "static", "--certified", "--eps", "0.5", "--max-boxes", "5000"]
    return argv, check


def _pose_of(solution: dict) -> list[float]:
    return [*solution["position"], *(solution.get("orientation") or []), *(solution.get("joints") or [])]


def sag(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        summary = d["summary"]
        assert summary["poses"] == 2 ** load(s.robot).dimension == len(d["poses"])
        assert 0 <= summary["both"] <= min(summary["feasible"], summary["straight_feasible"])

    return ["sag", s.robot, "--weight", "0.01", "--grid", "2"], check


def fk(s: Subject, tmp: Path):
    from taut.kinematics import cable_lengths

    robot = load(s.robot)
    if s.reference_lengths:
        lengths, extra = np.asarray(robot.reference.lengths, float), []
    else:
        lengths = cable_lengths(robot, np.asarray(s.pose, float))
        extra = ["--lengths", numbers(lengths)]

    def check(d: dict, s: Subject) -> None:
        assert d["solutions"], "the lengths of an equilibrium pose admit at least that equilibrium"
        for sol in d["solutions"]:
            spans = cable_lengths(robot, np.asarray(_pose_of(sol), float))
            taut = [i - 1 for i in sol["taut"]]
            assert close(spans[taut], lengths[taut])
            assert (spans <= lengths + 1e-6).all()

    return ["fk", s.robot, *extra], check


def igp(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert d["solutions"]
        want = sorted(int(i) for i in s.taut.split(","))
        for sol in d["solutions"]:
            assert sorted(sol["taut"]) == want
            assert len(sol["lengths"]) == load(s.robot).n_cables
            assert min(sol["tensions"]) >= 0

    return ["igp", s.robot, "--taut", s.taut, "--fix", s.fix], check


def plan(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert d["found"], "a short motion inside the workspace"
        assert close(d["path"][0], s.pose) and close(d["path"][-1], s.goal())

    return ["plan", s.robot, f"--start={numbers(s.pose)}", f"--goal={numbers(s.goal())}"], check


def atlas(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert d["charts"] >= 1
        assert 0 <= d["workspace_area"] <= d["reachable_area"] + 1e-9

    return ["atlas", s.robot, f"--start={numbers(s.pose[:2])}"], check


def trajectory(s: Subject, tmp: Path):
    path = tmp / "waypoints.txt"
    path.write_text(f"{numbers(s.pose)}\n{numbers(s.goal())}\n")

    def check(d: dict, s: Subject) -> None:
        assert d["samples"] == len(d["lengths"]) >= 2
        assert all(len(row) == load(s.robot).n_cables for row in d["lengths"])

    return ["trajectory", s.robot, "--waypoints", str(path), "--dt", "0.05", "--speed", "0.5"], check


def check_command(s: Subject, tmp: Path):
    path = tmp / "poses.csv"
    path.write_text(f"{numbers(s.pose)}\n{numbers(s.goal())}\n")

    def check(d: dict, s: Subject) -> None:
        assert len(d["steps"]) == d["summary"]["poses"] == 2

    return ["check", s.robot, "--trajectory", str(path)], check


def simulate(s: Subject, tmp: Path):
    def check(d: dict, s: Subject) -> None:
        assert d["pose_names"] == list(load(s.robot).pose_names)
        assert d["samples"] >= 2 and d["updates"] >= 2

    # 2 mm in 50 ms: accelerations of a few m/s², which cables pulling against gravity can give
    moves = f"--waypoints={numbers(s.pose)};{numbers(s.goal(0.002))}"
    return ["simulate", s.robot, moves, "--duration", "0.05"], check


def view(s: Subject, tmp: Path):
    out = tmp / "view.html"

    def check(d: dict, s: Subject) -> None:
        assert d["cables"] == load(s.robot).n_cables and d["out"] == str(out)
        assert out.stat().st_size == d["bytes"] > 0

    return ["view", s.robot, f"--pose={numbers(s.pose)}", "--out", str(out)], check


def calibrate(s: Subject, tmp: Path):
    """Noise-free lengths at 30 poses around the subject's: the fit reproduces them."""
    from taut.errors import TautError
    from taut.kinematics import cable_lengths

    robot = load(s.robot)
    rng = np.random.default_rng(0)
    poses = np.tile(np.asarray(s.pose, float), (30, 1))
    poses[:, : robot.dimension] += rng.uniform(-0.1, 0.1, (30, robot.dimension))
    try:
        lengths = cable_lengths(robot, poses)
    except TautError:  # a kind the command refuses before it reads the lengths
        lengths = np.ones((30, robot.n_cables))
    data = tmp / "data.csv"
    data.write_text(
        ",".join(f"l{i + 1}" for i in range(robot.n_cables)) + "\n" + "".join(numbers(row) + "\n" for row in lengths)
    )

    def check(d: dict, s: Subject) -> None:
        robot = load(s.robot)
        assert np.shape(d["exits"]) == robot.exits.shape
        assert max(d["residual_rms"]) < 1e-6

    return ["calibrate", s.robot, "--data", str(data)], check


def convert(suffix: str) -> Query:
    def query(s: Subject, tmp: Path):
        out = tmp / f"robot{suffix}"

        def check(d: dict, s: Subject) -> None:
            if suffix == ".mjcf.xml":  # MuJoCo is written, not read: the file is a MuJoCo model
                assert ET.parse(out).getroot().tag == "mujoco"
                return
            from taut.model import load_robot

            robot, back = load(s.robot), load_robot(out)
            assert (back.n_cables, back.pose_names) == (robot.n_cables, robot.pose_names)

        return ["convert", s.robot, str(out)], check

    return query


#: The rows of the table, by their first cell (backticks removed).
QUERIES: dict[str, Query] = {
    "taut ik": ik,
    "taut tensions": tensions,
    "taut workspace": workspace,
    "taut workspace --certified": certified_workspace,
    "taut sag": sag,
    "taut fk": fk,
    "taut igp": igp,
    "taut plan": plan,
    "taut atlas": atlas,
    "taut trajectory": trajectory,
    "taut check": check_command,
    "taut calibrate": calibrate,
    "taut simulate": simulate,
    "taut view": view,
    "taut convert to taut YAML": convert(".yaml"),
    "taut convert to CASPR": convert("_bodies.xml"),
    "taut convert to WireX": convert(".wcrfx"),
    "taut convert to MuJoCo": convert(".mjcf.xml"),
}


# ---- the table ---------------------------------------------------------------------------


def table() -> tuple[list[str], list[tuple[str, list[str]]]]:
    """The kinds (column heads) and the rows (analysis, cells) of the support matrix."""
    text = DOC.read_text(encoding="utf-8")
    assert HEADING in text, f"{DOC.name} has no section {HEADING!r}"
    section = text.split(HEADING, 1)[1].split("\n#", 1)[0]
    lines = [ln.strip() for ln in section.splitlines() if ln.strip().startswith("|")]
    rows = [[c.strip() for c in ln.strip("|").split("|")] for ln in lines]
    head, rule, *body = rows
    assert all(set(c) <= set("-: ") for c in rule), "the second line of the table is its rule"
    assert all(len(r) == len(head) for r in body), "every row has a cell per kind"
    return head[1:], [(r[0].replace("`", ""), r[1:]) for r in body]


KINDS, ROWS = table()
CELLS = [(analysis, kind, cell) for analysis, cells in ROWS for kind, cell in zip(KINDS, cells)]


def test_the_table_covers_every_kind_and_every_command():
    assert set(KINDS) == set(SUBJECTS), "a kind of the table without a robot here, or the reverse"
    analyses = [a for a, _ in ROWS]
    assert sorted(analyses) == sorted(QUERIES), "a row without a query here, or a query without a row"
    usage = run_taut("--help").out
    commands = set(re.search(r"\{([a-z,]+)\}", usage).group(1).split(","))
    assert commands - NO_ROBOT == {a.split()[1] for a in analyses}, "a command that takes a robot has no row"
    for _, _, cell in CELLS:
        assert cell == "supported" or re.fullmatch(r"refused: \S.*", cell), f"cell {cell!r}"


#: Every cell is a command-line run (a second to a minute each): they run with the slow tests
#: (`make check`); the quick suite checks the table itself.
@pytest.mark.slow
@pytest.mark.parametrize(("analysis", "kind", "cell"), CELLS, ids=[f"{a}|{k}" for a, k, _ in CELLS])
def test_cell(analysis, kind, cell, tmp_path):
    subject = OVERRIDES.get((analysis, kind), SUBJECTS[kind])
    argv, check = QUERIES[analysis](subject, tmp_path)
    run: Run = run_taut(*argv, "--json", timeout=300)
    if cell == "supported":
        assert run.code == 0, f"{analysis} on {kind} ({subject.robot}) is marked supported: {run.err.strip()}"
        check(run.json(), subject)
        return
    reason = cell.removeprefix("refused: ")
    lines = run.err.splitlines()
    assert run.code == 2 and len(lines) == 1 and lines[0].startswith("taut: error: "), (
        f"{analysis} on {kind} ({subject.robot}) is marked refused ({reason}): exit {run.code}, stderr {run.err!r}"
    )
    assert " ".join(reason.split()) in " ".join(lines[0].split()), f"the refusal does not say {reason!r}: {lines[0]}"
    assert run.out == ""
