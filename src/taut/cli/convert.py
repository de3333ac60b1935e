"""``taut convert IN OUT``: write a robot in the format the name of OUT selects
(:mod:`taut.model._formats`: taut YAML/JSON, a CASPR ``X_bodies.xml`` pair, ...)."""

from __future__ import annotations

import argparse

from taut.cli.main import Command, console, emit, load


def cmd_convert(ns: argparse.Namespace) -> int:
    from taut.model import format_of, write_robot

    format_of(ns.out, kind="write")  # an unknown OUT is refused before IN is read
    robot = load(ns.robot, ns.cable_set)
    fmt = write_robot(robot, ns.out)
    data = {"in": ns.robot, "out": ns.out, "format": fmt, "robot": robot.name}
    emit(data, ns.json, lambda d: console().print(f"{d['in']} -> {d['out']} ({d['format']})"))
    return 0


def register(command: Command) -> None:
    c = command("convert", "write a robot in another file format (chosen by the name of OUT)", cmd_convert)
    c.add_argument("out", metavar="OUT", help="output file: *.yaml, *.yml, *.json (taut) or X_bodies.xml (CASPR)")
