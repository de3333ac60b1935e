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

import math
from collections.abc import Callable
from typing import Any

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.errors import ArgumentError
from taut.interval import _kernels as K

#: Bound of the error of NumPy's ``cos`` and ``sin`` (the C library's, within an ulp or two of
#: the exact value; 1e-15 is nine ulps of 1), by which :meth:`Interval.cos` widens its ends.
TRIG_ERROR = 1e-15


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
    """An array of intervals ``[lo, hi]`` with outward-rounded arithmetic (Berti 2015,
    §1.3.1–1.3.2): every result encloses the exact result of the operation on every pair of
    reals of its operands (one rounding per operation, a proven bound of the rounding error).

    ``+ − × /``, ``**`` (non-negative integer powers), :meth:`sqr` and :meth:`sqrt` are
    lifted elementwise from the scalar kernels of :mod:`taut.interval._kernels`; writing an
    expression with these objects is its natural interval evaluation.

    Parameters
    ----------
    lo : array_like
        Lower ends.
    hi : array_like, optional
        Upper ends (default ``lo``: degenerate intervals), broadcast with ``lo``.

    Attributes
    ----------
    lo, hi : ndarray
        The ends, of the broadcast shape (a scalar interval has shape ``()``).
    shape : tuple of int
    width : ndarray
        ``hi − lo``.
    mid : ndarray
        ``(lo + hi) / 2``.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §1.3.1–1.3.2. (docs/references.bib: berti2015)

    Examples
    --------
    The float sum ``0.1 + 0.2`` is not the real one; the interval sum encloses both:

    >>> Interval(0.1) + Interval(0.2)
    Interval([0.3, 0.3000000000000001])
    >>> Interval(-1.0, 2.0).sqr()
    Interval([0.0, 4.000000000000001])
    """

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

    @classmethod
    def _own(cls, lo: np.ndarray, hi: np.ndarray) -> Interval:
        """An interval of fresh float arrays of one shape, which nothing else holds: no copy."""
        out = cls.__new__(cls)
        out.lo, out.hi = lo, hi
        return out

    # -- construction and inspection -------------------------------------------------
    @classmethod
    def point(cls, x: npt.ArrayLike) -> Interval:
        """The degenerate interval ``[x, x]`` (exact: ``x`` is a float).

        Examples
        --------
        >>> Interval.point(0.5)
        Interval([0.5, 0.5])
        """
        return cls(x, x)

    @property
    def shape(self) -> tuple[int, ...]:
        """The shape of the array of intervals."""
        return self.lo.shape

    @property
    def width(self) -> np.ndarray:
        """Widths ``hi − lo``."""
        return self.hi - self.lo

    @property
    def mid(self) -> np.ndarray:
        """Midpoints ``(lo + hi) / 2`` (rounded to nearest)."""
        return 0.5 * self.lo + 0.5 * self.hi

    def is_empty(self) -> np.ndarray:
        """Where ``lo > hi`` (or a NaN end): the empty intervals."""
        return ~(self.lo <= self.hi)

    def contains(self, x: npt.ArrayLike) -> np.ndarray:
        """Where the interval contains ``x``.

        Examples
        --------
        >>> Interval([0.0, 2.0], [1.0, 3.0]).contains(0.5)
        array([ True, False])
        """
        return (self.lo <= x) & (x <= self.hi)

    def subset(self, other: Interval) -> np.ndarray:
        """Where the interval lies in ``other``."""
        return (other.lo <= self.lo) & (self.hi <= other.hi)

    def __getitem__(self, key: Any) -> Interval:
        """The intervals at a NumPy index (integers, slices, arrays, ``None``, ``...``)."""
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
        return Interval._own(lo.reshape(shape), hi.reshape(shape))

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
        return Interval._own(-self.hi, -self.lo)

    def _unary(self, kernel: Callable[..., None], *args: int) -> Interval:
        shape, (al, ah) = _flat(self.lo, self.hi)
        lo, hi = np.empty_like(al), np.empty_like(al)
        kernel(al, ah, *args, lo, hi)
        return Interval._own(lo.reshape(shape), hi.reshape(shape))

    def sqr(self) -> Interval:
        """The square ``{x² : x ∈ [lo, hi]}`` (tighter than ``x·x``, which allows negative products)."""
        return self._unary(_sqr)

    def sqrt(self) -> Interval:
        """The square root of the non-negative part."""
        return self._unary(_sqrt)

    def __pow__(self, n: int) -> Interval:
        if int(n) != n or n < 0:
            raise ArgumentError(f"interval powers take a non-negative integer exponent, got {n!r}")
        return self._unary(_pow, int(n))

    def cos(self) -> Interval:
        """The cosine ``{cos x : x ∈ [lo, hi]}``: the ends' values widened by
        :data:`TRIG_ERROR`, and ``1`` (``−1``) where the interval holds an even (odd) multiple
        of π.

        Examples
        --------
        >>> Interval(-0.5, 0.5).cos().hi
        array(1.)
        >>> bool(Interval(3.0, 3.3).cos().lo == -1.0)
        True
        """
        return self._periodic(0.0)

    def sin(self) -> Interval:
        """The sine ``{sin x : x ∈ [lo, hi]}`` (as :meth:`cos`, peaks at π/2 + 2kπ).

        Examples
        --------
        >>> s = Interval(0.0, np.pi).sin()
        >>> bool(s.lo <= 0.0 and s.hi == 1.0)
        True
        """
        return self._periodic(0.5 * math.pi)

    def _periodic(self, peak: float) -> Interval:
        """``cos(x − peak)`` over the intervals, computed as ``cos`` or ``sin`` of ``x`` itself
        (so that no rounded shift enters); the extremes are where ``(x − peak)/π`` is an
        integer, searched with a margin that covers the rounding of that quotient."""
        lo, hi = self.lo, self.hi
        fun = np.cos if peak == 0.0 else np.sin
        with np.errstate(invalid="ignore"):
            a, b = fun(lo), fun(hi)
        out_lo = np.maximum(np.minimum(a, b) - TRIG_ERROR, -1.0)
        out_hi = np.minimum(np.maximum(a, b) + TRIG_ERROR, 1.0)
        margin = 1e-12 * (1.0 + np.abs(lo) + np.abs(hi))
        with np.errstate(invalid="ignore"):
            k_lo = np.ceil((lo - peak) / math.pi - margin)
            k_hi = np.floor((hi - peak) / math.pi + margin)
        many = ~np.isfinite(k_lo) | ~np.isfinite(k_hi) | (k_hi - k_lo >= 1) | ~(hi - lo < 2 * math.pi)
        one = (k_hi == k_lo) & ~many
        even = one & (np.mod(k_lo, 2) == 0)
        odd = one & ~even
        out_hi = np.where(many | even, 1.0, out_hi)
        out_lo = np.where(many | odd, -1.0, out_lo)
        return Interval(out_lo, out_hi)

    def sum_last(self) -> Interval:
        """Sums along the last axis, one rounded addition at a time.

        Examples
        --------
        >>> Interval([[0.0, 1.0], [2.0, 3.0]], [[0.5, 1.5], [2.5, 3.5]]).sum_last()
        Interval(lo=array([1., 5.]), hi=array([2., 6.]))
        """
        acc = self[..., 0]
        for j in range(1, self.shape[-1]):
            acc = acc + self[..., j]
        return acc

    def sum(self) -> Interval:
        """Sum of all elements, one rounded addition at a time."""
        acc = Interval(0.0)
        for lo, hi in zip(self.lo.ravel(), self.hi.ravel()):
            acc = acc + Interval(lo, hi)
        return acc


def centred_form(f_mid: Interval, jacobian: Interval, box: Interval, centre: np.ndarray) -> Interval:
    """The centred (mean-value) form ``f(c) + J([x])·([x] − c)`` of a vector function over a box:
    tighter than the natural evaluation on narrow boxes.

    Parameters
    ----------
    f_mid : Interval, shape (h,)
        Encloses ``f(c)``.
    jacobian : Interval, shape (h, n)
        Encloses ``∂f/∂x`` over ``box``.
    box : Interval, shape (n,)
    centre : ndarray, shape (n,)
        ``c``, a point of the box.

    Returns
    -------
    Interval, shape (h,)
        Encloses ``f`` over the box.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §1.3.2. (docs/references.bib: berti2015)

    Examples
    --------
    ``f(x) = 2.5 x`` over ``[0, 1]`` from its value 1.25 at the centre and its slope in ``[2, 3]``:

    >>> centred_form(Interval([1.25]), Interval([[2.0]], [[3.0]]), Interval([0.0], [1.0]), np.array([0.5]))
    Interval(lo=array([-0.25]), hi=array([2.75]))
    """
    d = box - centre
    out = f_mid
    for j in range(box.shape[0]):
        out = out + jacobian[:, j] * d[j]
    return out
