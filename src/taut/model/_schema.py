"""The JSON Schema of the robot file format, generated from :class:`taut.model.Robot`
and shipped as ``taut/schema/robot.schema.json`` (a test keeps the two identical)."""

from __future__ import annotations

import json
from importlib import resources

from taut.model._robot import Robot


def robot_schema() -> dict:
    """The JSON Schema of the robot file format (``format: taut/1``), generated from
    :class:`Robot`: what ``taut schema`` prints and ``taut/schema/robot.schema.json`` ships.

    Returns
    -------
    dict

    Examples
    --------
    >>> schema = robot_schema()
    >>> schema["title"], schema["required"]
    ('taut robot file (format taut/1)', ['name', 'dimension', 'cables'])
    """
    schema = Robot.model_json_schema()
    schema["$schema"] = "https://json-schema.org/draft/2020-12/schema"
    schema["title"] = "taut robot file (format taut/1)"
    return schema


def shipped_schema_text() -> str:
    return (resources.files("taut") / "schema" / "robot.schema.json").read_text(encoding="utf-8")


def schema_text() -> str:
    """:func:`robot_schema` as indented JSON text with sorted keys, ending in a newline.

    Returns
    -------
    str

    Examples
    --------
    >>> import json
    >>> json.loads(schema_text()) == robot_schema()
    True
    """
    return json.dumps(robot_schema(), indent=2, sort_keys=True) + "\n"
