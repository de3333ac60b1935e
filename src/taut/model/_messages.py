"""One-line messages for robot files that do not validate: a pydantic error becomes
``SOURCE: FIELD: what is wrong``, with 1-based list positions (cable numbers as users see them)."""

from __future__ import annotations

from pydantic import ValidationError
from pydantic_core import ErrorDetails


def _field(loc: tuple[int | str, ...]) -> str:
    out = ""
    for part in loc:
        if isinstance(part, int):
            out += f"[{part + 1}]"
        elif part in ("Circle", "Polygon", "circle", "polygon", "function-after[_consistent(), Robot]"):
            continue
        else:
            out += ("." if out else "") + str(part)
    return out or "(top level)"


def _message(err: ErrorDetails) -> str:
    kind, msg = err["type"], err["msg"]
    if kind == "extra_forbidden":
        return "unknown key (not part of the taut/1 format)"
    if kind == "missing":
        return "required field is missing"
    if kind == "value_error":
        return msg.removeprefix("Value error, ")
    if kind == "union_tag_invalid":
        return f"unknown kind; expected one of {err.get('ctx', {}).get('expected_tags', '')}"
    if kind == "finite_number":
        return "expected a finite number"
    inp = err.get("input")
    got = "" if isinstance(inp, (dict, list)) else f", got {inp!r}"
    return f"{msg.lower()}{got}"


def validation_message(source: str, exc: ValidationError) -> str:
    """Turn a pydantic error into lines ``SOURCE: FIELD: what is wrong``."""
    lines = []
    for err in exc.errors():
        loc = tuple(err["loc"])
        msg = _message(err)
        field = _field(loc)
        if (
            field == "(top level)"
            and ": " in msg
            and msg.split(": ", 1)[0].replace(".", "").replace("[", "").replace("]", "").replace("_", "").isalnum()
        ):
            field, msg = msg.split(": ", 1)
        lines.append(f"{source}: {field}: {msg}")
    return "\n".join(lines)
