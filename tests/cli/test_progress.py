"""Long commands say what they are doing: a progress bar with an estimate on a terminal, and
with ``--json`` nothing on stderr and the result alone on stdout (real subprocesses, stderr
on a pseudo-terminal)."""

import json
import re

import pytest

from taut.model import save_robot

#: What rich's default columns show after the bar: the percentage and the time remaining.
ESTIMATE = re.compile(r"\d+%.*?(\d+:\d\d:\d\d|-:--:--)")


@pytest.mark.slow
def test_atlas_shows_its_charts_being_built_and_decided(terminal_cli):
    run = terminal_cli("atlas", "vscr-single-cable")
    assert run.code == 0, run.err
    assert run.drew_a_bar and "atlas (charts expanded)" in run.err and "workspace (charts)" in run.err
    assert "44 charts" in run.out and "\x1b" not in run.out
    run = terminal_cli("atlas", "vscr-single-cable", "--json")
    assert run.code == 0 and run.err == ""
    assert json.loads(run.out)["charts"] == 44


@pytest.mark.slow
def test_workspace_of_2000_cables_shows_progress_and_an_estimate(terminal_cli, robot_2000_cables, tmp_path):
    """2 million capsule pairs a pose: one pose a chunk, each reported, within the memory
    limit of the test processes."""
    path = tmp_path / "many.yaml"
    save_robot(robot_2000_cables, path)
    run = terminal_cli("workspace", str(path), "--condition", "interference-free", "--grid", "2")
    assert run.code == 0, run.err
    assert run.drew_a_bar and "workspace" in run.err and ESTIMATE.search(run.err), run.err
    assert "of 4 poses inside" in run.out and "\x1b" not in run.out
    run = terminal_cli("workspace", str(path), "--condition", "static", "--grid", "5", "--json")
    assert run.code == 0 and run.err == ""
    data = json.loads(run.out)
    assert data["poses"] == 25 and data["robot"] == "2000 cables"
