"""Robot descriptions: data classes, files, validation, built-in examples (``docs/architecture.md`` §3)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut.lazy import lazy_exports
from taut.model.examples import example, example_descriptions, example_names

if TYPE_CHECKING:
    from taut.model.io import load_robot, parse_robot, robot_from_dict, robot_to_dict, save_robot
    from taut.model.mjcf import mjcf_text, pose_to_qpos, write_mjcf
    from taut.model.robot import (
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
    from taut.model.schema import robot_schema

#: Names re-exported from the modules that load pydantic and PyYAML: imported on first use
#: (PEP 562), so that listing the examples does not build the pydantic models.
_LAZY = {
    **dict.fromkeys(["load_robot", "parse_robot", "robot_from_dict", "robot_to_dict", "save_robot"], "taut.model.io"),
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
        "taut.model.robot",
    ),
    "robot_schema": "taut.model.schema",
    **dict.fromkeys(["mjcf_text", "pose_to_qpos", "write_mjcf"], "taut.model.mjcf"),
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
