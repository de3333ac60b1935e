"""taut: a toolkit for cable-driven parallel robots.

Layers (``docs/architecture.md`` §1): ``model`` → ``kinematics`` → ``statics`` → ``workspace``
→ ``viz`` / ``cli``.  The names most users need are re-exported here.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports
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

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
