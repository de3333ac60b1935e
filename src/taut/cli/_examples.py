"""``taut examples``: the built-in example robots, by name, with their descriptions."""

from __future__ import annotations

import argparse

from taut.cli._output import print_json

SUMMARY = "list the built-in example robots"
ROBOT = False


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """``taut examples`` takes no option but ``--json``."""


def run(ns: argparse.Namespace) -> int:
    from taut.model import example_descriptions

    desc = example_descriptions()
    if ns.json:
        print_json({"examples": [{"name": k, "description": v} for k, v in desc.items()]})
    else:
        width = max(map(len, desc))
        for k, v in desc.items():
            print(f"{k:<{width}}  {v}")
    return 0
