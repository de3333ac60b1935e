"""``taut schema``: the JSON Schema of the robot file format (``docs/architecture.md`` §3)."""

from __future__ import annotations

import argparse
import sys

SUMMARY = "print the JSON Schema of the robot file format"
ROBOT = False


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """``taut schema`` takes no option (``--json`` changes nothing: the schema is JSON)."""


def run(ns: argparse.Namespace) -> int:
    from taut.model import schema_text

    sys.stdout.write(schema_text())
    return 0
