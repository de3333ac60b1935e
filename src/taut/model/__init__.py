"""Robot descriptions: data classes, files, validation, built-in examples (``docs/architecture.md`` §3)."""

from taut.model.examples import example, example_descriptions, example_names
from taut.model.io import load_robot, parse_robot, robot_from_dict, robot_to_dict, save_robot
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
    Trajectory,
)
from taut.model.schema import robot_schema

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
    "Trajectory",
    "example",
    "example_descriptions",
    "example_names",
    "load_robot",
    "parse_robot",
    "robot_from_dict",
    "robot_schema",
    "robot_to_dict",
    "save_robot",
]
