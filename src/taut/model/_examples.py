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
    """Names of the built-in example robots, sorted.

    Returns
    -------
    tuple of str

    Examples
    --------
    >>> "planar-4cable" in example_names()
    True
    """
    return tuple(sorted(f.name[:-5] for f in _files().iterdir() if f.name.endswith(".yaml")))


def example(name: str) -> Robot:
    """A fresh copy of the built-in example robot ``name`` (``taut examples`` lists them).

    Parameters
    ----------
    name : str
        One of :func:`example_names`.

    Returns
    -------
    Robot

    Raises
    ------
    RobotFileError
        For a name that is not a built-in example.

    Examples
    --------
    >>> robot = example("planar-4cable")
    >>> robot.n_cables, robot.pose_names
    (4, ['x', 'y', 'theta'])
    """
    from taut.model._io import parse_robot

    if name not in example_names():
        raise RobotFileError(f"{name}: not a built-in example; expected one of {', '.join(example_names())}")
    return parse_robot((_files() / f"{name}.yaml").read_text(encoding="utf-8"), source=f"example {name}")


def example_descriptions() -> dict[str, str]:
    """One line per built-in example: the first line of its ``description`` (its name when it has
    none), read from the YAML alone (listing the examples does not validate every robot).

    Returns
    -------
    dict of str to str

    Examples
    --------
    >>> example_descriptions()["planar-4cable"]
    'Fully-constrained planar robot, rigid 0.2 m x 0.1 m platform, 4 cables from the corners of a 2 m square frame.'
    """
    import yaml

    loader = getattr(yaml, "CSafeLoader", yaml.SafeLoader)
    out = {}
    for n in example_names():
        data = yaml.load((_files() / f"{n}.yaml").read_text(encoding="utf-8"), Loader=loader)
        out[n] = str(data.get("description") or data["name"]).strip().splitlines()[0]
    return out
