"""Checks of docs/architecture.md §2.7 on a result: frozen, its arrays read-only, ``as_dict()``
in plain JSON types (no NaN or infinity) that round-trips through ``json``."""

import dataclasses
import json
import math

import numpy as np
import pytest


def _arrays(value):
    if isinstance(value, np.ndarray):
        yield value
    elif isinstance(value, (list, tuple)):
        for v in value:
            yield from _arrays(v)


def _plain(value):
    """``value`` (loaded from JSON) holds only dicts, lists, str, int, float, bool and None."""
    if isinstance(value, dict):
        return all(isinstance(k, str) and _plain(v) for k, v in value.items())
    if isinstance(value, list):
        return all(_plain(v) for v in value)
    if isinstance(value, float):
        return math.isfinite(value)
    return value is None or isinstance(value, (str, int, bool))


def check_result(result):
    """Assert the conventions on ``result`` and return ``as_dict()`` after a JSON round trip."""
    fields = dataclasses.fields(result)
    with pytest.raises(dataclasses.FrozenInstanceError):
        setattr(result, fields[0].name, None)
    for f in fields:
        for a in _arrays(getattr(result, f.name)):
            assert not a.flags.writeable, f.name
            if a.size:
                with pytest.raises(ValueError, match="read-only"):
                    a[(0,) * a.ndim] = a[(0,) * a.ndim]
    data = result.as_dict()
    text = json.dumps(data, allow_nan=False)
    back = json.loads(text)
    assert back == data and _plain(back)
    return back


def same(got, want):
    """A JSON list ``got`` holds the numbers of the array ``want`` (NaN and ±inf as None)."""
    want = np.asarray(want)
    if want.dtype.kind == "f":
        expect = np.where(np.isfinite(want), want, np.nan)
        values = np.array(got, dtype=float) if want.size else np.zeros(want.shape)
        assert values.shape == want.shape
        np.testing.assert_array_equal(values, expect)
    else:
        assert got == want.tolist()
