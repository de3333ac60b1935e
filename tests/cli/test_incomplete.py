"""Never a silent gap, at the command line: a real search cut short by ``--max-boxes``
prints its answer with ``"complete": false`` and the undecided boxes' enclosures, one
warning line on stderr naming the sub-problems concerned, and exits 3 under ``--strict``;
a complete answer has no warning and exits 0 under ``--strict``."""

import json
import re
import subprocess
import sys
from itertools import combinations

import pytest
from fold_robot import fold_robot

from taut.cli._incomplete import CAUSE_TEXT, NAMED, warning
from taut.dgp import CAUSES, UndecidedBox
from taut.model import save_robot

FK = ["fk", "suspended-3cable"]
IGP = ["igp", "suspended-3cable", "--taut", "3,1,2", "--fix", "x=2.7505,y=3.9798,z=5.5061"]

#: command, budget that leaves boxes undecided, the unknowns its boxes are named by
CUT = {
    "fk": (FK, "20", ("q1_x", "q1_y", "q1_z", "q2_x", "q2_y", "q2_z", "q3_x", "q3_y", "q3_z")),
    "igp": (IGP, "50", ("cos(a)", "sin(a)", "cos(b)", "sin(b)", "cos(c)", "sin(c)")),
}


def _warning(err: str) -> str:
    """The one line on stderr, a warning."""
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("taut: warning: "), err
    assert "may be incomplete" in lines[0]
    return lines[0]


def _named_subsets(line: str) -> set[tuple[int, ...]]:
    return {tuple(int(k) for k in m.split(",")) for m in re.findall(r"\{([\d,]+)\}", line)}


@pytest.mark.parametrize("command", sorted(CUT))
@pytest.mark.parametrize("strict", [False, True], ids=["plain", "strict"])
def test_a_search_cut_by_its_budget_says_where_it_is_incomplete(taut_cli, command, strict):
    argv, budget, unknowns = CUT[command]
    run = taut_cli(*argv, "--max-boxes", budget, "--json", *(["--strict"] if strict else []), timeout=300)
    assert run.code == (3 if strict else 0), run.err
    d = json.loads(run.out)  # printed with --strict too
    assert d["complete"] is False
    boxes = d["undecided_enclosures"]
    assert len(boxes) == d["undecided_boxes"] > 0
    for b in boxes:
        assert b["cause"] == "budget"
        assert set(b["taut"]) <= {1, 2, 3} and len(b["taut"]) >= 2  # 1-based cable numbers
        assert tuple(b["enclosure"])[: len(unknowns)] == unknowns
        bounds = [*b["enclosure"].values(), *b["tensions"]]
        assert all(lo is None or hi is None or lo <= hi for lo, hi in bounds)
        assert len(b["tensions"]) == len(b["taut"])
    line = _warning(run.err)
    assert _named_subsets(line) == {tuple(b["taut"]) for b in boxes}
    assert line.startswith(f"taut: warning: {len(boxes)} boxes could not be certified")


def test_the_warning_goes_to_stderr_without_json_too(taut_cli):
    run = taut_cli(*FK, "--max-boxes", "20", timeout=300)
    assert run.code == 0, run.err
    assert _named_subsets(_warning(run.err)) >= {(1, 2, 3)}
    assert "warning" not in run.out


@pytest.mark.parametrize(
    "argv",
    [[*FK, "--max-taut", "2"], IGP],
    ids=["fk", "igp"],
)
def test_a_complete_answer_has_no_warning_and_exits_0_under_strict(taut_cli, argv):
    run = taut_cli(*argv, "--strict", "--json", timeout=300)
    assert run.code == 0, run.err
    assert run.err.strip() == ""
    d = json.loads(run.out)
    assert d["complete"] is True and d["undecided_boxes"] == 0 and d["undecided_enclosures"] == []


@pytest.mark.parametrize("command", ["fk", "igp"])
def test_the_exit_statuses_are_in_the_help(taut_cli, command):
    run = taut_cli(command, "--help")
    assert run.code == 0
    text = " ".join(run.out.split())
    assert "Exit status: 0" in text and "2 bad input" in text and "3 the answer is incomplete and --strict" in text


def test_the_warning_names_a_dozen_sub_problems_then_counts_the_rest():
    """An 8-cable robot has 70 four-cable sub-problems: the line stays one readable line."""
    boxes = [UndecidedBox(t, "narrow", (), (), (), (), ()) for t in combinations(range(8), 4)]
    line = warning([*boxes, boxes[0]], "equilibria")
    assert "\n" not in line and line.startswith("taut: warning: 71 boxes could not be certified (71 too narrow")
    assert len(_named_subsets(line)) == NAMED and f"and {70 - NAMED} more" in line
    assert _named_subsets(line) == {tuple(k + 1 for k in b.taut) for b in boxes[:NAMED]}


def test_the_warning_counts_every_cause():
    boxes = [UndecidedBox((0, 1, 2), cause, (), (), (), (), ()) for cause in CAUSES for _ in range(2)]
    line = warning(boxes, "equilibria")
    assert line.startswith(f"taut: warning: {2 * len(CAUSES)} boxes could not be certified (")
    assert all(f"2 {CAUSE_TEXT[c]}" in line for c in CAUSES) and set(CAUSE_TEXT) == set(CAUSES)


def _fold_robot(tmp_path):
    """``taut fk`` on the suite robot at a fold (tests/fold_robot.py), saved to a file."""
    robot, lengths, _ = fold_robot()
    path = tmp_path / "seed0.yaml"
    save_robot(robot, path)
    return ["fk", str(path), "--lengths", ",".join(repr(float(x)) for x in lengths), "--max-taut", "3"]


@pytest.mark.slow
def test_nearly_double_equilibria_are_certified_through_the_cli(taut_cli, tmp_path):
    pytest.importorskip("flint")
    run = taut_cli(*_fold_robot(tmp_path), "--json", "--strict", timeout=300)
    assert run.code == 0 and not run.err.strip(), run.err
    d = json.loads(run.out)
    assert d["complete"] is True and d["undecided_enclosures"] == []
    assert sum(s["taut"] == [1, 2, 3] for s in d["solutions"]) == 6


@pytest.mark.slow
def test_without_python_flint_the_warning_says_how_to_search_narrow_boxes_again(tmp_path):
    """The same command where python-flint cannot be imported (as without the extra): the
    narrow boxes stay undecided, and the one warning line says how to install it."""
    hide = "import runpy, sys; sys.modules['flint'] = None; sys.argv[0] = 'taut'; runpy.run_module('taut', run_name='__main__')"
    proc = subprocess.run(
        [sys.executable, "-c", hide, *_fold_robot(tmp_path), "--json", "--strict"],
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert proc.returncode == 3, proc.stderr
    line = _warning(proc.stderr)
    assert "too narrow to split" in line and "pip install 'taut[precise]'" in line
    d = json.loads(proc.stdout)
    assert d["complete"] is False and {b["cause"] for b in d["undecided_enclosures"]} == {"narrow"}
