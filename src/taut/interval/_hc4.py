"""HC4 (forward–backward, "2B") contraction of polynomial constraints
(Berti 2015, §3.1.3, the 2B approach; Benhamou et al.'s HC4-revise).

The constraints of a :class:`~taut.interval._expression.Tape` share their common
subexpressions (one DAG).  The forward pass evaluates every node over the box (natural
interval extension), each constraint's root is intersected with its bounds, and the
backward pass projects each node's domain onto its children (``x ∈ z − y`` for
``z = x + y``, ``x ∈ ±√z`` for ``z = x²``, ``x ∈ tan z`` for ``z = atan x``, …) down to
the variables, whose domains shrink — all constraints in one sweep each way, as in the
DAG propagation of Vu, Schichl & Sam-Haroud (J. Global Optim. 45, 2009): a secondary
point used by a dozen constraints is
evaluated and projected once per sweep instead of once per constraint, with what all of
them say about it.  :func:`contract` repeats the sweeps until no domain shrinks by more
than a fraction ``ratio`` of its width.  Every projection uses the
outward-rounded kernels of :mod:`taut.interval._kernels`, so no solution is ever lost.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.1.3. (docs/references.bib: berti2015)
.. [2] F. Benhamou, F. Goualard, L. Granvilliers, J.-F. Puget, "Revising hull and box
   consistency", ICLP, 1999. (docs/references.bib: benhamou1999)
.. [3] X.-H. Vu, H. Schichl, D. Sam-Haroud, "Interval propagation and search on directed acyclic
   graphs for numerical constraint solving", Journal of Global Optimization 45, 2009.
   (docs/references.bib: vu2009)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.interval import _kernels as K
from taut.interval._expression import ADD, ATAN, CONST, MUL, NEG, POW, SQR, SQRT, SUB, VAR, Tape


@njit(cache=True, fastmath=False)
def forward_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    s: int,
    e: int,
    lo: np.ndarray,
    hi: np.ndarray,
    nl: np.ndarray,
    nh: np.ndarray,
) -> None:
    """Forward sweep of the tape ``(op, a, b, clo, chi)`` over its nodes ``s … e−1`` on the
    box ``[lo, hi]``: writes each node's outward-rounded enclosure into ``[nl, nh]``
    (point evaluation with ``lo = hi``).  Compiled, for compiled callers."""
    for k in range(s, e):
        o = op[k]
        if o == VAR:
            nl[k], nh[k] = lo[a[k]], hi[a[k]]
        elif o == CONST:
            nl[k], nh[k] = clo[k], chi[k]
        elif o == ADD:
            nl[k], nh[k] = K.add(nl[a[k]], nh[a[k]], nl[b[k]], nh[b[k]])
        elif o == SUB:
            nl[k], nh[k] = K.sub(nl[a[k]], nh[a[k]], nl[b[k]], nh[b[k]])
        elif o == MUL:
            nl[k], nh[k] = K.mul(nl[a[k]], nh[a[k]], nl[b[k]], nh[b[k]])
        elif o == NEG:
            nl[k], nh[k] = -nh[a[k]], -nl[a[k]]
        elif o == SQR:
            nl[k], nh[k] = K.sqr(nl[a[k]], nh[a[k]])
        elif o == POW:
            nl[k], nh[k] = K.power(nl[a[k]], nh[a[k]], b[k])
        elif o == SQRT:
            nl[k], nh[k] = K.sqrt(nl[a[k]], nh[a[k]])
        elif o == ATAN:
            nl[k], nh[k] = K.atan(nl[a[k]], nh[a[k]])
        else:
            nl[k], nh[k] = K.div(nl[a[k]], nh[a[k]], nl[b[k]], nh[b[k]])


@njit(cache=True, fastmath=False, inline="always")
def _meet(nl: np.ndarray, nh: np.ndarray, i: int, lo: float, hi: float) -> bool:
    """Intersect node ``i`` with ``[lo, hi]``; False when it becomes empty."""
    if lo > nl[i]:
        nl[i] = lo
    if hi < nh[i]:
        nh[i] = hi
    return nl[i] <= nh[i]


@njit(cache=True, fastmath=False)
def _backward(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    s: int,
    e: int,
    lo: np.ndarray,
    hi: np.ndarray,
    nl: np.ndarray,
    nh: np.ndarray,
    fl: np.ndarray,
    fh: np.ndarray,
) -> bool:
    """Project nodes ``e − 1`` down to ``s`` onto their children.  A node whose domain is
    still its forward value ``[fl, fh]`` (no parent or bound narrowed it) is skipped: as
    ``z ⊇ x ∘ y``, ``x ∈ z ∘⁻¹ y`` cannot narrow ``x``."""
    for k in range(e - 1, s - 1, -1):
        if nl[k] == fl[k] and nh[k] == fh[k]:
            continue
        o = op[k]
        zl, zh = nl[k], nh[k]
        if o == VAR:
            j = a[k]
            lo[j] = max(lo[j], zl)
            hi[j] = min(hi[j], zh)
            if not lo[j] <= hi[j]:
                return False
        elif o == CONST:
            pass
        elif o == ADD:
            x, y = a[k], b[k]
            l, h = K.sub(zl, zh, nl[y], nh[y])
            if not _meet(nl, nh, x, l, h):
                return False
            l, h = K.sub(zl, zh, nl[x], nh[x])
            if not _meet(nl, nh, y, l, h):
                return False
        elif o == SUB:
            x, y = a[k], b[k]
            l, h = K.add(zl, zh, nl[y], nh[y])
            if not _meet(nl, nh, x, l, h):
                return False
            l, h = K.sub(nl[x], nh[x], zl, zh)
            if not _meet(nl, nh, y, l, h):
                return False
        elif o == MUL:
            x, y = a[k], b[k]
            if not (nl[y] <= 0.0 <= nh[y]):
                l, h = K.div(zl, zh, nl[y], nh[y])
                if not _meet(nl, nh, x, l, h):
                    return False
            elif not (zl <= 0.0 <= zh) and nl[y] == 0.0 and nh[y] == 0.0:
                return False
            if not (nl[x] <= 0.0 <= nh[x]):
                l, h = K.div(zl, zh, nl[x], nh[x])
                if not _meet(nl, nh, y, l, h):
                    return False
        elif o == NEG:
            if not _meet(nl, nh, a[k], -zh, -zl):
                return False
        elif o == SQR:
            if zh < 0.0:
                return False
            rl, rh = K.sqrt(zl, zh)
            x = a[k]
            # x ∈ [-rh, -rl] ∪ [rl, rh]: keep the hull of the parts that meet x
            pl, ph = max(nl[x], rl), min(nh[x], rh)
            ml, mh = max(nl[x], -rh), min(nh[x], -rl)
            pos, negp = pl <= ph, ml <= mh
            if pos and negp:
                nl[x], nh[x] = ml, ph
            elif pos:
                nl[x], nh[x] = pl, ph
            elif negp:
                nl[x], nh[x] = ml, mh
            else:
                return False
        elif o == POW:
            pass  # odd/even n-th roots are not correctly rounded: no projection (sound)
        elif o == SQRT:
            if zh < 0.0:
                return False
            l, h = K.sqr(max(zl, 0.0), zh)
            if not _meet(nl, nh, a[k], -np.inf if zl <= 0.0 else l, h):
                return False
        elif o == ATAN:
            l, h = K.tan_inverse(zl, zh)
            if not _meet(nl, nh, a[k], l, h):
                return False
        else:  # DIV z = x / y
            x, y = a[k], b[k]
            l, h = K.mul(zl, zh, nl[y], nh[y])
            if not _meet(nl, nh, x, l, h):
                return False
            if not (zl <= 0.0 <= zh):
                l, h = K.div(nl[x], nh[x], zl, zh)
                if not _meet(nl, nh, y, l, h):
                    return False
    return True


@njit(cache=True, fastmath=False)
def contract_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    blo: np.ndarray,
    bhi: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    ratio: float,
    max_rounds: int,
) -> bool:
    """HC4 fixpoint on the box ``lo, hi`` (modified in place); False when proven empty.

    One round is one forward sweep over the whole tape, every root met with its
    constraint's bounds, and one backward sweep from the last node to the first: a node's
    parents all come after it, so by the time it projects onto its children its domain
    holds what every constraint sharing it has said (HC4 on the DAG)."""
    nl = np.empty(op.size)
    nh = np.empty(op.size)
    fl = np.empty(op.size)
    fh = np.empty(op.size)
    n = lo.size
    N = op.size
    before = np.empty(n)
    for _ in range(max_rounds):
        for j in range(n):
            before[j] = hi[j] - lo[j]
        forward_kernel(op, a, b, clo, chi, 0, N, lo, hi, nl, nh)
        fl[:] = nl
        fh[:] = nh
        for c in range(start.size):
            if not _meet(nl, nh, end[c] - 1, blo[c], bhi[c]):
                return False
        if not _backward(op, a, b, 0, N, lo, hi, nl, nh, fl, fh):
            return False
        gain = False
        for j in range(n):
            if hi[j] - lo[j] < (1.0 - ratio) * before[j]:
                gain = True
                break
        if not gain:
            break
    return True


@njit(cache=True, fastmath=False)
def evaluate_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    out_lo: np.ndarray,
    out_hi: np.ndarray,
) -> None:
    nl = np.empty(op.size)
    nh = np.empty(op.size)
    # the segments tile the tape in order: one sweep evaluates them all (shared nodes too)
    forward_kernel(op, a, b, clo, chi, 0, op.size, lo, hi, nl, nh)
    for c in range(start.size):
        out_lo[c], out_hi[c] = nl[end[c] - 1], nh[end[c] - 1]


@njit(cache=True, fastmath=False)
def point_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    x: np.ndarray,
    out: np.ndarray,
) -> None:
    """The floating-point value of every constraint of a tape at ``x``: the compiled kernel of
    :func:`evaluate_point`, callable from other kernels (hence the flat tape arguments).

    Parameters
    ----------
    op, a, b, clo, chi, start, end : ndarray
        The first seven of ``Tape.arrays``.
    x : ndarray, shape (n,)
    out : ndarray, shape (tape.size,)
        Receives the values.

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> tape = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1]).tape
    >>> out = np.empty(tape.size)
    >>> point_kernel(*tape.arrays[:7], np.array([0.5, 0.5]), out)
    >>> out
    array([-0.5, -0.5])
    """
    v = np.empty(op.size)
    for c in range(start.size):
        for k in range(start[c], end[c]):
            o = op[k]
            if o == VAR:
                v[k] = x[a[k]]
            elif o == CONST:
                v[k] = 0.5 * clo[k] + 0.5 * chi[k]
            elif o == ADD:
                v[k] = v[a[k]] + v[b[k]]
            elif o == SUB:
                v[k] = v[a[k]] - v[b[k]]
            elif o == MUL:
                v[k] = v[a[k]] * v[b[k]]
            elif o == NEG:
                v[k] = -v[a[k]]
            elif o == SQR:
                v[k] = v[a[k]] * v[a[k]]
            elif o == POW:
                v[k] = v[a[k]] ** b[k]
            elif o == SQRT:
                v[k] = np.sqrt(v[a[k]])
            elif o == ATAN:
                v[k] = np.arctan(v[a[k]])
            else:
                v[k] = v[a[k]] / v[b[k]]
        out[c] = v[end[c] - 1]


def contract(tape: Tape, lo: np.ndarray, hi: np.ndarray, *, ratio: float = 0.05, max_rounds: int = 50) -> bool:
    """Contract the box ``[lo, hi]`` in place with HC4: forward evaluation and backward
    projection of every constraint of ``tape``, repeated while a domain shrinks by more than
    ``ratio`` (Berti 2015, §1.3.3; Benhamou et al. 1999).

    Parameters
    ----------
    tape : Tape
    lo, hi : ndarray, shape (n,)
        The box, contracted in place (float arrays).
    ratio : float, default 0.05
        Stop when no domain shrinks by more than this fraction of its width.
    max_rounds : int, default 50
        At most this many sweeps.

    Returns
    -------
    bool
        False when the box holds no solution.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §1.3.3. (docs/references.bib: berti2015)
    .. [2] F. Benhamou, F. Goualard, L. Granvilliers, J.-F. Puget, "Revising hull and box
       consistency", ICLP, 1999. (docs/references.bib: benhamou1999)

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> lo, hi = np.array([-2.0, 0.0]), np.array([2.0, 2.0])
    >>> contract(circles.tape, lo, hi), np.round(lo, 12), hi
    (True, array([0., 0.]), array([1., 1.]))
    """
    return bool(contract_kernel(*tape.arrays, lo, hi, ratio, max_rounds))


def evaluate(tape: Tape, lo: npt.ArrayLike, hi: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """The natural interval evaluation of every constraint of ``tape`` over a box.

    Parameters
    ----------
    tape : Tape
    lo, hi : array_like, shape (n,)

    Returns
    -------
    lo, hi : ndarray, shape (tape.size,)
        Enclosures of the constraints' values.

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> evaluate(circles.tape, [0.0, 0.0], [1.0, 1.0])
    (array([-1., -1.]), array([1., 1.]))
    """
    out_lo, out_hi = np.empty(tape.size), np.empty(tape.size)
    op, a, b, clo, chi, start, end, _, _ = tape.arrays
    evaluate_kernel(op, a, b, clo, chi, start, end, np.asarray(lo, float), np.asarray(hi, float), out_lo, out_hi)
    return out_lo, out_hi


def evaluate_point(tape: Tape, x: npt.ArrayLike) -> np.ndarray:
    """The floating-point value of every constraint of ``tape`` at a point (constants at their
    midpoints): for Newton's method.

    Parameters
    ----------
    tape : Tape
    x : array_like, shape (n,)

    Returns
    -------
    ndarray, shape (tape.size,)

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> evaluate_point(circles.tape, [0.5, 0.5])
    array([-0.5, -0.5])
    """
    out = np.empty(tape.size)
    op, a, b, clo, chi, start, end, _, _ = tape.arrays
    point_kernel(op, a, b, clo, chi, start, end, np.asarray(x, float), out)
    return out
