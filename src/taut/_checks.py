"""Checks of a public function's arguments (``docs/architecture.md`` §2.7): what is not a
number, an array of the expected shape, a whole count or an index becomes one
:class:`~taut.errors.TautError` (or the subclass the caller names) whose one-line message
names the argument, never the ``ValueError`` or ``TypeError`` NumPy would raise deeper down."""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np

from taut.errors import TautError

__all__ = ["as_array", "as_count", "as_index", "as_number", "as_rng"]


def _shown(value: object) -> str:
    """``value`` as a message shows it: its repr, cut at 60 characters."""
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def as_array(
    value: object,
    what: str,
    *,
    shape: Sequence[int | None] | None = None,
    finite: bool = True,
    error: type[TautError] = TautError,
) -> np.ndarray:
    """``value`` as a float array, of ``shape`` when given (``None`` for an axis of any
    length), with finite entries when ``finite``; ``error`` naming ``what`` otherwise."""
    try:
        arr = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise error(f"{what}: expected numbers, got {_shown(value)}") from None
    if shape is not None and (
        arr.ndim != len(shape) or any(n is not None and m != n for m, n in zip(arr.shape, shape))
    ):
        want = "(" + ", ".join("N" if n is None else str(n) for n in shape) + ("," if len(shape) == 1 else "") + ")"
        raise error(f"{what}: expected an array of shape {want}, got shape {arr.shape}")
    if finite and not np.all(np.isfinite(arr)):
        raise error(f"{what}: expected finite numbers, got {_shown(value)}")
    return arr


def as_number(value: object, what: str, *, positive: bool = False, error: type[TautError] = TautError) -> float:
    """``value`` as a finite float, ``> 0`` when ``positive``; ``error`` naming ``what`` otherwise."""
    if isinstance(value, (bool, np.bool_)):
        raise error(f"{what}: expected a number, got {value!r}")
    try:
        x = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise error(f"{what}: expected a number, got {_shown(value)}") from None
    if not math.isfinite(x) or (positive and x <= 0.0):
        raise error(f"{what}: expected a finite number{' > 0' if positive else ''}, got {_shown(value)}")
    return x


def as_count(value: object, what: str, *, minimum: int = 1) -> int:
    """``value`` as a whole number ``≥ minimum`` (a float of integral value is one: ``1e6``)."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, float, np.integer, np.floating)):
        raise TautError(f"{what}: expected a whole number >= {minimum}, got {_shown(value)}")
    if not (math.isfinite(value) and value == int(value) and value >= minimum):
        raise TautError(f"{what}: expected a whole number >= {minimum}, got {_shown(value)}")
    return int(value)


def as_index(value: object, what: str, n: int, *, error: type[TautError] = TautError) -> int:
    """``value`` as an index ``0 ≤ i < n``."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)) or not 0 <= value < n:
        raise error(f"{what}: expected an index 0..{n - 1}, got {_shown(value)}")
    return int(value)


def as_rng(seed: object, what: str = "seed") -> np.random.Generator:
    """The random generator of ``seed``: an ``int`` (or ``None``) seeds a new one, a
    :class:`numpy.random.Generator` is used as it is."""
    try:
        return np.random.default_rng(seed)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise TautError(f"{what}: expected an int or a numpy.random.Generator, got {_shown(seed)}") from None
