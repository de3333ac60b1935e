"""The command line as users run it: ``python -m taut ...`` in a real subprocess, with a
time limit and an address-space limit so that a hang or a runaway allocation fails the
test instead of the machine."""

from __future__ import annotations

import json
import os
import pty
import resource
import subprocess
import sys
import threading
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


@dataclass(frozen=True)
class TerminalRun(Run):
    """A run with stderr on a terminal: ``err`` is all the terminal received."""

    @property
    def drew_a_bar(self) -> bool:
        """Whether rich drew a live progress bar (it hides the cursor, then draws ``━``)."""
        return "\x1b[?25l" in self.err and "━" in self.err


def run_with_terminal_stderr(*argv: str) -> TerminalRun:
    """Run ``taut ARGV`` with stderr on a pseudo-terminal (so that progress bars are drawn)
    and stdout on a pipe: ``err`` is everything written to the terminal."""
    master, slave = pty.openpty()
    env = {k: v for k, v in os.environ.items() if k not in ("TTY_INTERACTIVE", "NO_COLOR")}
    env["TERM"] = "xterm-256color"
    proc = subprocess.Popen(
        [sys.executable, "-m", "taut", *argv],
        stdin=subprocess.DEVNULL,
        stdout=subprocess.PIPE,
        stderr=slave,
        env=env,
        preexec_fn=_limit_memory,
    )
    os.close(slave)
    chunks: list[bytes] = []

    def drain() -> None:  # a full pty buffer would block the child
        while True:
            try:
                data = os.read(master, 4096)
            except OSError:  # EIO: the child closed the terminal
                return
            if not data:
                return
            chunks.append(data)

    reader = threading.Thread(target=drain)
    reader.start()
    out, _ = proc.communicate(timeout=600)
    reader.join(timeout=60)
    os.close(master)
    return TerminalRun(proc.returncode, out.decode(), b"".join(chunks).decode(errors="replace"))


@pytest.fixture
def terminal_cli() -> Callable[..., TerminalRun]:
    """``terminal_cli("fk", "suspended-3cable")``: :func:`run_with_terminal_stderr`."""
    return run_with_terminal_stderr


@pytest.fixture(scope="session")
def robot_2000_cables():
    """A planar rigid platform hung from 2000 exits round a circle of radius 2, anchored round
    a circle of radius 0.1 a quarter turn ahead: 2 million capsule pairs, a 3 × 2000 ``W``."""
    import numpy as np

    from taut.model import robot_from_dict

    angles = np.linspace(0.0, 2 * np.pi, 2000, endpoint=False).tolist()
    cables = [
        {"exit": [2 * np.cos(a), 2 * np.sin(a)], "anchor": [0.1 * np.cos(a + 1.5), 0.1 * np.sin(a + 1.5)]}
        for a in angles
    ]
    return robot_from_dict({"name": "2000 cables", "dimension": 2, "platform": {"kind": "rigid"}, "cables": cables})
