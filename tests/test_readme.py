"""Every example of the README runs: python blocks are executed, console lines are run
through the CLI entry point and must succeed."""

import re
import shlex
from pathlib import Path

import pytest

from taut.cli.main import main

README = (Path(__file__).parents[1] / "README.md").read_text()
PYTHON = re.findall(r"```python\n(.*?)```", README, re.S)
CONSOLE = [
    line[2:]
    for block in re.findall(r"```console\n(.*?)```", README, re.S)
    for line in block.splitlines()
    if line.startswith("$ ")
]


def test_readme_has_the_two_setup_commands():
    setup = re.search(r"```sh\n(.*?)```", README, re.S).group(1)
    assert [line.split()[0:2] for line in setup.splitlines()] == [["make", "demo"], ["make", "test"]]


@pytest.mark.parametrize("code", PYTHON, ids=[f"python-{i}" for i in range(len(PYTHON))])
def test_python_blocks(code, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "README.md", "exec"), {})


@pytest.mark.parametrize("line", CONSOLE)
def test_console_lines(line, capsys):
    argv = shlex.split(line)
    assert argv[0] == "taut"
    assert main(argv[1:]) == 0, capsys.readouterr().err
    assert capsys.readouterr().out.strip()
