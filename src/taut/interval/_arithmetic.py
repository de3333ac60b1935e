"""Interval arrays: ``lo`` and ``hi`` endpoint arrays with outward-rounded arithmetic
(Berti 2015, §1.3.1–1.3.2).

:class:`Interval` wraps two broadcastable float arrays and overloads ``+ − × / **``,
:meth:`Interval.sqr` and :meth:`Interval.sqrt`, each lifted elementwise from the scalar
kernels of :mod:`taut.interval._kernels` (one rounding per operation, no BLAS, no
``np.sum`` on endpoints).  Writing an expression with these objects is its *natural*
interval evaluation; :func:`centred_form` gives the centred (mean-value) form
``f(c) + J([x])([x] − c)`` from an enclosure of the Jacobian.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §1.3.1–1.3.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.errors import ArgumentError
from taut.interval import _kernels as K


@njit(cache=True, fastmath=False)
def _add(al: np.ndarray, ah: np.ndarray, bl: np.ndarray, bh: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.add(al[i], ah[i], bl[i], bh[i])


@njit(cache=True, fastmath=False)
def _sub(al: np.ndarray, ah: np.ndarray, bl: np.ndarray, bh: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.sub(al[i], ah[i], bl[i], bh[i])


@njit(cache=True, fastmath=False)
def _mul(al: np.ndarray, ah: np.ndarray, bl: np.ndarray, bh: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.mul(al[i], ah[i], bl[i], bh[i])


@njit(cache=True, fastmath=False)
def _div(al: np.ndarray, ah: np.ndarray, bl: np.ndarray, bh: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.div(al[i], ah[i], bl[i], bh[i])


@njit(cache=True, fastmath=False)
def _sqr(al: np.ndarray, ah: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.sqr(al[i], ah[i])


@njit(cache=True, fastmath=False)
def _sqrt(al: np.ndarray, ah: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.sqrt(al[i], ah[i])


@njit(cache=True, fastmath=False)
def _pow(al: np.ndarray, ah: np.ndarray, n: int, lo: np.ndarray, hi: np.ndarray) -> None:
    for i in range(lo.size):
        lo[i], hi[i] = K.power(al[i], ah[i], n)


def _flat(*arrays: np.ndarray) -> tuple[tuple[int, ...], list[np.ndarray]]:
    shape = np.broadcast_shapes(*(a.shape for a in arrays))
    return shape, [np.ascontiguousarray(np.broadcast_to(a, shape), dtype=np.float64).ravel() for a in arrays]


class Interval:
    """An array of intervals ``[lo, hi]`` (any shape; a scalar interval has shape ``()``)."""

    __array_priority__ = 1000  # ``ndarray + Interval`` defers to Interval.__radd__

    def __init__(self, lo: npt.ArrayLike, hi: npt.ArrayLike | None = None) -> None:
        try:
            lo = np.asarray(lo, dtype=np.float64)
            hi = lo if hi is None else np.asarray(hi, dtype=np.float64)
            shape = np.broadcast_shapes(lo.shape, hi.shape)
        except (TypeError, ValueError):
            raise ArgumentError("interval end points must be numbers in arrays that broadcast together") from None
        self.lo = np.broadcast_to(lo, shape).copy()
        self.hi = np.broadcast_to(hi, shape).copy()

    # -- construction and inspection -------------------------------------------------
    @classmethod
    def point(cls, x: npt.ArrayLike) -> Interval:
        """The degenerate interval ``[x, x]`` (exact: ``x`` is a float)."""
        return cls(x, x)

    @property
    def shape(self) -> tuple[int, ...]:
        return self.lo.shape

    @property
    def width(self) -> np.ndarray:
        return self.hi - self.lo

    @property
    def mid(self) -> np.ndarray:
        return 0.5 * self.lo + 0.5 * self.hi

    def is_empty(self) -> np.ndarray:
        return ~(self.lo <= self.hi)

    def contains(self, x: npt.ArrayLike) -> np.ndarray:
        return (self.lo <= x) & (x <= self.hi)

    def subset(self, other: Interval) -> np.ndarray:
        return (other.lo <= self.lo) & (self.hi <= other.hi)

    def __getitem__(self, key: int | slice | np.ndarray | tuple[int | slice | np.ndarray | None, ...]) -> Interval:
        return Interval(self.lo[key], self.hi[key])

    def __repr__(self) -> str:
        if self.lo.ndim == 0:
            return f"Interval([{float(self.lo)!r}, {float(self.hi)!r}])"
        return f"Interval(lo={self.lo!r}, hi={self.hi!r})"

    # -- arithmetic -------------------------------------------------------------------
    @staticmethod
    def _coerce(x: Interval | npt.ArrayLike) -> Interval:
        return x if isinstance(x, Interval) else Interval(x, x)

    def _binary(self, other: Interval | npt.ArrayLike, kernel: Callable[..., None], swap: bool = False) -> Interval:
        a, b = (self._coerce(other), self) if swap else (self, self._coerce(other))
        shape, (al, ah, bl, bh) = _flat(a.lo, a.hi, b.lo, b.hi)
        lo, hi = np.empty_like(al), np.empty_like(al)
        kernel(al, ah, bl, bh, lo, hi)
        return Interval(lo.reshape(shape), hi.reshape(shape))

    def __add__(self, other: Interval | npt.ArrayLike) -> Interval:
        return self._binary(other, _add)

    __radd__ = __add__

    def __sub__(self, other: Interval | npt.ArrayLike) -> Interval:
        return self._binary(other, _sub)

    def __rsub__(self, other: Interval | npt.ArrayLike) -> Interval:
        return self._binary(other, _sub, swap=True)

    def __mul__(self, other: Interval | npt.ArrayLike) -> Interval:
        return self._binary(other, _mul)

    __rmul__ = __mul__

    def __truediv__(self, other: Interval | npt.ArrayLike) -> Interval:
        return self._binary(other, _div)

    def __rtruediv__(self, other: Interval | npt.ArrayLike) -> Interval:
        return self._binary(other, _div, swap=True)

    def __neg__(self) -> Interval:
        return Interval(-self.hi, -self.lo)

    def _unary(self, kernel: Callable[..., None], *args: int) -> Interval:
        shape, (al, ah) = _flat(self.lo, self.hi)
        lo, hi = np.empty_like(al), np.empty_like(al)
        kernel(al, ah, *args, lo, hi)
        return Interval(lo.reshape(shape), hi.reshape(shape))

    def sqr(self) -> Interval:
        return self._unary(_sqr)

    def sqrt(self) -> Interval:
        return self._unary(_sqrt)

    def __pow__(self, n: int) -> Interval:
        if int(n) != n or n < 0:
            raise ArgumentError(f"interval powers take a non-negative integer exponent, got {n!r}")
        return self._unary(_pow, int(n))

    def sum(self) -> Interval:
        """Sum of all elements, one rounded addition at a time."""
        acc = Interval(0.0)
        for lo, hi in zip(self.lo.ravel(), self.hi.ravel()):
            acc = acc + Interval(lo, hi)
        return acc


def centred_form(f_mid: Interval, jacobian: Interval, box: Interval, centre: np.ndarray) -> Interval:
    """Centred (mean-value) evaluation ``f(c) + J([x])·([x] − c)`` of a vector function:
    ``f_mid`` encloses ``f(c)``, ``jacobian`` (``(h, n)``) encloses ``∂f/∂x`` over ``box``."""
    d = box - centre
    out = f_mid
    for j in range(box.shape[0]):
        out = out + jacobian[:, j] * d[j]
    return out
