"""Reading and writing robot files (YAML or JSON) with one clear message per problem.

A file that cannot be read, is not YAML/JSON, or does not validate raises
:class:`taut.RobotFileError` whose message names the file, the field (1-based list
positions, as cable numbers are shown to users) and what was expected.
"""

from __future__ import annotations

import json
import math
import stat
from pathlib import Path
from typing import Any

import yaml
from pydantic import ValidationError

from taut.errors import RobotFileError
from taut.model._limits import MAX_MAGNITUDE
from taut.model._messages import validation_message
from taut.model._robot import Robot

#: Largest robot file read, in bytes: a robot of thousands of cables is a few hundred KiB.
MAX_FILE_BYTES = 16 << 20

#: Deepest nesting of lists and mappings in a robot file (the format needs about 6).
MAX_DEPTH = 32


def _check_values(data: object, source: str) -> None:
    """Refuse nesting deeper than :data:`MAX_DEPTH` and finite numbers larger than
    :data:`MAX_MAGNITUDE` (infinities are left to validation: ``.inf`` is a valid tension bound)."""
    stack: list[tuple[object, str, int]] = [(data, "", 0)]
    while stack:
        value, field, depth = stack.pop()
        if depth > MAX_DEPTH:
            raise RobotFileError(f"{source}: nested more than {MAX_DEPTH} levels deep at {field or '(top level)'}")
        if isinstance(value, dict):
            stack.extend((v, f"{field}.{k}" if field else str(k), depth + 1) for k, v in value.items())
        elif isinstance(value, list):
            stack.extend((v, f"{field}[{i + 1}]", depth + 1) for i, v in enumerate(value))
        elif isinstance(value, (int, float)) and not isinstance(value, bool):
            too_large = (
                abs(value) > MAX_MAGNITUDE
                if isinstance(value, int)
                else math.isfinite(value) and abs(value) > MAX_MAGNITUDE
            )
            if too_large:
                raise RobotFileError(
                    f"{source}: {field or '(top level)'}: {float(value):.3g} is out of range "
                    f"(taut takes magnitudes up to {MAX_MAGNITUDE:g} in SI units)"
                )


def robot_from_dict(data: object, source: str = "<robot>") -> Robot:
    """Validate a parsed robot description."""
    if not isinstance(data, dict):
        raise RobotFileError(
            f"{source}: expected a mapping of robot fields at the top level, got {type(data).__name__}"
        )
    _check_values(data, source)
    try:
        return Robot.model_validate(data)
    except ValidationError as exc:
        raise RobotFileError(validation_message(source, exc)) from None


def parse_robot(text: str, source: str = "<robot>", *, json_text: bool = False) -> Robot:
    """Parse YAML or JSON text into a validated :class:`Robot`.

    JSON is read by :mod:`json` (which knows ``Infinity`` for unbounded tensions), YAML by
    ``yaml.safe_load`` (where it is ``.inf``)."""
    try:
        if json_text:
            try:
                data = json.loads(text)
            except json.JSONDecodeError as exc:
                raise RobotFileError(
                    f"{source}: not valid JSON at line {exc.lineno}, column {exc.colno}: {exc.msg}"
                ) from None
        else:
            try:
                data = yaml.safe_load(text)
            except yaml.YAMLError as exc:
                where = getattr(exc, "problem_mark", None)
                at = f" at line {where.line + 1}, column {where.column + 1}" if where is not None else ""
                raise RobotFileError(f"{source}: not valid YAML/JSON{at}: {getattr(exc, 'problem', exc)}") from None
    except RecursionError:
        raise RobotFileError(f"{source}: nested too deeply (at most {MAX_DEPTH} levels)") from None
    except RobotFileError:
        raise
    except ValueError:  # an integer of thousands of digits: beyond Python's int conversion limit
        raise RobotFileError(f"{source}: a number has too many digits to be read") from None
    return robot_from_dict(data, source)


def check_regular(path: Path) -> None:
    """Refuse anything but a regular file (a FIFO, a device or a directory would block or
    never end).

    Raises
    ------
    RobotFileError
        If ``path`` cannot be examined or is not a regular file.
    """
    try:
        regular = stat.S_ISREG(path.stat().st_mode)
    except OSError as exc:
        raise RobotFileError(f"{path}: cannot read the file: {exc}") from None
    if not regular:
        raise RobotFileError(f"{path}: not a regular file")


def read_bytes(path: Path) -> bytes:
    """The bytes of a robot file: regular files only (a FIFO, a device or a directory would
    block or never end), at most :data:`MAX_FILE_BYTES`.

    Raises
    ------
    RobotFileError
        If the file cannot be read, is not a regular file or is too large.
    """
    check_regular(path)
    try:
        with path.open("rb") as fh:
            raw = fh.read(MAX_FILE_BYTES + 1)
    except OSError as exc:
        raise RobotFileError(f"{path}: cannot read the file: {exc}") from None
    if len(raw) > MAX_FILE_BYTES:
        raise RobotFileError(f"{path}: larger than {MAX_FILE_BYTES >> 20} MiB: not a robot file")
    return raw


def read_text(path: Path) -> str:
    """The UTF-8 text of a robot file, read by :func:`read_bytes`.

    Raises
    ------
    RobotFileError
        If the file cannot be read, is not a regular file, is too large or is not UTF-8.
    """
    try:
        return read_bytes(path).decode("utf-8")
    except UnicodeDecodeError as exc:
        raise RobotFileError(f"{path}: cannot read the file: {exc}") from None


def _plain(value: object) -> object:
    """Tuples (the model's immutable sequences) as lists, which YAML and JSON write alike."""
    if isinstance(value, (tuple, list)):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    return value


def robot_to_dict(robot: Robot) -> dict[str, Any]:
    """The robot as plain data (lists, dicts, numbers, strings), without fields left at their defaults."""
    data = robot.model_dump(mode="python", exclude_defaults=True)
    return {k: _plain(v) for k, v in data.items()} | {"format": robot.format}


def save_robot(robot: Robot, path: str | Path) -> None:
    """Write ``robot`` as JSON (``.json``) or YAML (anything else)."""
    path = Path(path)
    data = robot_to_dict(robot)
    if path.suffix.lower() == ".json":
        text = json.dumps(data, indent=2)
    else:
        text = yaml.safe_dump(data, sort_keys=False, default_flow_style=None)
    path.write_text(text, encoding="utf-8")
