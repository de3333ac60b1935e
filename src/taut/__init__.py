"""taut: a toolkit for cable-driven parallel robots.

Layers (``docs/architecture.md`` §1): ``model`` → ``kinematics`` → ``statics`` → ``workspace``
→ ``viz`` / ``cli``.  The names most users need are re-exported here.
"""

from __future__ import annotations

from importlib import import_module
from typing import TYPE_CHECKING

from taut.errors import (
    InfeasiblePoseError,
    PoseError,
    RobotFileError,
    SingularConfigurationError,
    TautError,
    UnreachableLengthsError,
)

if TYPE_CHECKING:
    from taut.model import Robot, example, example_names, load_robot, save_robot

__version__ = "0.1.0"

#: The model's names are imported on first use (PEP 562): ``import taut`` (and so every
#: ``taut`` command) does not build the pydantic models until one needs a robot.
_LAZY = dict.fromkeys(["Robot", "example", "example_names", "load_robot", "save_robot"], "taut.model")


def __getattr__(name: str) -> object:
    if name not in _LAZY:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(import_module(_LAZY[name]), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))


__all__ = [
    "InfeasiblePoseError",
    "PoseError",
    "Robot",
    "RobotFileError",
    "SingularConfigurationError",
    "TautError",
    "UnreachableLengthsError",
    "example",
    "example_names",
    "load_robot",
    "save_robot",
]
