"""Robot descriptions: data classes, files, validation, built-in examples (``docs/architecture.md`` §3)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from taut._lazy import lazy_exports

if TYPE_CHECKING:
    from taut.model._caspr import BODIES_SUFFIX, parse_xml, read_caspr, write_caspr
    from taut.model._examples import example, example_descriptions, example_names
    from taut.model._formats import FORMATS, format_of, load_robot, supported, write_robot
    from taut.model._io import parse_robot, read_text, robot_from_dict, robot_to_dict, save_robot
    from taut.model._limits import MAX_MAGNITUDE
    from taut.model._mjcf import mjcf_text, pose_to_qpos, write_mjcf
    from taut.model._random_robots import random_planar_robot, random_point_mass_robot, random_suspended_robot
    from taut.model._robot import (
        Body,
        Cable,
        Capsule,
        Circle,
        Joint,
        JointActuator,
        Platform,
        Polygon,
        Pulley,
        Reference,
        Robot,
        Shape,
        SwivelPulley,
        Trajectory,
        ViaPoint,
    )
    from taut.model._schema import robot_schema, schema_text

#: Every name is imported on first use (PEP 562), so that importing the package loads nothing heavy.
_LAZY = {
    "BODIES_SUFFIX": "taut.model._caspr",
    "parse_xml": "taut.model._caspr",
    "read_caspr": "taut.model._caspr",
    "write_caspr": "taut.model._caspr",
    "example": "taut.model._examples",
    "example_descriptions": "taut.model._examples",
    "example_names": "taut.model._examples",
    "FORMATS": "taut.model._formats",
    "format_of": "taut.model._formats",
    "load_robot": "taut.model._formats",
    "supported": "taut.model._formats",
    "write_robot": "taut.model._formats",
    "parse_robot": "taut.model._io",
    "read_text": "taut.model._io",
    "robot_from_dict": "taut.model._io",
    "robot_to_dict": "taut.model._io",
    "save_robot": "taut.model._io",
    "MAX_MAGNITUDE": "taut.model._limits",
    "mjcf_text": "taut.model._mjcf",
    "pose_to_qpos": "taut.model._mjcf",
    "write_mjcf": "taut.model._mjcf",
    "random_point_mass_robot": "taut.model._random_robots",
    "random_planar_robot": "taut.model._random_robots",
    "random_suspended_robot": "taut.model._random_robots",
    "Body": "taut.model._robot",
    "Cable": "taut.model._robot",
    "Capsule": "taut.model._robot",
    "Circle": "taut.model._robot",
    "Joint": "taut.model._robot",
    "JointActuator": "taut.model._robot",
    "Platform": "taut.model._robot",
    "Polygon": "taut.model._robot",
    "Pulley": "taut.model._robot",
    "Reference": "taut.model._robot",
    "Robot": "taut.model._robot",
    "Shape": "taut.model._robot",
    "SwivelPulley": "taut.model._robot",
    "ViaPoint": "taut.model._robot",
    "Trajectory": "taut.model._robot",
    "robot_schema": "taut.model._schema",
    "schema_text": "taut.model._schema",
}

__all__ = [
    "BODIES_SUFFIX",
    "Body",
    "Cable",
    "Capsule",
    "Circle",
    "FORMATS",
    "Joint",
    "JointActuator",
    "MAX_MAGNITUDE",
    "Platform",
    "Polygon",
    "Pulley",
    "Reference",
    "Robot",
    "Shape",
    "SwivelPulley",
    "Trajectory",
    "ViaPoint",
    "example",
    "example_descriptions",
    "example_names",
    "format_of",
    "load_robot",
    "mjcf_text",
    "parse_robot",
    "parse_xml",
    "pose_to_qpos",
    "random_point_mass_robot",
    "random_planar_robot",
    "random_suspended_robot",
    "read_caspr",
    "read_text",
    "robot_from_dict",
    "robot_schema",
    "robot_to_dict",
    "save_robot",
    "schema_text",
    "supported",
    "write_caspr",
    "write_mjcf",
    "write_robot",
]

__getattr__, __dir__ = lazy_exports(__name__, _LAZY, __all__)
