"""docs/architecture.md §2.7: results are frozen, their arrays read-only, ``as_dict()`` plain JSON."""

import dataclasses
import json
import math

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from taut._results import Result, freeze, jsonable
from taut.errors import TautError


@dataclasses.dataclass(frozen=True)
class Sample(Result):
    values: np.ndarray
    cables: tuple[int, ...]
    parts: tuple[np.ndarray, ...] = ()
    label: str = "x"
    count: int = 0


def test_arrays_are_read_only_and_the_callers_array_is_untouched():
    own = np.arange(3.0)
    r = Sample(own, (0, 2), parts=(np.ones(2), np.zeros(1)))
    with pytest.raises(ValueError):
        r.values[0] = 5.0
    with pytest.raises(ValueError):
        r.parts[0][0] = 5.0
    with pytest.raises(dataclasses.FrozenInstanceError):
        r.values = np.zeros(3)  # type: ignore[misc]
    own[0] = 7.0  # the caller's array stays writeable
    assert own.flags.writeable


def test_freeze_on_a_plain_dataclass():
    @dataclasses.dataclass
    class Plain:
        a: np.ndarray
        b: list

    p = Plain(np.zeros(2), [(np.zeros(1), np.ones(1)), (np.ones(1), np.ones(2))])
    freeze(p)
    assert not p.a.flags.writeable
    assert isinstance(p.b, tuple) and not any(x.flags.writeable for box in p.b for x in box)


def test_as_dict_types():
    r = Sample(np.array([[1.0, np.nan], [np.inf, -2.5]]), (1, 3), label="lp", count=np.int64(4))
    d = r.as_dict()
    assert d == {"values": [[1.0, None], [None, -2.5]], "cables": [1, 3], "parts": [], "label": "lp", "count": 4}
    assert type(d["count"]) is int
    json.dumps(d, allow_nan=False)


def test_nested_results_use_their_as_dict():
    @dataclasses.dataclass(frozen=True)
    class Outer(Result):
        inner: Sample
        flags: np.ndarray

    o = Outer(Sample(np.zeros(1), ()), np.array([True, False]))
    assert o.as_dict() == {
        "inner": {"values": [0.0], "cables": [], "parts": [], "label": "x", "count": 0},
        "flags": [True, False],
    }


def test_no_json_form_is_a_taut_error():
    with pytest.raises(TautError, match="function"):
        jsonable({"f": lambda: 0})


@given(arrays(np.float64, st.integers(0, 6)))
def test_round_trip(values):
    d = Sample(values, (0,)).as_dict()
    back = json.loads(json.dumps(d, allow_nan=False))["values"]
    expected = [float(v) if math.isfinite(v) else None for v in values]
    assert back == expected
