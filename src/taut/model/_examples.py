"""Built-in example robots, shipped as YAML files in ``taut/examples/`` and addressable
by name wherever a ROBOT is expected."""

from __future__ import annotations

from functools import cache
from importlib import resources
from importlib.resources.abc import Traversable
from typing import TYPE_CHECKING

from taut.errors import RobotFileError

if TYPE_CHECKING:
    from taut.model._robot import Robot


def _files() -> Traversable:
    return resources.files("taut") / "examples"


@cache
def example_names() -> tuple[str, ...]:
    """Names of the built-in examples, sorted."""
    return tuple(sorted(f.name[:-5] for f in _files().iterdir() if f.name.endswith(".yaml")))


def example(name: str) -> Robot:
    """A fresh copy of the built-in example ``name``."""
    from taut.model._io import parse_robot

    if name not in example_names():
        raise RobotFileError(f"{name}: not a built-in example; expected one of {', '.join(example_names())}")
    return parse_robot((_files() / f"{name}.yaml").read_text(encoding="utf-8"), source=f"example {name}")


def example_descriptions() -> dict[str, str]:
    """One line per example: the first line of its description (its name when it has none).

    Read from the YAML alone: listing the examples does not validate every robot."""
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    out = {}
    for n in example_names():
        data = yaml.load((_files() / f"{n}.yaml").read_text(encoding="utf-8"), Loader=loader)
        out[n] = str(data.get("description") or data["name"]).strip().splitlines()[0]
    return out
