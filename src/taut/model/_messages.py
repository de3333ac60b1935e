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
    """Turn a pydantic error into one line ``SOURCE: FIELD: what is wrong`` naming the first
    problem (and how many more there are).  An error of a container whose items failed
    (pydantic's "at least 1 item after validation" once every cable is refused) is a
    consequence of those items' errors, not a problem of its own, and is left out."""
    errors = exc.errors()
    locs = [tuple(err["loc"]) for err in errors]
    own = [err for err, loc in zip(errors, locs) if not any(len(o) > len(loc) and o[: len(loc)] == loc for o in locs)]
    err = own[0]
    msg = _message(err)
    field = _field(tuple(err["loc"]))
    if (
        field == "(top level)"
        and ": " in msg
        and msg.split(": ", 1)[0].replace(".", "").replace("[", "").replace("]", "").replace("_", "").isalnum()
    ):
        field, msg = msg.split(": ", 1)
    more = f" (and {len(own) - 1} more {'problem' if len(own) == 2 else 'problems'})" if len(own) > 1 else ""
    return f"{source}: {field}: {msg}{more}"
