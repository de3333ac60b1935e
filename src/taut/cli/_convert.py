"""``taut convert IN OUT``: write a robot in the format the name of OUT selects
(:data:`taut.model._formats.FORMATS`: taut YAML/JSON, a CASPR ``X_bodies.xml`` pair, ...)."""

from __future__ import annotations

import argparse
from pathlib import Path

from taut.cli import _args as A
from taut.cli._output import check_writable, console, emit, markup
from taut.model import FORMATS

SUMMARY = "write a robot in another file format (chosen by the name of OUT)"
ROBOT = True


def _out_help() -> str:
    """The names OUT may have, from the format table (so that the help cannot drift from it)."""
    kinds = [f"{', '.join(f.patterns)} ({f.name})" for f in FORMATS if f.writer is not None]
    return "output file; its name selects the format: " + "; ".join(kinds)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("out", metavar="OUT", help=_out_help().replace("%", "%%"))


def run(ns: argparse.Namespace) -> int:
    from taut.model import format_of, write_robot

    format_of(ns.out, "write")  # an unknown OUT is refused before IN is read
    check_writable(Path(ns.out), "OUT")
    robot = A.load(ns.robot, ns.cable_set)
    fmt = write_robot(robot, ns.out)
    data = {"in": ns.robot, "out": ns.out, "format": fmt, "robot": robot.name}
    emit(data, ns.json, lambda d: console().print(markup(f"{d['in']} -> {d['out']} ({d['format']})")))
    return 0
