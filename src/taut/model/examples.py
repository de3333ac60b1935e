"""Built-in example robots, shipped as YAML files in ``taut/examples/`` and addressable
by name wherever a ROBOT is expected."""

from __future__ import annotations

from functools import cache
from importlib import resources
from importlib.resources.abc import Traversable

from taut.errors import RobotFileError
from taut.model.robot import Robot


def _files() -> Traversable:
    return resources.files("taut") / "examples"


@cache
def example_names() -> tuple[str, ...]:
    """Names of the built-in examples, sorted."""
    return tuple(sorted(f.name[:-5] for f in _files().iterdir() if f.name.endswith(".yaml")))


def example(name: str) -> Robot:
    """A fresh copy of the built-in example ``name``."""
    from taut.model.io import parse_robot

    if name not in example_names():
        raise RobotFileError(f"{name}: not a built-in example; expected one of {', '.join(example_names())}")
    return parse_robot((_files() / f"{name}.yaml").read_text(encoding="utf-8"), f"example {name}")


def example_descriptions() -> dict[str, str]:
    """One line per example: its description."""
    return {n: (example(n).description or example(n).name).strip().splitlines()[0] for n in example_names()}
