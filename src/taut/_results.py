"""The one kind of result (``docs/architecture.md`` §2.7): a frozen dataclass whose arrays are
read-only, with ``as_dict()`` in plain JSON types.

A result class derives from :class:`Result` and is declared ``@dataclass(frozen=True)``::

    @dataclass(frozen=True)
    class TensionResult(Result):
        tensions: np.ndarray
        feasible: bool

A subclass that defines its own ``__post_init__`` calls ``super().__post_init__()``; one whose
fields are not all data (a robot, a callable) overrides ``as_dict`` and builds it with
:func:`jsonable`.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from enum import Enum
from typing import Any

import numpy as np

__all__ = ["Result", "freeze", "jsonable"]


def _read_only(value: Any) -> Any:
    """``value`` with its arrays as read-only views (a view, so the caller's array is not
    changed and nothing is copied); a list or tuple holding arrays, at any depth, becomes a
    tuple of the same items with read-only arrays."""
    if isinstance(value, np.ndarray):
        if not value.flags.writeable:
            return value
        view = value.view()
        view.flags.writeable = False
        return view
    if isinstance(value, (list, tuple)):
        items = [_read_only(v) for v in value]
        if any(a is not b for a, b in zip(items, value)):
            return tuple(items)
    return value


def freeze(obj: Any) -> None:
    """Make the array fields of the dataclass instance ``obj`` read-only, in place.

    Parameters
    ----------
    obj : dataclass instance
        Frozen or not; its fields holding a :class:`numpy.ndarray` (or lists or tuples of
        them, nested) are replaced by read-only views.

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> import numpy as np
    >>> @dataclass(frozen=True)
    ... class R:
    ...     x: np.ndarray
    >>> r = R(np.zeros(2))
    >>> freeze(r)
    >>> r.x.flags.writeable
    False
    """
    for field in dataclasses.fields(obj):
        value = getattr(obj, field.name)
        frozen = _read_only(value)
        if frozen is not value:
            object.__setattr__(obj, field.name, frozen)


def jsonable(value: Any) -> Any:
    """``value`` in plain JSON types: lists, floats, ints, strings, booleans and ``None``.

    Arrays and tuples become lists, NumPy scalars Python numbers, NaN and infinities ``None``,
    dataclasses (their ``as_dict()`` when they have one) and mappings dictionaries with
    string keys, enumerations their value.

    Parameters
    ----------
    value : object
        The value to convert.

    Returns
    -------
    object
        ``json.dumps(result, allow_nan=False)`` accepts it.

    Raises
    ------
    TypeError
        For a value of no JSON form (a callable, a robot): a bug of the result class, which
        should leave the field out of its ``as_dict``.

    Examples
    --------
    >>> import numpy as np
    >>> jsonable({"t": np.array([1.5, np.inf]), "n": np.int64(3), "cables": (0, 2)})
    {'t': [1.5, None], 'n': 3, 'cables': [0, 2]}
    """
    if value is None or isinstance(value, (bool, str)):
        return value
    if isinstance(value, np.bool_):
        return bool(value)
    if isinstance(value, (int, np.integer)):
        return int(value)
    if isinstance(value, (float, np.floating)):
        return float(value) if math.isfinite(value) else None
    if isinstance(value, np.ndarray):
        if value.dtype.kind in "biu":
            return value.tolist()
        return jsonable(value.tolist())
    if isinstance(value, Enum):
        return jsonable(value.value)
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        as_dict = getattr(value, "as_dict", None)
        if callable(as_dict):
            return as_dict()
        return {f.name: jsonable(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, Mapping):
        return {str(k): jsonable(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [jsonable(v) for v in value]
    raise TypeError(f"no JSON form for a {type(value).__name__}")


class Result:
    """Base of taut's results: declared ``@dataclass(frozen=True)``, its arrays are made
    read-only when it is built, and :meth:`as_dict` gives its fields in JSON types.

    Examples
    --------
    >>> import json
    >>> from dataclasses import dataclass
    >>> import numpy as np
    >>> @dataclass(frozen=True)
    ... class Distances(Result):
    ...     values: np.ndarray
    ...     complete: bool
    >>> r = Distances(np.array([0.5, np.nan]), True)
    >>> r.values.flags.writeable
    False
    >>> json.dumps(r.as_dict(), allow_nan=False)
    '{"values": [0.5, null], "complete": true}'
    """

    def __post_init__(self) -> None:
        freeze(self)

    def as_dict(self) -> dict[str, Any]:
        """The fields, by name, in plain JSON types (:func:`jsonable`).

        Returns
        -------
        dict
            ``json.dumps(result.as_dict(), allow_nan=False)`` accepts it.
        """
        return {f.name: jsonable(getattr(self, f.name)) for f in dataclasses.fields(self)}  # type: ignore[arg-type]
