"""Polynomial expressions and their compiled *tape* (Berti 2015, §1.3.2, §3.1.3).

Constraints are written with :class:`Expr` objects (``x[0]**2 + x[1]*x[2] - 3``) and
compiled by :func:`compile_system` into flat arrays — one node per operation, children
before parents, each constraint a contiguous run of nodes ending at its root — that the
Numba kernels of :mod:`taut.interval._hc4` evaluate forwards (natural interval extension)
and backwards (HC4 projections).  Equal subexpressions, within a constraint and across
constraints, become one node (the same Python object, or the same operation on the same
operands), so the tape is one DAG, evaluated once and projected once per sweep.

:func:`derivative` differentiates symbolically (the constraints are polynomials, so the
partial derivatives are again expressions); :func:`compile_system` compiles the Jacobian
of the *equations* into a second tape for interval Newton / Krawczyk.

Constants are intervals: ``const(lo, hi)`` encloses a real that is not a float.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §1.3.2, §3.1.3. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np

from taut.errors import ArgumentError

# Opcodes shared with taut.interval._hc4.
#: The opcodes of a tape's nodes (``Tape.op``), shared with the kernels of
#: :mod:`taut.interval._hc4`: a variable, a constant interval, then the operations.
VAR, CONST, ADD, SUB, MUL, NEG, SQR, POW, SQRT, DIV, ATAN = range(11)


class Expr:
    """A node of a polynomial expression: build them with :func:`variables`, :func:`const`,
    :func:`sqrt`, :func:`atan` and the operators ``+ − × /`` and ``**`` (non-negative integer powers);
    constants are folded where trivial (``x·0``, ``x + 0``, ``x·1``).

    Parameters
    ----------
    op : int
        Its opcode (``VAR``, :data:`CONST`, ``ADD``, ... :data:`SQR`).
    args : iterable of Expr
        Its operands.
    index : int
        The variable's index (``VAR``) or the exponent (``POW``).
    lo, hi : float
        A constant's interval (:data:`CONST`).
    exact : Fraction, optional
        The rational a constant's interval encloses, when known.

    Examples
    --------
    >>> x, y = variables(2)
    >>> x**2 + y * 3.0 - 1
    ((sqr(x0) + (x1 * [3.0, 3.0])) - [1.0, 1.0])
    """

    __slots__ = ("op", "args", "index", "lo", "hi", "exact")
    __array_priority__ = 1000

    def __init__(
        self,
        op: int,
        args: Iterable[Expr] = (),
        index: int = 0,
        lo: float = 0.0,
        hi: float = 0.0,
        exact: Fraction | None = None,
    ) -> None:
        self.op, self.args, self.index, self.lo, self.hi = op, tuple(args), int(index), float(lo), float(hi)
        self.exact = exact

    def is_const(self, value: float | None = None) -> bool:
        """Whether it is a constant (equal to the float ``value`` when given).

        Examples
        --------
        >>> ONE.is_const(1.0), variables(1)[0].is_const()
        (True, False)
        """
        return self.op == CONST and (value is None or (self.lo == value and self.hi == value))

    def __add__(self, o: Expr | float) -> Expr:
        o = _coerce(o)
        if self.is_const(0.0):
            return o
        if o.is_const(0.0):
            return self
        return Expr(ADD, (self, o))

    def __radd__(self, o: Expr | float) -> Expr:
        return _coerce(o) + self

    def __sub__(self, o: Expr | float) -> Expr:
        o = _coerce(o)
        if o.is_const(0.0):
            return self
        if self.is_const(0.0):
            return -o
        return Expr(SUB, (self, o))

    def __rsub__(self, o: Expr | float) -> Expr:
        return _coerce(o) - self

    def __mul__(self, o: Expr | float) -> Expr:
        o = _coerce(o)
        if self.is_const(0.0) or o.is_const(0.0):
            return ZERO
        if self.is_const(1.0):
            return o
        if o.is_const(1.0):
            return self
        return Expr(MUL, (self, o))

    def __rmul__(self, o: Expr | float) -> Expr:
        return _coerce(o) * self

    def __truediv__(self, o: Expr | float) -> Expr:
        return Expr(DIV, (self, _coerce(o)))

    def __neg__(self) -> Expr:
        if self.op == CONST:
            return Expr(CONST, lo=-self.hi, hi=-self.lo, exact=None if self.exact is None else -self.exact)
        return Expr(NEG, (self,))

    def __pow__(self, n: int) -> Expr:
        if int(n) != n or n < 0:
            raise ArgumentError(f"expressions take non-negative integer powers, got {n!r}")
        n = int(n)
        if n == 0:
            return ONE
        if n == 1:
            return self
        if n == 2:
            return Expr(SQR, (self,))
        return Expr(POW, (self,), index=n)

    def __repr__(self) -> str:
        names = {VAR: f"x{self.index}", CONST: f"[{self.lo}, {self.hi}]"}
        if self.op in names:
            return names[self.op]
        sym = {ADD: "+", SUB: "-", MUL: "*", DIV: "/"}
        if self.op in sym:
            return f"({self.args[0]!r} {sym[self.op]} {self.args[1]!r})"
        fn = {NEG: "-", SQR: "sqr", POW: f"pow{self.index}", SQRT: "sqrt", ATAN: "atan"}[self.op]
        return f"{fn}({self.args[0]!r})"


def const(lo: float, hi: float | None = None, *, exact: Fraction | None = None) -> Expr:
    """The constant interval ``[lo, hi]`` as an expression: ``[lo, lo]`` for a float, an enclosure
    of a real that no float holds otherwise.

    Parameters
    ----------
    lo : float
    hi : float, optional
        Default ``lo``.
    exact : Fraction, optional
        The rational it encloses, when known: the multi-precision solver
        (:func:`solve_precise`) evaluates it instead of the float interval.

    Returns
    -------
    Expr

    Examples
    --------
    >>> from fractions import Fraction
    >>> third = const(np.nextafter(1 / 3, 0), np.nextafter(1 / 3, 1), exact=Fraction(1, 3))
    >>> third.lo < 1 / 3 < third.hi, third.exact
    (True, Fraction(1, 3))
    """
    return Expr(CONST, lo=lo, hi=lo if hi is None else hi, exact=exact)


def _coerce(x: Expr | float) -> Expr:
    return x if isinstance(x, Expr) else const(float(x))


#: The constants 0 and 1 as expressions (folded: ``x * ZERO`` is ``ZERO``).
ZERO, ONE = const(0.0), const(1.0)


def variables(n: int) -> list[Expr]:
    """The unknowns ``x_0 … x_{n−1}`` as expressions.

    Parameters
    ----------
    n : int

    Returns
    -------
    list of Expr

    Examples
    --------
    >>> variables(3)
    [x0, x1, x2]
    """
    return [Expr(VAR, index=i) for i in range(n)]


def sqrt(e: Expr) -> Expr:
    """The square root of an expression.

    Parameters
    ----------
    e : Expr or float

    Returns
    -------
    Expr

    Examples
    --------
    >>> sqrt(variables(1)[0] + 1)
    sqrt((x0 + [1.0, 1.0]))
    """
    return Expr(SQRT, (_coerce(e),))


def atan(e: Expr) -> Expr:
    """The arctangent of an expression, in ``(−π/2, π/2)``: the one elementary function of
    the tapes, monotone, enclosed by the kernels of :mod:`taut.interval._kernels`.

    Parameters
    ----------
    e : Expr or float

    Returns
    -------
    Expr

    Examples
    --------
    >>> atan(variables(1)[0] / 2)
    atan((x0 / [2.0, 2.0]))
    """
    return Expr(ATAN, (_coerce(e),))


def derivative(e: Expr, i: int, memo: dict | None = None) -> Expr:
    """The partial derivative ``∂e/∂x_i`` as an expression (constants folded): the constraints
    are polynomials, so their derivatives are again expressions.

    Parameters
    ----------
    e : Expr
    i : int
        The variable's index.
    memo : dict, optional
        Derivatives already taken, by node (shared subexpressions are differentiated once).

    Returns
    -------
    Expr

    Examples
    --------
    >>> x, y = variables(2)
    >>> derivative(x**2 * y, 0)
    (([2.0, 2.0] * x0) * x1)
    """
    memo = {} if memo is None else memo
    key = id(e)
    if key in memo:
        return memo[key]
    op = e.op
    if op == VAR:
        d = ONE if e.index == i else ZERO
    elif op == CONST:
        d = ZERO
    else:
        da = [derivative(a, i, memo) for a in e.args]
        a = e.args
        if op == ADD:
            d = da[0] + da[1]
        elif op == SUB:
            d = da[0] - da[1]
        elif op == NEG:
            d = -da[0] if not da[0].is_const(0.0) else ZERO
        elif op == MUL:
            d = da[0] * a[1] + a[0] * da[1]
        elif op == SQR:
            d = ZERO if da[0].is_const(0.0) else 2.0 * a[0] * da[0]
        elif op == POW:
            d = ZERO if da[0].is_const(0.0) else float(e.index) * a[0] ** (e.index - 1) * da[0]
        elif op == SQRT:
            d = ZERO if da[0].is_const(0.0) else da[0] / (2.0 * e)
        elif op == ATAN:
            d = ZERO if da[0].is_const(0.0) else da[0] / (1.0 + a[0] ** 2)
        else:  # DIV
            d = (da[0] * a[1] - a[0] * da[1]) / a[1] ** 2 if not (da[0].is_const(0.0) and da[1].is_const(0.0)) else ZERO
    memo[key] = d
    return d


def _depends(e: Expr, memo: dict) -> frozenset:
    key = id(e)
    if key not in memo:
        if e.op == VAR:
            memo[key] = frozenset((e.index,))
        elif e.op == CONST:
            memo[key] = frozenset()
        else:
            memo[key] = frozenset().union(*(_depends(a, memo) for a in e.args))
    return memo[key]


#: The degree :func:`degree` gives an expression that is not a polynomial.
NOT_POLYNOMIAL = 1 << 30


def degree(e: Expr, memo: dict | None = None) -> int:
    """Total degree of ``e`` as a polynomial in the unknowns (an upper bound: terms that
    cancel are not noticed), :data:`NOT_POLYNOMIAL` when it has a square root or a
    division by a non-constant."""
    memo = {} if memo is None else memo
    key = id(e)
    if key not in memo:
        if e.op == VAR:
            d = 1
        elif e.op == CONST:
            d = 0
        else:
            k = [degree(x, memo) for x in e.args]
            if e.op in (ADD, SUB):
                d = max(k)
            elif e.op == NEG:
                d = k[0]
            elif e.op == MUL:
                d = k[0] + k[1]
            elif e.op == SQR:
                d = 2 * k[0]
            elif e.op == POW:
                d = e.index * k[0]
            elif e.op == DIV and k[1] == 0:
                d = k[0]
            else:
                d = NOT_POLYNOMIAL
        memo[key] = min(d, NOT_POLYNOMIAL)
    return memo[key]


@dataclass(frozen=True)
class Tape:
    """Compiled constraints ``blo[c] ≤ root_c(x) ≤ bhi[c]``: nodes ``start[c] … end[c]-1``."""

    op: np.ndarray  #: (nodes,) opcodes
    a: np.ndarray  #: first child, or the variable index of VAR nodes
    b: np.ndarray  #: second child, or the exponent of POW nodes
    clo: np.ndarray  #: constant lower bounds (CONST nodes)
    chi: np.ndarray
    start: np.ndarray  #: (constraints,)
    end: np.ndarray
    blo: np.ndarray  #: (constraints,) bounds on the constraint value
    bhi: np.ndarray
    #: (nodes,) the exact rational of a CONST node whose float interval only encloses it,
    #: else None
    exact: tuple[Fraction | None, ...] = ()

    @property
    def arrays(
        self,
    ) -> tuple[
        np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray
    ]:
        return (self.op, self.a, self.b, self.clo, self.chi, self.start, self.end, self.blo, self.bhi)

    @property
    def size(self) -> int:
        return self.start.size

    def parents(self, k: int) -> int:
        """How many nodes have node ``k`` as a child (shared nodes have several)."""
        first = (self.op != VAR) & (self.op != CONST)  # ``a`` is a child, not a variable index
        second = np.isin(self.op, (ADD, SUB, MUL, DIV))  # ``b`` is a child, not an exponent
        return int(np.count_nonzero(first & (self.a == k)) + np.count_nonzero(second & (self.b == k)))


def compile_tape(exprs: Iterable[Expr | float], bounds: Sequence[tuple[float, ...]]) -> Tape:
    """Compile expressions with value bounds into a :class:`Tape`: flat arrays, one node per
    operation, children before parents, each constraint a contiguous run of nodes ending at
    its root, that the kernels of :mod:`taut.interval._hc4` evaluate and contract.

    Nodes are shared across constraints and merged when structurally equal (hash-consing:
    same operation on the same operands), so constraint ``c``'s segment holds only the nodes
    that earlier constraints lack: the tape is evaluated in order, from its first node.

    Parameters
    ----------
    exprs : iterable of Expr or float
        The constraints' expressions.
    bounds : sequence of (float, float)
        ``(lo, hi)`` of each: ``lo ≤ expr ≤ hi``.

    Returns
    -------
    Tape

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.3. (docs/references.bib: berti2015)

    Examples
    --------
    ``x·y`` and ``x·y + 1`` share the product:

    >>> x, y = variables(2)
    >>> xy = x * y
    >>> tape = compile_tape([xy, xy + 1], [(0.0, 1.0), (-np.inf, np.inf)])
    >>> tape.size, len(tape.op)
    (2, 5)
    """
    op: list[int]
    op, a, b, clo, chi, start, end = [], [], [], [], [], [], []
    exact: list[Fraction | None] = []
    index: dict = {}
    keep: list[Expr] = []  # an id is a key only while its object lives
    for e in exprs:
        e = _coerce(e)
        start.append(len(op))

        def emit(node: Expr) -> int:
            k = id(node)
            if k in index:
                return index[k]
            kids = [emit(c) for c in node.args]
            keep.append(node)
            form = (node.op, tuple(kids), node.index, node.lo, node.hi, node.exact)
            if form in index:
                index[k] = index[form]
                return index[k]
            op.append(node.op)
            if node.op == VAR:
                a.append(node.index)
                b.append(0)
            elif node.op == POW:
                a.append(kids[0])
                b.append(node.index)
            else:
                a.append(kids[0] if kids else 0)
                b.append(kids[1] if len(kids) > 1 else 0)
            clo.append(node.lo)
            chi.append(node.hi)
            exact.append(node.exact)
            index[k] = index[form] = len(op) - 1
            return index[k]

        root = emit(e)
        if root < start[-1]:  # emitted whole by an earlier constraint: end on −(−root), exact
            first = len(op)
            op.extend([NEG, NEG])
            a.extend([root, first])
            b.extend([0, 0])
            clo.extend([0.0, 0.0])
            chi.extend([0.0, 0.0])
            exact.extend([None, None])
        end.append(len(op))
    bl = np.array([lo for lo, _ in bounds], dtype=np.float64)
    bh = np.array([hi for _, hi in bounds], dtype=np.float64)
    return Tape(
        np.array(op, np.int64),
        np.array(a, np.int64),
        np.array(b, np.int64),
        np.array(clo, np.float64),
        np.array(chi, np.float64),
        np.array(start, np.int64),
        np.array(end, np.int64),
        bl,
        bh,
        tuple(exact),
    )


@dataclass(frozen=True)
class System:
    """A square system of polynomial equations plus redundant constraints (equalities or
    inequalities) that only the contractor uses: what :func:`compile_system` builds and the
    solvers take.

    Attributes
    ----------
    n : int
        Number of unknowns.
    n_equations : int
        Number of equations ``h`` (``= n``).
    tape : Tape
        The equations first (bounds ``[0, 0]``), then the redundant constraints.
    jacobian : Tape
        The non-zero entries ``∂f_i/∂x_j`` of the equations' Jacobian.
    rows, cols : ndarray of int
        Where each entry of ``jacobian`` goes.
    degrees : ndarray of int
        The polynomial degree of each equation (:func:`degree`).

    Examples
    --------
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> circles.n, circles.rows, circles.cols
    (2, array([0, 0, 1, 1]), array([0, 1, 0, 1]))
    """

    n: int
    n_equations: int
    tape: Tape
    jacobian: Tape
    rows: np.ndarray
    cols: np.ndarray
    degrees: np.ndarray


def compile_system(
    n: int,
    equations: Iterable[Expr],
    constraints: Sequence[tuple[Expr | float, tuple[float, float]]] = (),
) -> System:
    """Compile a square polynomial system and its Jacobian (symbolic, :func:`derivative`).

    Parameters
    ----------
    n : int
        Number of unknowns ``x_0 … x_{n−1}``.
    equations : iterable of Expr
        ``n`` expressions equal to 0.
    constraints : sequence of (Expr or float, (float, float))
        Redundant constraints ``lo ≤ expr ≤ hi`` that prune boxes (a tension ``≥ 0``).

    Returns
    -------
    System

    Raises
    ------
    TautError
        Unless there are ``n`` equations.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §1.3.2, §3.1.3. (docs/references.bib: berti2015)

    Examples
    --------
    The two unit circles centred at ``(0, 0)`` and ``(1, 0)`` (Berti 2015, §3.2.1, Example 1),
    with ``y ≥ 0``:

    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1], [(y, (0.0, np.inf))])
    >>> circles.tape.size, circles.degrees
    (3, array([2, 2]))
    """
    equations = [_coerce(e) for e in equations]
    if len(equations) != n:
        raise ArgumentError(f"a square system needs {n} equations, got {len(equations)}")
    exprs = list(equations) + [_coerce(e) for e, _ in constraints]
    bounds = [(0.0, 0.0)] * n + [tuple(map(float, bd)) for _, bd in constraints]
    tape = compile_tape(exprs, bounds)
    deps: dict = {}
    jac, rows, cols = [], [], []
    for i, e in enumerate(equations):
        memo: dict = {}
        for j in sorted(_depends(e, deps)):
            memo.clear()
            d = derivative(e, j, memo)
            if not d.is_const(0.0):
                jac.append(d)
                rows.append(i)
                cols.append(j)
    jtape = compile_tape(jac, [(-np.inf, np.inf)] * len(jac))
    memo = {}
    degrees = np.array([degree(e, memo) for e in equations], np.int64)
    return System(n, n, tape, jtape, np.array(rows, np.int64), np.array(cols, np.int64), degrees)
