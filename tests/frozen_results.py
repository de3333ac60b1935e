"""Checks of docs/architecture.md §2.7 on a result: a frozen dataclass whose arrays are
read-only and whose ``as_dict()`` is plain JSON (no NaN) with the expected keys."""

import dataclasses
import json

import numpy as np
import pytest


def check_frozen(result: object, keys: set[str]) -> dict:
    """Assert the result cannot be changed (no field can be set, no array written) and that
    ``as_dict()`` has exactly ``keys`` and survives ``json.dumps(allow_nan=False)``; return
    the dictionary read back from that JSON, for comparisons with the fields."""
    assert dataclasses.is_dataclass(result)
    first = dataclasses.fields(result)[0].name
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(result, first, getattr(result, first))
    arrays = [getattr(result, f.name) for f in dataclasses.fields(result)]
    arrays = [a for a in arrays if isinstance(a, np.ndarray) and a.size]
    for a in arrays:
        with pytest.raises(ValueError, match="read-only"):
            a.flat[0] = a.flat[0]
    data = result.as_dict()  # type: ignore[attr-defined]
    assert set(data) == keys
    return json.loads(json.dumps(data, allow_nan=False))
