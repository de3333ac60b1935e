"""Robot descriptions: data classes, files, validation, built-in examples (``docs/architecture.md`` §3)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports
from taut.model._examples import example, example_descriptions, example_names

if TYPE_CHECKING:
    from taut.model._io import load_robot, parse_robot, robot_from_dict, robot_to_dict, save_robot
    from taut.model._mjcf import mjcf_text, pose_to_qpos, write_mjcf
    from taut.model._robot import (
        Body,
        Cable,
        Capsule,
        Circle,
        Joint,
        Platform,
        Polygon,
        Pulley,
        Reference,
        Robot,
        Shape,
        SwivelPulley,
        Trajectory,
    )
    from taut.model._schema import robot_schema

#: Names re-exported from the modules that load pydantic and PyYAML: imported on first use
#: (PEP 562), so that listing the examples does not build the pydantic models.
_LAZY = {
    **dict.fromkeys(["load_robot", "parse_robot", "robot_from_dict", "robot_to_dict", "save_robot"], "taut.model._io"),
    **dict.fromkeys(
        [
            "Body",
            "Cable",
            "Capsule",
            "Circle",
            "Joint",
            "Platform",
            "Polygon",
            "Pulley",
            "Reference",
            "Robot",
            "Shape",
            "SwivelPulley",
            "Trajectory",
        ],
        "taut.model._robot",
    ),
    "robot_schema": "taut.model._schema",
    **dict.fromkeys(["mjcf_text", "pose_to_qpos", "write_mjcf"], "taut.model._mjcf"),
}


__all__ = [
    "Body",
    "Cable",
    "Capsule",
    "Circle",
    "Joint",
    "Platform",
    "Polygon",
    "Pulley",
    "Reference",
    "Robot",
    "Shape",
    "SwivelPulley",
    "Trajectory",
    "example",
    "example_descriptions",
    "example_names",
    "load_robot",
    "mjcf_text",
    "parse_robot",
    "pose_to_qpos",
    "robot_from_dict",
    "robot_schema",
    "robot_to_dict",
    "save_robot",
    "write_mjcf",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
