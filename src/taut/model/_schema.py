"""The JSON Schema of the robot file format, generated from :class:`taut.model.Robot`
and shipped as ``taut/schema/robot.schema.json`` (a test keeps the two identical)."""

from __future__ import annotations

import json
from importlib import resources

from taut.model._robot import Robot


def robot_schema() -> dict:
    schema = Robot.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "taut robot file (format taut/1)"
    return schema


def shipped_schema_text() -> str:
    return (resources.files("taut") / "schema" / "robot.schema.json").read_text(encoding="utf-8")


def schema_text() -> str:
    return json.dumps(robot_schema(), indent=2, sort_keys=True) + "\n"
