"""taut: a toolkit for cable-driven parallel robots.

Layers (``docs/architecture.md`` §1): ``model`` → ``kinematics`` → ``statics`` → ``workspace``
→ ``viz`` / ``cli``.  The names most users need are re-exported here.
"""

from taut.errors import (
    InfeasiblePoseError,
    PoseError,
    RobotFileError,
    SingularConfigurationError,
    TautError,
    UnreachableLengthsError,
)
from taut.model import Robot, example, example_names, load_robot, save_robot

__version__ = "0.1.0"

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
