"""``taut demo``: run taut on the built-in robots and write an HTML report (:mod:`taut.demo`)."""

from __future__ import annotations

import argparse
from pathlib import Path

from taut.cli._output import print_json
from taut.errors import TautError

SUMMARY = "run taut on the built-in robots and write an HTML report"
ROBOT = False


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--out", default="report", help="report directory (default: report)")


def run(ns: argparse.Namespace) -> int:
    from taut.demo import run_demo

    out = Path(ns.out)
    if out.exists() and not out.is_dir():
        raise TautError(f"--out: {ns.out!r} is a file; give a directory for the report")
    if not out.parent.is_dir():
        raise TautError(f"--out: the directory {str(out.parent)!r} does not exist")
    path = run_demo(out)
    if ns.json:
        print_json({"report": str(path)})
    else:
        print(f"report written to {path}")
    return 0
