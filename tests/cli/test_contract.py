"""The command line's contract (``docs/architecture.md`` §4.1) where it used to break: bad
option values, output files that cannot be written, files written in part, FIFOs, several
lines on stderr, the magnitude limit, tables cut short, help that drifted from the format
table, Ctrl-C.  Every case runs ``python -m taut`` in a real subprocess."""

from __future__ import annotations

import ast
import json
import os
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import NamedTuple

import numpy as np
import pytest
import yaml

import taut
import taut.cli
from taut.model import robot_to_dict

#: Seconds one refusal may take: far beyond the second or two of a refusal, far below a hang.
TIMEOUT = 120

SIMULATE = ["simulate", "spatial-8cable", "--waypoints", "0,0,0;0.1,0,0", "--duration", "1"]
PLAN = ["plan", "robocrane", "--start", "q3", "--goal", "q4", "--fix", "x=0,y=0,z=2,sigma=35deg"]


class Run(NamedTuple):
    """Exit status and the two output streams of one ``taut`` process."""

    code: int
    out: str
    err: str

    def json(self) -> dict:
        assert self.code == 0, self.err
        return json.loads(self.out)


def refused(run: Run, *words: str) -> None:
    """Exit status 2, nothing on stdout, and exactly one line on stderr: ``taut: error: ...``
    holding ``words``."""
    assert run.code == 2, (run.code, run.out[:300], run.err[-2000:])
    assert run.out == ""
    lines = run.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("taut: error: "), run.err
    assert "internal error" not in run.err
    for w in words:
        assert w in lines[0], (w, run.err)


def taut_run(*argv: str, cwd: Path | None = None, file_size: int | None = None, timeout: float = TIMEOUT) -> Run:
    """``python -m taut ARGV``; with ``file_size``, no file the process writes may grow beyond
    that many bytes (a full disk, as far as the process can tell: the write fails with EFBIG)."""

    def limits() -> None:
        resource.setrlimit(resource.RLIMIT_AS, (4 << 30, 4 << 30))
        if file_size is not None:
            signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
            resource.setrlimit(resource.RLIMIT_FSIZE, (file_size, file_size))

    proc = subprocess.run(
        [sys.executable, "-m", "taut", *argv],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=cwd,
        preexec_fn=limits,
        env=os.environ | {"PYTHONDONTWRITEBYTECODE": "1"},
    )
    return Run(proc.returncode, proc.stdout, proc.stderr)


# ---- 1. one command table ----------------------------------------------------------------


def _command_modules() -> set[str]:
    """The modules of taut.cli that define a command's ``run``."""
    root = Path(taut.cli.__file__).parent
    out = set()
    for path in root.glob("*.py"):
        tree = ast.parse(path.read_text())
        if any(isinstance(n, ast.FunctionDef) and n.name == "run" for n in tree.body):
            out.add(path.stem)
    return out


def test_every_command_is_in_the_table_and_none_imports_main():
    from taut.cli._main import COMMANDS

    assert {module.__name__.rsplit(".", 1)[1] for _, module in COMMANDS} == _command_modules()
    root = Path(taut.cli.__file__).parent
    for path in root.glob("*.py"):
        if path.name in ("__init__.py", "_main.py"):  # the package exports main; _main is the table
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            names = (
                [node.module or ""]
                if isinstance(node, ast.ImportFrom)
                else [a.name for a in node.names]
                if isinstance(node, ast.Import)
                else []
            )
            assert "taut.cli._main" not in names, f"{path.name} imports taut.cli._main"
    run = taut_run("--help")
    assert run.code == 0
    listed = run.out.split("{", 1)[1].split("}", 1)[0].split(",")
    assert listed == [name for name, _ in COMMANDS]


# ---- 2. bad option values are refused as the command line is parsed ------------------------

BAD_OPTIONS = [
    ([*PLAN, "--planner=atlasrrt", "--seed=-1"], "--seed"),
    ([*PLAN, "--seed=4294967296"], "--seed"),
    (["fk", "suspended-3cable", "--max-boxes=9223372036854775808", "--strict", "--json"], "--max-boxes"),
    (["fk", "suspended-3cable", "--max-boxes=1e30"], "--max-boxes"),
    (["fk", "suspended-3cable", "--max-taut=0"], "--max-taut"),
    (["fk", "suspended-3cable", "--workers=0"], "--workers"),
    (["igp", "suspended-3cable", "--taut", "1,2,3", "--fix", "x=1,y=1,z=1", "--max-boxes=-5"], "--max-boxes"),
    ([*PLAN, "--max-charts=1"], "--max-charts"),
    ([*PLAN, "--subdivide=0"], "--subdivide"),
    ([*PLAN, "--max-nodes=1"], "--max-nodes"),
    ([*PLAN, "--radius=nan"], "--radius"),
    ([*PLAN, "--step=0"], "--step"),
    ([*SIMULATE, "--kp="], "--kp"),
    ([*SIMULATE, "--kd="], "--kd"),
    ([*SIMULATE, "--substeps=0"], "--substeps"),
    ([*SIMULATE, "--substeps=1001"], "--substeps"),
    ([*SIMULATE, "--rate=inf"], "--rate"),
    ([*SIMULATE, "--sample-rate=0"], "--sample-rate"),
    ([*SIMULATE, "--mass-error=1"], "--mass-error"),
    (["simulate", "spatial-8cable", "--waypoints", "0,0,0;0.1,0,0", "--duration=nan"], "--duration"),
    (["trajectory", "vscr-single-cable", "--dt=0"], "--dt"),
    (["trajectory", "vscr-single-cable", "--speed=-1"], "--speed"),
    (["trajectory", "vscr-single-cable", "--dwell=nan"], "--dwell"),
    (["atlas", "vscr-single-cable", "--theta=x"], "--theta"),
    (["workspace", "planar-4cable", "--condition", "static", "--grid", "9" * 5000], "--grid"),
]


@pytest.mark.parametrize(("argv", "option"), BAD_OPTIONS, ids=[f"{o}-{i}" for i, (_, o) in enumerate(BAD_OPTIONS)])
def test_bad_option_values_exit_2_on_one_line(argv, option):
    refused(taut_run(*argv), option)


@pytest.mark.slow
def test_the_largest_box_budget_is_taken():
    """The bound of ``--max-boxes`` is what the kernels take: at it, fk answers as by default."""
    default = taut_run("fk", "suspended-3cable", "--json")
    largest = taut_run("fk", "suspended-3cable", f"--max-boxes={2**63 - 1}", "--json")
    assert [s["position"] for s in largest.json()["solutions"]] == [s["position"] for s in default.json()["solutions"]]


# ---- 3, 5. outputs that cannot be written: refused before anything is computed --------------


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        ([*SIMULATE, "--out", "{tmp}/fifo.csv"], ("--out", "not a regular file")),
        (["convert", "spatial-8cable", "{tmp}/fifo.yaml"], ("fifo.yaml", "not a regular file")),
        (["ik", "planar-4cable", "--plot", "{tmp}/fifo.png"], ("--plot", "not a regular file")),
        (["trajectory", "vscr-single-cable", "--out", "/dev/full"], ("--out", "not a regular file")),
        ([*PLAN, "--out", "/dev/full"], ("--out", "not a regular file")),
        (["atlas", "vscr-single-cable", "--out", "{tmp}/dir.json"], ("--out", "directory")),
        (["workspace", "planar-4cable", "--condition", "static", "--out", "{tmp}/dir.npz"], ("--out", "directory")),
        ([*SIMULATE, "--out", "{tmp}/no/s.csv"], ("--out", "does not exist")),
        (["convert", "spatial-8cable", "{tmp}/dangling.yaml"], ("dangling.yaml",)),
    ],
    ids=["simulate-fifo", "convert-fifo", "plot-fifo", "dev-full", "plan-dev-full", "dir", "npz-dir", "no-dir", "link"],
)
def test_unwritable_outputs_are_refused_without_blocking(tmp_path, argv, words):
    for name in ("fifo.csv", "fifo.yaml", "fifo.png"):
        os.mkfifo(tmp_path / name)
    (tmp_path / "dir.json").mkdir()
    (tmp_path / "dir.npz").mkdir()
    (tmp_path / "dangling.yaml").symlink_to(tmp_path / "nowhere" / "r.yaml")
    before = sorted(p.name for p in tmp_path.iterdir())
    refused(taut_run(*(a.format(tmp=tmp_path) for a in argv)), *words)
    assert sorted(p.name for p in tmp_path.iterdir()) == before


# ---- 3. a write that fails after the computation: one line, exit 2, the old file kept --------


@pytest.mark.slow
@pytest.mark.parametrize(
    ("argv", "name"),
    [
        ([*SIMULATE, "--out", "{out}"], "s.csv"),
        (["workspace", "planar-4cable", "--condition", "static", "--grid", "40", "--out", "{out}"], "w.npz"),
        (["ik", "spatial-8cable", "--plot", "{out}"], "p.png"),
        (["trajectory", "vscr-single-cable", "--out", "{out}"], "t.csv"),
        (["convert", "spatial-8cable", "{out}"], "r.json"),
    ],
    ids=["simulate", "workspace", "ik-plot", "trajectory", "convert"],
)
def test_a_full_disk_after_computing_is_one_line_and_leaves_the_file_whole(tmp_path, argv, name):
    out = tmp_path / name
    args = [a.format(out=out) for a in argv]
    first = taut_run(*args, "--json")  # also compiles and caches every kernel the command needs
    assert first.code == 0, first.err
    whole = out.read_bytes()
    assert len(whole) > 1000
    run = taut_run(*args, "--json", file_size=len(whole) // 2)
    refused(run, "cannot write", "File too large")
    assert out.read_bytes() == whole
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


# ---- 4. a model of two files is written whole or not at all ---------------------------------


@pytest.mark.parametrize("companion", ["directory", "dangling link", "full disk"])
def test_convert_writes_both_caspr_files_or_neither(tmp_path, companion):
    cables = tmp_path / "q_cables.xml"
    file_size = None
    if companion == "directory":
        cables.mkdir()
    elif companion == "dangling link":
        cables.symlink_to(tmp_path / "nowhere" / "c.xml")
    else:
        whole = tmp_path / "whole"
        whole.mkdir()
        assert taut_run("convert", "spatial-8cable", str(whole / "q_bodies.xml")).code == 0
        sizes = sorted(p.stat().st_size for p in whole.iterdir())
        file_size = (sizes[0] + sizes[1]) // 2  # the smaller file fits, the larger does not
        assert sizes[0] < file_size < sizes[1]
    before = sorted(p.name for p in tmp_path.iterdir())
    run = taut_run("convert", "spatial-8cable", str(tmp_path / "q_bodies.xml"), file_size=file_size)
    refused(run, "q_")
    assert sorted(p.name for p in tmp_path.iterdir()) == before


def test_an_output_name_that_is_only_an_extension_is_refused(tmp_path):
    refused(taut_run("convert", "spatial-8cable", str(tmp_path / ".yaml")), ".yaml", "name")
    refused(taut_run("convert", "spatial-8cable", str(tmp_path / "_bodies.xml")), "name")
    assert not any(tmp_path.iterdir())


# ---- 6. one line on stderr ----------------------------------------------------------------


def _robot_file(tmp_path: Path, edit) -> str:
    data = json.loads(json.dumps(robot_to_dict(taut.example("suspended-3cable")), default=float))
    edit(data)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(data))
    return str(path)


def test_a_robot_file_with_every_cable_bad_names_the_first_in_one_line(tmp_path):
    path = _robot_file(tmp_path, lambda d: [c.update(exit=[0, "x", 0]) for c in d["cables"]])
    run = taut_run("ik", path)
    refused(run, "cables[1].exit[2]", "2 more problems")
    assert "at least 1 item" not in run.err


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (["fk"], ("robot", "taut fk --help")),
        (["frobnicate"], ("frobnicate",)),
        (["workspace", "planar-4cable"], ("--condition",)),
        (["ik", "planar-4cable", "--nonsense"], ("--nonsense",)),
        ([], ("command",)),
    ],
)
def test_argparse_refusals_are_one_line(argv, words):
    refused(taut_run(*argv), *words)


@pytest.mark.parametrize("scheme", ["udp", "tls", "inproc", "ucx"])
def test_a_scheduler_the_command_line_cannot_reach_is_refused_in_one_line(scheme):
    run = taut_run("fk", "suspended-3cable", "--scheduler", f"{scheme}://127.0.0.1:1", "--json")
    refused(run, "--scheduler", "tcp://HOST:PORT")


# ---- 7. one magnitude limit --------------------------------------------------------------


@pytest.mark.slow
def test_robot_files_options_and_poses_share_one_magnitude_limit(tmp_path):
    """A number is refused beyond the same limit, with the same words, wherever it is written;
    at the limit, a robot file loads."""
    limit = "up to 1e+09"
    far = _robot_file(tmp_path, lambda d: d["cables"][0].update(exit=[1.5e9, 0, 0]))
    refused(taut_run("ik", far), "cables[1].exit[1]", limit)
    heavy = _robot_file(tmp_path, lambda d: d["platform"].update(wrench=[0, 0, -5e11, 0, 0, 0]))
    refused(taut_run("tensions", heavy), "platform.wrench", limit)
    refused(taut_run("tensions", "planar-4cable", "--wrench", "0,5e11,0"), "--wrench", limit)
    refused(taut_run("ik", "planar-4cable", "--pose=1.5e9,0,0"), "--pose", limit)
    at = _robot_file(tmp_path, lambda d: d["cables"][0].update(exit=[1e9, 0, 0]))
    assert taut_run("ik", at, "--json").code == 0


# ---- 8. tables at full width -------------------------------------------------------------


def test_ik_tables_hold_every_digit_through_a_pipe():
    data = taut_run("ik", "spatial-8cable", "--pose", "0.1,0,0.2,0.1,-0.1,0.2", "--json").json()
    run = taut_run("ik", "spatial-8cable", "--pose", "0.1,0,0.2,0.1,-0.1,0.2")
    assert run.code == 0 and run.err == ""
    assert "length [m]" in run.out and "…" not in run.out
    cells = [[c.strip() for c in ln.split("│")[1:-1]] for ln in run.out.splitlines() if ln.startswith("│")]
    lengths = [[f"{i + 1}", f"{v:.6g}"] for i, v in enumerate(data["lengths"])]
    assert [row[:2] for row in cells[:8]] == lengths
    W = np.array(data["structure_matrix"])
    assert cells[8:] == [[f"{x:.4g}" for x in row] for row in W]


def test_brackets_in_a_robot_name_are_printed_not_read_as_styles(tmp_path):
    path = _robot_file(tmp_path, lambda d: d.update(name="[/x] bot [m]"))
    run = taut_run("ik", path)
    assert run.code == 0, run.err
    assert run.out.splitlines()[0].startswith("[/x] bot [m] at pose")


# ---- 9. help from the format table -------------------------------------------------------


def test_convert_help_names_every_format_written():
    run = taut_run("convert", "--help")
    assert run.code == 0
    text = " ".join(run.out.split())
    for pattern in ("*.yaml", "*.yml", "*.json", "*_bodies.xml", "*.wcrfx", "*.mjcf.xml"):
        assert pattern in text, pattern


# ---- 10. Ctrl-C --------------------------------------------------------------------------


@pytest.mark.slow
def test_ctrl_c_exits_130_with_one_line():
    proc = subprocess.Popen(
        [sys.executable, "-m", "taut", "workspace", "spatial-8cable", "--condition", "wrench-closure"]
        + ["--grid", "100", "--json"],  # about 7 s: the signal lands mid-run, not in the exit
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    time.sleep(2)
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=TIMEOUT)
    assert proc.returncode == 130, err
    assert out == "" and err.splitlines() == ["taut: interrupted"]
