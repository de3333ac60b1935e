"""Certified solutions at higher precision: branch-and-prune with the Krawczyk operator in
arb ball arithmetic (python-flint, ``pip install 'taut[precise]'``), for the boxes that
double precision leaves undecided.

Near a double root (two equilibria about to merge as a cable length varies) the Jacobian is
nearly singular: to prove a root unique the Krawczyk box must be narrower than the roots'
distance, yet wider than the rounding error of ``f`` divided by the Jacobian's smallest
singular value.  In double precision both bounds meet while the roots are still far apart
(about 1e-3 in the DGP's unknowns on a 3-cable robot at a relative length 1e-9 from the
fold).  In arb balls of :data:`PRECISION` bits, with every constant of the system entered as
the exact rational it stands for (:attr:`taut.interval._expression.Tape.exact`), the same
operator separates and certifies roots down to distances of about ``2^(−PRECISION/2)``.

The search runs on a box the double search gave up on, with the same constraints: the
equations and the redundant constraints of the :class:`~taut.interval.System`
discard boxes where their enclosure misses their bounds; the Krawczyk operator
``K(X) = y − C f(y) + (I − C J(X))(X − y)`` (``y`` the box's centre, ``C`` the midpoint
inverse of ``J(X)``) discards a box when ``K(X) ∩ X = ∅``, proves a unique root in it when
``K(X) ⊂ int X``, and otherwise contracts it to ``K(X) ∩ X`` before it is bisected.  A
contracted box is also given to Newton's method from its centre: when it converges, the
operator is tried on a box of relative half-width ``2^(−PRECISION/4)`` around its limit,
which certifies a root lying on a bisection face (inside no box's interior) and, once
proven, discards every box inside it.  Newton's method converges only linearly to a singular
root, so boxes around one shrink to ``2^(−PRECISION/2)`` and are returned undecided.

References
----------
.. [1] R. Krawczyk, "Newton-Algorithmen zur Bestimmung von Nullstellen mit Fehlerschranken",
   Computing 4, 1969. (docs/references.bib: krawczyk1969)
.. [2] A. Neumaier, "Interval Methods for Systems of Equations", Cambridge University Press,
   1990, §5.1. (docs/references.bib: neumaier1990)
.. [3] F. Johansson, "Arb: efficient arbitrary-precision midpoint-radius interval
   arithmetic", IEEE Transactions on Computers 66(8), 2017. (docs/references.bib: johansson2017)
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.interval._expression import ADD, ATAN, CONST, DIV, MUL, NEG, POW, SQR, SQRT, SUB, VAR, System, Tape
from taut.interval._krawczyk import Certificate

#: Bits of the arb balls: roots closer than about ``2^(−PRECISION/4)`` (relative) are not
#: separated.
PRECISION = 256

#: Newton steps from a box's centre before the limit is given up as singular.
NEWTON_STEPS = 12

#: Boxes one search may process before what is left stays undecided (about 0.3 ms each on
#: the 12 unknowns of a 3-cable DGP sub-problem).
MAX_PRECISE_BOXES = 20_000


@dataclass(frozen=True)
class PreciseResult(Result):
    """What a multi-precision search proved (a frozen result, read-only arrays).  Every float
    box is rounded outwards from the arb one it stands for.

    Attributes
    ----------
    solutions : tuple of Certificate
        Roots, each unique in its box.
    boundary : tuple of Certificate
        Certified roots whose box straddles a bound of the domain or of a redundant inequality.
    undecided : tuple of (ndarray, ndarray)
        Boxes narrower than ``2^(−precision/2)`` relative: around a singular root, where
        Newton's method does not converge, or roots closer than ``2^(−precision/4)``.
    unsearched : tuple of (ndarray, ndarray)
        Boxes left when the budget ran out.
    boxes : int
        Boxes processed.
    elapsed_s : float
        Wall-clock seconds.
    exhausted : bool
        The budget ran out (some boxes are unsearched).
    complete : bool
        No box is undecided or unsearched.
    """

    solutions: tuple[Certificate, ...]
    boundary: tuple[Certificate, ...]
    undecided: tuple[tuple[np.ndarray, np.ndarray], ...]
    unsearched: tuple[tuple[np.ndarray, np.ndarray], ...]
    boxes: int
    elapsed_s: float
    exhausted: bool = field(init=False)
    complete: bool = field(init=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "exhausted", bool(self.unsearched))
        object.__setattr__(self, "complete", not self.undecided and not self.unsearched)
        super().__post_init__()


def precise_available() -> bool:
    """Whether python-flint (the ``precise`` extra, arb balls) can be imported, which
    :func:`solve_precise` needs.

    Returns
    -------
    bool

    Examples
    --------
    >>> isinstance(precise_available(), bool)
    True
    """
    try:
        import flint  # noqa: F401
    except ImportError:
        return False
    return True


class _Evaluator:
    """A tape evaluated in arb balls: each CONST node once, as its exact rational when the
    tape has it, else as its float interval."""

    def __init__(self, tape: Tape, flint: Any) -> None:
        self.arb = flint.arb
        self.nodes = list(zip(tape.op.tolist(), tape.a.tolist(), tape.b.tolist()))
        self.roots = [int(e) - 1 for e in tape.end]
        self.lo, self.hi = tape.blo.tolist(), tape.bhi.tolist()
        self.consts: dict[int, Any] = {}
        for k, (op, _, _) in enumerate(self.nodes):
            if op == CONST:
                q = tape.exact[k] if tape.exact else None
                if q is not None:
                    self.consts[k] = self.arb(flint.fmpq(q.numerator, q.denominator))
                else:
                    self.consts[k] = self.arb(float(tape.clo[k])).union(self.arb(float(tape.chi[k])))

    def __call__(self, x: list) -> list:
        v: list = [None] * len(self.nodes)
        for k, (op, a, b) in enumerate(self.nodes):
            if op == VAR:
                v[k] = x[a]
            elif op == CONST:
                v[k] = self.consts[k]
            elif op == ADD:
                v[k] = v[a] + v[b]
            elif op == SUB:
                v[k] = v[a] - v[b]
            elif op == MUL:
                v[k] = _sqr(self.arb, v[a]) if a == b else v[a] * v[b]
            elif op == NEG:
                v[k] = -v[a]
            elif op == SQR:
                v[k] = _sqr(self.arb, v[a])
            elif op == POW:
                v[k] = _power(self.arb, v[a], b)
            elif op == SQRT:
                v[k] = v[a].nonnegative_part().sqrt()
            elif op == DIV:
                v[k] = v[a] / v[b]
            elif op == ATAN:
                v[k] = v[a].atan()
        return [v[r] for r in self.roots]

    def excluded(self, values: list) -> bool:
        """Some constraint's enclosure misses its bounds."""
        for v, lo, hi in zip(values, self.lo, self.hi):
            if not v.is_finite():
                continue
            if (lo > -math.inf and v.upper() < lo) or (hi < math.inf and v.lower() > hi):
                return True
        return False

    def straddles(self, values: list, start: int) -> bool:
        """Some inequality from ``start`` on (the redundant ones) is not inside its bounds:
        an equality's enclosure always holds its value and more."""
        for v, lo, hi in zip(values[start:], self.lo[start:], self.hi[start:]):
            if lo == hi:
                continue
            if not v.is_finite() or (lo > -math.inf and v.lower() < lo) or (hi < math.inf and v.upper() > hi):
                return True
        return False


def _sqr(arb: Any, v: Any) -> Any:
    """``v²`` of a ball: ``v·v`` would let it go negative when ``v`` holds 0."""
    lo, hi = v.lower(), v.upper()
    if lo >= 0 or hi <= 0:
        return v * v
    top = max(abs(lo), abs(hi))
    return arb(0).union(top * top)


def _power(arb: Any, v: Any, n: int) -> Any:
    out = arb(1)
    for _ in range(n // 2):
        out = out * _sqr(arb, v)
    return out * v if n % 2 else out


def _larger(a: Any, b: Any) -> Any:
    """The larger of two exact arb points (their comparison is decided)."""
    return a if a >= b else b


def _smaller(a: Any, b: Any) -> Any:
    return a if a <= b else b


def _float_down(arb: Any, v: Any) -> float:
    f = float(v)
    return f if arb(f) <= v else math.nextafter(f, -math.inf)


def _float_up(arb: Any, v: Any) -> float:
    f = float(v)
    return f if arb(f) >= v else math.nextafter(f, math.inf)


def _float_ends(arb: Any, B: list) -> tuple[np.ndarray, np.ndarray]:
    """The float box holding the box of exact end points ``B``."""
    return np.array([_float_down(arb, a) for a, _ in B]), np.array([_float_up(arb, b) for _, b in B])


def solve_precise(
    system: System,
    boxes: Sequence[tuple[npt.ArrayLike, npt.ArrayLike]],
    *,
    domain: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    precision: int = PRECISION,
    max_boxes: int = MAX_PRECISE_BOXES,
) -> PreciseResult:
    """Every root of ``system`` in the boxes ``[(lo, hi), …]``, certified in arb balls of
    ``precision`` bits (module docstring): the boxes double precision leaves too narrow to
    split (nearly double roots of the DGP) searched again.

    A root whose box lies in ``domain`` is a solution, one whose box straddles its bound is
    ``boundary``, one outside it is dropped.  A root in two overlapping boxes is reported
    once.

    Parameters
    ----------
    system : System
    boxes : sequence of (array_like, array_like)
        The boxes to search, sharing one budget.
    domain : (array_like, array_like), optional
        The whole search domain (default unbounded).
    precision : int, default :data:`PRECISION`
        Bits of the balls.
    max_boxes : int, default :data:`MAX_PRECISE_BOXES`
        Boxes processed, all start boxes together, before the rest is left unsearched.

    Returns
    -------
    PreciseResult

    Raises
    ------
    ImportError
        Without python-flint (:func:`precise_available`).

    References
    ----------
    .. [1] F. Johansson, "Arb: efficient arbitrary-precision midpoint-radius interval
       arithmetic", IEEE Transactions on Computers 66(8), 2017. (docs/references.bib: johansson2017)

    Examples
    --------
    Two circles whose centres are ``2 − 2⁻⁶⁰/3`` apart meet in two points about ``1.9e-10``
    apart in ``y``, which no float box separates:

    >>> from fractions import Fraction
    >>> from taut.interval import compile_system, const, variables
    >>> gap = Fraction(2) - Fraction(1, 3 * 2**60)
    >>> centre = const(np.nextafter(float(gap), 0), np.nextafter(float(gap), 3), exact=gap)
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - centre) ** 2 + y**2 - 1])
    >>> res = solve_precise(circles, [([0.5, -0.5], [1.5, 0.5])])
    >>> len(res.solutions), res.complete
    (2, True)
    """
    import flint

    start = time.perf_counter()
    arb = flint.arb
    old = flint.ctx.prec
    flint.ctx.prec = int(precision)
    try:
        starts = [(np.asarray(lo, float), np.asarray(hi, float)) for lo, hi in boxes]
        n = system.n
        # the domain classifies roots, it does not clip the box: a root on its bound would
        # sit on the box's face, where no Krawczyk box lies inside the search box
        dlo = np.full(n, -np.inf) if domain is None else np.asarray(domain[0], float)
        dhi = np.full(n, np.inf) if domain is None else np.asarray(domain[1], float)
        f = _Evaluator(system.tape, flint)
        jac = _Evaluator(system.jacobian, flint)
        rows, cols = system.rows.tolist(), system.cols.tolist()
        inside = [
            (arb(float(a)) if math.isfinite(a) else None, arb(float(b)) if math.isfinite(b) else None)
            for a, b in zip(dlo, dhi)
        ]
        widest = np.max([hi - lo for lo, hi in starts], axis=0) if starts else np.ones(n)
        scale = [arb(max(float(w), 1e-300)) for w in widest]
        tiny = arb(2) ** (-(int(precision) // 2))
        eye = flint.arb_mat(n, n, [1 if i == j else 0 for i in range(n) for j in range(n)])
        # a box is its exact end points: as one ball each side would be widened by the
        # radius's 30-bit rounding, and sibling boxes would overlap
        stack = [[(arb(float(a)), arb(float(b))) for a, b in zip(lo, hi)] for lo, hi in reversed(starts)]
        solutions: list[Certificate] = []
        boundary: list[Certificate] = []
        undecided: list[tuple[np.ndarray, np.ndarray]] = []
        unsearched: list[tuple[np.ndarray, np.ndarray]] = []
        processed = 0

        def krawczyk(B: list) -> tuple[str, list]:
            """``("none", B)``, ``("unique", K)`` with ``K ⊂ int B`` holding the root, or
            ``("contracted", K ∩ B)``."""
            X = [a.union(b) for a, b in B]
            y = [((a + b) / 2).mid() for a, b in B]
            fy = flint.arb_mat(n, 1, f(y)[:n])
            J = flint.arb_mat(n, n)
            for r, c, v in zip(rows, cols, jac(X)):
                J[r, c] = v
            try:
                C = J.mid().inv().mid()
            except ZeroDivisionError:
                return "contracted", B
            d = flint.arb_mat(n, 1, [x - c for x, c in zip(X, y)])
            K = flint.arb_mat(n, 1, y) - C * fy + (eye - C * J) * d
            k = [K[i, 0] for i in range(n)]
            if not all(kk.is_finite() for kk in k):
                return "contracted", B
            if all(kk.lower() > a and kk.upper() < b for kk, (a, b) in zip(k, B)):
                return "unique", k
            cut = [(_larger(a, kk.lower()), _smaller(b, kk.upper())) for kk, (a, b) in zip(k, B)]
            if any(a > b for a, b in cut):
                return "none", B
            return "contracted", cut

        def refined(K: list) -> list:
            """``K`` narrowed to the working precision: Krawczyk on its own box proves the
            root unique in a narrower one."""
            for _ in range(8):
                status, K2 = krawczyk([(k.lower(), k.upper()) for k in K])
                if status != "unique":
                    break
                K = K2
            return K

        def certificate(U: list, K: list) -> Certificate:
            blo, bhi = _float_ends(arb, [(k.lower(), k.upper()) for k in K])
            x = np.array([float(k.mid()) for k in K])
            gap = min(min(arb(float(xi)) - a, b - arb(float(xi))) for xi, (a, b) in zip(x, U))
            return Certificate(x, blo, bhi, _float_down(arb, gap) if gap > 0 else 0.0)

        def within(B: list, U: list) -> bool:
            return all(a >= ua and b <= ub for (a, b), (ua, ub) in zip(B, U))

        def report(U: list, K: list) -> None:
            """The root in ``K ⊂ int U``, alone in ``U``, unless a region already holds it."""
            K = refined(K)
            if any(within([(k.lower(), k.upper()) for k in K], R) for R in regions):
                return
            regions.append(U)
            bounds = f(K)
            out = any(
                (a is not None and k.upper() < a) or (b is not None and k.lower() > b) for k, (a, b) in zip(K, inside)
            )
            if out or f.excluded(bounds):
                return
            straddle = f.straddles(bounds, n) or any(
                (a is not None and k.lower() < a) or (b is not None and k.upper() > b) for k, (a, b) in zip(K, inside)
            )
            (boundary if straddle else solutions).append(certificate(U, K))

        def newton(B: list) -> list | None:
            """The point Newton's method converges to from ``B``'s centre, when it does within
            :data:`NEWTON_STEPS` (not at a singular root) and ends within a width of ``B``."""
            x = [((a + b) / 2).mid() for a, b in B]
            for _ in range(NEWTON_STEPS):
                J = flint.arb_mat(n, n)
                for r, c, v in zip(rows, cols, jac(x)):
                    J[r, c] = v
                try:
                    step = J.mid().solve(flint.arb_mat(n, 1, f(x)[:n]).mid())
                except ZeroDivisionError:
                    return None
                dx = [step[i, 0].mid() for i in range(n)]
                x = [(xi - d).mid() for xi, d in zip(x, dx)]
                if not all(d.is_finite() for d in dx):
                    return None
                if all(abs(d) <= tiny * max(arb(1), abs(xi)) for d, xi in zip(dx, x)):
                    break
            else:
                return None
            if any(xi < a - (b - a) or xi > b + (b - a) for xi, (a, b) in zip(x, B)):
                return None
            return x

        # boxes proven to hold exactly one root, already reported: a box inside one holds
        # nothing else.  A root on a bisection face is inside no box's interior, so it is
        # certified in a small box around Newton's limit instead, which then covers the
        # boxes that shrink onto it.
        regions: list[list] = []
        near = arb(2) ** (-(int(precision) // 4))
        while stack:
            if processed >= max_boxes:
                unsearched += [_float_ends(arb, B) for B in stack]
                break
            B = stack.pop()
            processed += 1
            if any(within(B, U) for U in regions) or f.excluded(f([a.union(b) for a, b in B])):
                continue
            status, K = krawczyk(B)
            if status == "none":
                continue
            if status == "unique":
                report(B, K)
                continue
            B = K
            x = newton(B)
            if x is not None:
                U = [(xi - near * max(arb(1), abs(xi)), xi + near * max(arb(1), abs(xi))) for xi in x]
                U = [(a.lower(), b.upper()) for a, b in U]
                status, K = krawczyk(U)
                if status == "unique":
                    report(U, K)
                    if within(B, U):
                        continue
            if all(b - a <= tiny * max(1.0, abs(float(a))) for a, b in B):
                undecided.append(_float_ends(arb, B))
                continue
            i = max(range(n), key=lambda j: float((B[j][1] - B[j][0]) / scale[j]))
            a, b = B[i]
            m = ((a + b) / 2).mid()
            left, right = list(B), list(B)
            left[i], right[i] = (a, m), (m, b)
            stack += [right, left]
        return PreciseResult(
            tuple(solutions),
            tuple(boundary),
            tuple(undecided),
            tuple(unsearched),
            processed,
            time.perf_counter() - start,
        )
    finally:
        flint.ctx.prec = old
