"""Cable numbers at the command line's boundary: users read and write 1-based cable numbers,
the library takes and returns 0-based indices (``docs/architecture.md`` §2.6)."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from taut.errors import CableSetError

#: Fields of the library's result dictionaries that hold cable indices.
CABLE_FIELDS = ("taut", "slack", "length_violations", "boundary")


def cable_indices(numbers: Iterable[int], n_cables: int, option: str) -> list[int]:
    """0-based indices of the 1-based cable ``numbers`` a user gave to ``option``; a number
    outside ``1..n_cables`` raises :class:`~taut.errors.CableSetError` naming it."""
    numbers = [int(k) for k in numbers]
    bad = [k for k in numbers if not 1 <= k <= n_cables]
    if bad:
        raise CableSetError(f"{option}: no cable {', '.join(map(str, bad))}; the robot has cables 1..{n_cables}")
    return [k - 1 for k in numbers]


def cable_numbers(indices: Iterable[int]) -> list[int]:
    """1-based cable numbers, for users, of 0-based cable ``indices``."""
    return [int(i) + 1 for i in indices]


def numbered(record: dict[str, Any]) -> dict[str, Any]:
    """``record`` (a result's ``as_dict()``) with its cable-index fields (:data:`CABLE_FIELDS`)
    as 1-based numbers, in it and in the records it holds (a dictionary, or a list of them:
    the solutions and undecided boxes of a result)."""
    out = {}
    for key, value in record.items():
        if key in CABLE_FIELDS and value is not None:
            value = cable_numbers(value)
        elif isinstance(value, dict):
            value = numbered(value)
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            value = [numbered(v) for v in value]
        out[key] = value
    return out
