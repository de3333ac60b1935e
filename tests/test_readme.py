"""Every example of the README and of docs/ runs: python blocks are executed, console lines
are run as the user runs them (a real ``taut`` process) and must succeed, and YAML blocks are
robot files that validate."""

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

from taut.model import parse_robot

ROOT = Path(__file__).parents[1]
README = (ROOT / "README.md").read_text()
DOCS = README + "".join(p.read_text() for p in sorted((ROOT / "docs").glob("*.md")))
PYTHON = re.findall(r"```python\n(.*?)```", DOCS, re.S)
YAML = re.findall(r"```yaml\n(.*?)```", DOCS, re.S)
CONSOLE = [
    line[2:]
    for block in re.findall(r"```console\n(.*?)```", DOCS, re.S)
    for line in block.splitlines()
    if line.startswith("$ ")
]


def test_readme_has_the_two_setup_commands():
    setup = re.search(r"```sh\n(.*?)```", README, re.S).group(1)
    assert [line.split()[0:2] for line in setup.splitlines()] == [["make", "demo"], ["make", "test"]]


#: Blocks that compile the control loop's or the all-solutions search's kernels from cold (half
#: a minute each on a fresh clone) run with the slow suite of ``make check``, so that
#: ``make test`` stays under five minutes.
HEAVY = ("simulate_control(", "solve_igp(")


@pytest.mark.parametrize(
    "code",
    [pytest.param(c, marks=pytest.mark.slow) if any(h in c for h in HEAVY) else c for c in PYTHON],
    ids=[f"python-{i}" for i in range(len(PYTHON))],
)
def test_python_blocks(code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})


@pytest.mark.parametrize("line", CONSOLE)
def test_console_lines(line, tmp_path):
    argv = shlex.split(line)
    assert argv[0] == "taut"
    # a line reading a file of the repository runs from a clone's root, as the README says
    cwd = ROOT if "tests/" in line else tmp_path
    done = subprocess.run(
        [sys.executable, "-m", "taut", *argv[1:]], capture_output=True, text=True, cwd=cwd, timeout=600
    )
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip()
    assert "Traceback" not in done.stderr


@pytest.mark.parametrize("text", YAML, ids=[f"yaml-{i}" for i in range(len(YAML))])
def test_yaml_blocks_are_valid_robot_files(text):
    robot = parse_robot(text, source="README")
    assert robot.n_cables == text.count("- {exit:")
