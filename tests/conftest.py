"""The command line as users run it: ``python -m taut ...`` in a real subprocess, with a
time limit and an address-space limit so that a hang or a runaway allocation fails the
test instead of the machine."""

from __future__ import annotations

import json
import resource
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

import pytest

#: Address-space limit of a CLI subprocess: far above what any command needs on the test
#: inputs, far below what the historical runaway allocations reached.
MEMORY_LIMIT = 4 << 30


def _limit_memory() -> None:
    resource.setrlimit(resource.RLIMIT_AS, (MEMORY_LIMIT, MEMORY_LIMIT))


@dataclass(frozen=True)
class Run:
    """Exit status and the two output streams of one ``taut`` process."""

    code: int
    out: str
    err: str

    def json(self) -> dict:
        """The JSON document on stdout of a successful run (stdout holds nothing else)."""
        assert self.code == 0, self.err
        return json.loads(self.out)


def run_taut(*argv: str, timeout: float = 600, cwd: Path | None = None, stdin: str | None = None) -> Run:
    proc = subprocess.run(
        [sys.executable, "-m", "taut", *argv],
        capture_output=True,
        text=True,
        timeout=timeout,
        cwd=cwd,
        input=stdin,
        preexec_fn=_limit_memory,
    )
    return Run(proc.returncode, proc.stdout, proc.stderr)


@pytest.fixture
def taut_cli() -> Callable[..., Run]:
    """``taut_cli("ik", "planar-4cable", "--json")`` runs ``python -m taut ...`` and returns a :class:`Run`."""
    return run_taut


class Output(NamedTuple):
    out: str
    err: str


class Session:
    """Commands run one after another in subprocesses: ``main(argv)`` returns the exit status
    and ``readouterr()`` the last command's ``(out, err)``, as pytest's ``capsys`` would."""

    def __init__(self) -> None:
        self.last = Run(0, "", "")

    def main(self, argv: list[str]) -> int:
        self.last = run_taut(*argv)
        return self.last.code

    def readouterr(self) -> Output:
        return Output(self.last.out, self.last.err)


@pytest.fixture
def cli() -> Session:
    """``cli.main([...])`` then ``cli.readouterr()``: :class:`Session`."""
    return Session()
