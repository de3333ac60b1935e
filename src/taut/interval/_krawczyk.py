"""Certified solutions of square polynomial systems (Berti 2015, §3.2.1).

* :func:`newton` — plain Newton iterations in floating point (the refinement step).
* :func:`krawczyk` — the Krawczyk operator
  ``K(X) = y − C f(y) + (I − C J(X))(X − y)``, ``C = mid(J(X))⁻¹``, ``y = mid X``:
  ``K(X) ⊂ int X`` proves that ``X`` holds exactly one solution, ``K(X) ∩ X = ∅`` that it
  holds none (Krawczyk 1969; Neumaier 1990 §5.1).  It plays the role of the Kantorovich
  test of §3.2.1 (same conclusion, no second-derivative bound ``p₀`` to derive).  With
  the slopes of :mod:`taut.interval._slope` in place of ``J(X)`` it excludes and
  contracts wider boxes; uniqueness needs ``J(X)``.
* :func:`tube_kernel` — the parametric Krawczyk operator on an under-determined system
  (more unknowns than equations): contracts a box onto the hull of the solution
  manifold's piece in it (the DGP's rigidity and length equations), with the Jacobian
  over the box or the slopes.
* :func:`inflate` — the inflation procedure of §3.2.1 (Eqs. 3.25–3.29): around a solution
  ``y*``, ``S = J(y*)⁻¹ J(B_k)`` over boxes ``B_k`` of half-width ``2^k δ`` is checked for
  strict diagonal dominance (``m_S > M_S``, an H-matrix, hence every matrix in ``J(B_k)`` is
  regular and ``B_k`` holds no second solution); the last box that passes is returned.

Interval matrix products are computed by the Numba kernels below, one outward-rounded
operation at a time (no BLAS on interval endpoints); ``C`` is an ordinary float matrix.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.2.1, Eqs. 3.25–3.29. (docs/references.bib: berti2015)
.. [2] R. Krawczyk, "Newton-Algorithmen zur Bestimmung von Nullstellen mit Fehlerschranken",
   Computing 4, 1969. (docs/references.bib: krawczyk1969)
.. [3] A. Neumaier, "Interval Methods for Systems of Equations", Cambridge University Press,
   1990, §5.1. (docs/references.bib: neumaier1990)
.. [4] S. M. Rump, "Solving algebraic problems with high accuracy", in A New Approach to
   Scientific Computation, Academic Press, 1983. (docs/references.bib: rump1983)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from numba import njit

from taut._results import Result
from taut.interval import _kernels as K
from taut.interval._expression import System
from taut.interval._hc4 import evaluate, evaluate_kernel, evaluate_point, forward_kernel, point_kernel
from taut.interval._linear import float_inverse, precondition
from taut.interval._slope import slopes


def jacobian(system: System, lo: npt.ArrayLike, hi: npt.ArrayLike) -> tuple[np.ndarray, np.ndarray]:
    """Interval enclosure ``(Jlo, Jhi)`` of the Jacobian of the equations over a box."""
    return _dense(system, *evaluate(system.jacobian, lo, hi))


def jacobian_at(system: System, x: npt.ArrayLike) -> np.ndarray:
    J = np.zeros((system.n_equations, system.n))
    J[system.rows, system.cols] = evaluate_point(system.jacobian, x)
    return J


def residual(system: System, x: npt.ArrayLike) -> np.ndarray:
    return evaluate_point(system.tape, x)[: system.n_equations]


def newton(system: System, x0: npt.ArrayLike, *, tol: float = 1e-13, max_iter: int = 30) -> tuple[np.ndarray, bool]:
    """Newton's method on the equations of ``system`` from ``x0``.

    Parameters
    ----------
    system : System
    x0 : array_like, shape (n,)
    tol : float, default 1e-13
        Converged when the last step is at most ``tol · max(1, ‖x‖∞)``.
    max_iter : int, default 30

    Returns
    -------
    x : ndarray, shape (n,)
    converged : bool

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> newton(circles, [0.4, 0.8])
    (array([0.5      , 0.8660254]), True)
    """
    x = np.array(x0, dtype=float)
    for _ in range(max_iter):
        f = residual(system, x)
        try:
            dx = np.linalg.solve(jacobian_at(system, x), f)
        except np.linalg.LinAlgError:
            return x, False
        if not np.all(np.isfinite(dx)):
            return x, False
        x = x - dx
        if np.max(np.abs(dx)) <= tol * max(1.0, np.max(np.abs(x))):
            return x, bool(np.all(np.isfinite(residual(system, x))))
    return x, False


_U = 2.0**-53  #: unit roundoff
#: Added to every radius: bounds the underflow errors of a dot product (at most 2n·2⁻¹⁰⁷⁴).
_TINY = 1e-300


@njit(cache=True, fastmath=False)
def _mid_rad(lo: float, hi: float) -> tuple[float, float]:
    """``(c, r)`` with ``[lo, hi] ⊆ [c − r, c + r]``; ``r`` rounded up."""
    c = 0.5 * lo + 0.5 * hi
    return c, K.up(max(c - lo, hi - c))


@njit(cache=True, fastmath=False)
def krawczyk_image(
    C: np.ndarray,
    y: np.ndarray,
    fl: np.ndarray,
    fh: np.ndarray,
    Jl: np.ndarray,
    Jh: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """``K(X) = y − C f(y) + (I − C J(X))(X − y)`` for a square system: :func:`krawczyk_rows`
    with every variable solved for."""
    return krawczyk_rows(C, np.arange(C.shape[0]), y, fl, fh, Jl, Jh, lo, hi)


@njit(cache=True, fastmath=False)
def krawczyk_rows(
    C: np.ndarray,
    sel: np.ndarray,
    y: np.ndarray,
    fl: np.ndarray,
    fh: np.ndarray,
    Jl: np.ndarray,
    Jh: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """``K(X) = y_S − C f(y) + (I_S − C J(X))(X − y)`` for ``h`` equations in ``n ≥ h``
    variables, of which the ``h`` variables ``S = sel`` are solved for and the others are
    parameters (``I_S``: rows of the identity at ``S``; ``C ≈ J_S⁻¹``).  By the mean-value
    theorem every solution in ``X`` has its ``S`` coordinates in ``K(X)`` — the parametric
    Krawczyk operator (Neumaier 1990 §5.1; for ``n = h`` the square one).

    Midpoint-radius form (Rump, "Fast and parallel interval arithmetic", BIT 39, 1999):
    a point matrix times an interval matrix is ``C·[J_c ± J_r] = C J_c ± |C| J_r``
    exactly, so the products are float
    dot products, each bounded by the a-priori error ``γ_n = n u/(1 − n u)`` of an
    n-term dot product (Higham, *Accuracy and Stability*, Eq. 3.5), instead of n³
    outward-rounded interval operations.  ``X − y`` is enclosed in ``[−x_r, x_r]``, so
    ``M (X − y) ⊆ ±(|M_c| + M_r) x_r`` (exact for a symmetric vector).  A non-finite
    input leaves ``K(X)`` unbounded (no information)."""
    h, n = C.shape[0], y.size
    kl, kh = np.full(h, -np.inf), np.full(h, np.inf)
    g = (n + 2) * _U / (1.0 - (n + 2) * _U)  # γ_{n+2}: dot products of up to n+1 terms
    grow = 1.0 + 2.0 * g + 16.0 * _U  # x_exact ≤ x_float/(1 − γ) ≤ x_float(1 + 2γ), plus the bound's own roundings
    Jc, Jr = np.empty((h, n)), np.empty((h, n))
    for i in range(h):
        for j in range(n):
            Jc[i, j], Jr[i, j] = _mid_rad(Jl[i, j], Jh[i, j])
            if not (np.isfinite(Jc[i, j]) and np.isfinite(Jr[i, j])):
                return kl, kh
    xr = np.empty(n)
    for j in range(n):
        xr[j] = K.up(max(y[j] - lo[j], hi[j] - y[j]))
        if not np.isfinite(xr[j]):
            return kl, kh
    pc, pa, pr = np.empty(n), np.empty(n), np.empty(n)
    for i in range(h):
        # (C f(y))_i: centre and radius of a point row times the interval vector f(y)
        cf, ca, cr = 0.0, 0.0, 0.0
        for k in range(h):
            fc, fr = _mid_rad(fl[k], fh[k])
            cf += C[i, k] * fc
            ca += abs(C[i, k] * fc)
            cr += abs(C[i, k]) * fr
        # row i of M = I − C J(X) in midpoint-radius form, then |M| x_r; the sums over k
        # run in the same order for every j, the j loop innermost (contiguous, vectorised)
        pc[:], pa[:], pr[:] = 0.0, 0.0, 0.0
        for k in range(h):
            c = C[i, k]
            ac = abs(c)
            for j in range(n):
                p = c * Jc[k, j]
                pc[j] += p
                pa[j] += abs(p)
                pr[j] += ac * Jr[k, j]
        v = 0.0
        for j in range(n):
            mc = (1.0 if sel[i] == j else 0.0) - pc[j]
            mr = (pr[j] + g * pa[j]) * grow + 2.0 * _U * abs(mc)
            v += (abs(mc) + mr) * xr[j]
        kc = y[sel[i]] - cf
        kr = K.up((cr + g * ca + v) * grow + 2.0 * _U * abs(kc)) + _TINY
        if not (np.isfinite(kc) and np.isfinite(kr)):
            return np.full(h, -np.inf), np.full(h, np.inf)
        kl[i], kh[i] = K.down(kc - kr), K.up(kc + kr)
    return kl, kh


@njit(cache=True, fastmath=False)
def _diagonally_dominant(Sl: np.ndarray, Sh: np.ndarray) -> bool:
    """``m_S > M_S`` of Eqs. 3.28–3.29 (strict row diagonal dominance of an interval matrix)."""
    h = Sl.shape[0]
    m_s = np.inf
    M_s = 0.0
    for i in range(h):
        if Sl[i, i] <= 0.0 <= Sh[i, i]:
            return False
        m_s = min(m_s, min(abs(Sl[i, i]), abs(Sh[i, i])))
        row = 0.0
        for j in range(h):
            if j != i:
                row = K.up(row + max(abs(Sl[i, j]), abs(Sh[i, j])))
        M_s = max(M_s, row)
    return m_s > M_s


@dataclass(frozen=True)
class KrawczykResult(Result):
    """One Krawczyk step's verdict on a box (a frozen result, read-only arrays).

    Attributes
    ----------
    status : str
        ``"unique"`` (exactly one solution in the box), ``"empty"`` (none) or ``"unknown"``.
    lo, hi : ndarray, shape (n,)
        ``K(X) ∩ X``, which holds every solution of the box.
    """

    status: str  #: "unique" (exactly one solution in the box), "empty" (none), "unknown"
    lo: np.ndarray  #: K(X) ∩ X
    hi: np.ndarray


def krawczyk(system: System, lo: npt.ArrayLike, hi: npt.ArrayLike, *, points: int = 0) -> KrawczykResult:
    """One Krawczyk step on the box ``[lo, hi]``: ``K(X) ⊂ int X`` proves a unique solution in
    ``X``, ``K(X) ∩ X = ∅`` proves none (module docstring).

    With ``points > 0`` the slope enclosure of :mod:`taut.interval._slope` (that many nodes)
    replaces ``J(X)``: it proves more boxes empty and contracts more, but ``K(X) ⊂ int X``
    from slopes proves only that a solution exists, so such a box is tried again with
    ``J(X)``, which alone proves it unique.

    Parameters
    ----------
    system : System
    lo, hi : array_like, shape (n,)
    points : int, default 0
        Gauss–Legendre nodes of the slope enclosure (0: the Jacobian over the box).

    Returns
    -------
    KrawczykResult

    References
    ----------
    .. [1] R. Krawczyk, "Newton-Algorithmen zur Bestimmung von Nullstellen mit Fehlerschranken",
       Computing 4, 1969. (docs/references.bib: krawczyk1969)
    .. [2] A. Neumaier, "Interval Methods for Systems of Equations", Cambridge University Press,
       1990, §5.1. (docs/references.bib: neumaier1990)
    .. [3] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.1. (docs/references.bib: berti2015)

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> krawczyk(circles, [0.45, 0.8], [0.55, 0.9]).status, krawczyk(circles, [1.0, 1.0], [1.1, 1.1]).status
    ('unique', 'empty')
    """
    lo, hi = np.asarray(lo, float), np.asarray(hi, float)
    if points:
        res = _krawczyk_step(system, lo, hi, *_dense(system, *slopes(system, lo, hi, points)))
        if res.status != "unique":
            return res
    return _krawczyk_step(system, lo, hi, *jacobian(system, lo, hi))


def _dense(system: System, vl: np.ndarray, vh: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    Jl = np.zeros((system.n_equations, system.n))
    Jh = np.zeros((system.n_equations, system.n))
    Jl[system.rows, system.cols] = vl
    Jh[system.rows, system.cols] = vh
    return Jl, Jh


def _krawczyk_step(system: System, lo: np.ndarray, hi: np.ndarray, Jl: np.ndarray, Jh: np.ndarray) -> KrawczykResult:
    """:func:`krawczyk` with the matrix ``[Jl, Jh]`` (the Jacobian over the box or slopes)."""
    y = 0.5 * lo + 0.5 * hi
    try:
        C = np.linalg.inv(0.5 * Jl + 0.5 * Jh)
    except np.linalg.LinAlgError:
        return KrawczykResult("unknown", lo, hi)
    if not np.all(np.isfinite(C)):
        return KrawczykResult("unknown", lo, hi)
    fl, fh = evaluate(system.tape, y, y)
    h = system.n_equations
    kl, kh = krawczyk_image(C, y, fl[:h], fh[:h], Jl, Jh, lo, hi)
    nl, nh = np.maximum(kl, lo), np.minimum(kh, hi)
    if np.any(nl > nh):
        return KrawczykResult("empty", nl, nh)
    if np.all((kl > lo) & (kh < hi)):
        return KrawczykResult("unique", kl, kh)
    return KrawczykResult("unknown", nl, nh)


@njit(cache=True, fastmath=False)
def _krawczyk_box(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    h: int,
    jop: np.ndarray,
    ja: np.ndarray,
    jb: np.ndarray,
    jclo: np.ndarray,
    jchi: np.ndarray,
    jstart: np.ndarray,
    jend: np.ndarray,
    rows: np.ndarray,
    cols: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
) -> tuple[int, np.ndarray, np.ndarray]:
    """Numba twin of :func:`krawczyk`: ``(status, lo, hi)`` with
    status 0 unknown, 1 unique, 2 empty."""
    nj = jstart.size
    vl, vh = np.empty(nj), np.empty(nj)
    evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, lo, hi, vl, vh)
    return krawczyk_jacobian(op, a, b, clo, chi, start, end, h, rows, cols, vl, vh, lo, hi)


@njit(cache=True, fastmath=False)
def krawczyk_jacobian(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    h: int,
    rows: np.ndarray,
    cols: np.ndarray,
    vl: np.ndarray,
    vh: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
) -> tuple[int, np.ndarray, np.ndarray]:
    """Krawczyk test of the box ``[lo, hi]`` for the ``h`` equations that lead the tape
    ``(op, a, b, clo, chi, start, end)``, given the Jacobian's nonzero entries ``[vl, vh]``
    over the box (at ``rows, cols``), which the caller may use again: ``(status, lo', hi')``
    with status 0 unknown (``[lo', hi']`` the contracted box), 1 a unique zero in the
    Krawczyk image ``[lo', hi']``, 2 no zero in the box.  Compiled (:func:`_krawczyk_box` and
    the branch-and-prune loop call it)."""
    n = lo.size
    nj = rows.size
    Jl, Jh, Jm = np.zeros((h, n)), np.zeros((h, n)), np.zeros((h, n))
    for k in range(nj):
        Jl[rows[k], cols[k]], Jh[rows[k], cols[k]] = vl[k], vh[k]
    for i in range(h):
        for j in range(n):
            Jm[i, j] = 0.5 * Jl[i, j] + 0.5 * Jh[i, j]
    ok, C = float_inverse(Jm)
    if not ok:
        return 0, lo, hi
    y = 0.5 * lo + 0.5 * hi
    nodes = np.empty(op.size)
    nodeh = np.empty(op.size)
    fl, fh = np.empty(h), np.empty(h)
    forward_kernel(op, a, b, clo, chi, 0, end[h - 1], y, y, nodes, nodeh)  # the equations lead the tape
    for c in range(h):
        fl[c], fh[c] = nodes[end[c] - 1], nodeh[end[c] - 1]
    kl, kh = krawczyk_image(C, y, fl, fh, Jl, Jh, lo, hi)
    nl, nh = np.maximum(kl, lo), np.minimum(kh, hi)
    inner = True
    for i in range(n):
        if nl[i] > nh[i]:
            return 2, nl, nh
        if not (kl[i] > lo[i] and kh[i] < hi[i]):
            inner = False
    if inner:
        return 1, kl, kh
    return 0, nl, nh


@njit(cache=True, fastmath=False)
def tube_kernel(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    end: np.ndarray,
    g: int,
    gvars: np.ndarray,
    dependent: int,
    rows: np.ndarray,
    cols: np.ndarray,
    vl: np.ndarray,
    vh: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
) -> int:
    """Contract the box ``[lo, hi]`` (in place) onto the manifold of the tape's first ``g``
    equations, which involve only the ``k > g`` variables ``gvars``: the parametric
    Krawczyk operator (:func:`krawczyk_rows`) solves for the ``g`` of them that column-
    pivoted Gram–Schmidt on the midpoint Jacobian finds best conditioned, the other
    ``k − g`` are its parameters.  The first ``dependent ≤ g`` of ``gvars`` are always
    solved for: an auxiliary unknown that is a function of the others, such as the DGP's
    plane normal, makes a poor parameter (CoGiRo's cables 2, 3, 6, 7 take 107 069 boxes
    this way, 169 675 when the pivoting may make it one).  Where HC4 leaves a box as wide
    as the piece of the manifold it holds in every direction, this one shrinks it to that
    piece's hull once the equations are nearly linear over the box.  ``[vl, vh]``: the
    Jacobian's nonzero entries (at ``rows, cols``) over the box, or their slopes about its
    midpoint (:mod:`taut.interval._slope`).  Returns 2 when the box holds no point of the
    manifold, 1 when it shrank, 0 otherwise."""
    n, ng = lo.size, gvars.size
    pos = np.full(n, -1)
    for k in range(ng):
        pos[gvars[k]] = k
    Jl, Jh, M = np.zeros((g, ng)), np.zeros((g, ng)), np.zeros((g, ng))
    for k in range(rows.size):
        if rows[k] < g:
            Jl[rows[k], pos[cols[k]]], Jh[rows[k], pos[cols[k]]] = vl[k], vh[k]
            M[rows[k], pos[cols[k]]] = 0.5 * vl[k] + 0.5 * vh[k]
    glo, ghi, y = np.empty(ng), np.empty(ng), np.empty(ng)
    x = lo.copy()  # the other variables do not occur in the first g equations
    for k in range(ng):
        glo[k], ghi[k] = lo[gvars[k]], hi[gvars[k]]
        y[k] = 0.5 * glo[k] + 0.5 * ghi[k]
        x[gvars[k]] = y[k]
        if not np.isfinite(y[k]):
            return 0
    Q = M.T.copy()  # the columns as contiguous rows, with their squared norms
    nrm = np.zeros(ng)
    for j in range(ng):
        for i in range(g):
            nrm[j] += Q[j, i] * Q[j, i]
    chosen = np.zeros(ng, np.bool_)
    sel = np.empty(g, np.int64)
    first = 0.0
    for s in range(g):
        best, bn = -1, 0.0
        for j in range(ng if s >= dependent else dependent):
            if not chosen[j] and nrm[j] > bn:
                best, bn = j, nrm[j]
        if s == 0:
            first = bn
        if best < 0 or not (bn > 1e-20 * first) or not np.isfinite(bn):
            return 0
        chosen[best] = True
        sel[s] = best
        for j in range(ng):  # the other columns' components along the chosen one go
            if not chosen[j]:
                d = 0.0
                for i in range(g):
                    d += Q[best, i] * Q[j, i]
                r = 0.0
                for i in range(g):
                    Q[j, i] -= d / bn * Q[best, i]
                    r += Q[j, i] * Q[j, i]
                nrm[j] = r
    Ms = np.empty((g, g))
    for i in range(g):
        for s in range(g):
            Ms[i, s] = M[i, sel[s]]
    ok, C = float_inverse(Ms)
    if not ok:
        return 0
    nodes, nodeh = np.empty(end[g - 1]), np.empty(end[g - 1])
    forward_kernel(op, a, b, clo, chi, 0, end[g - 1], x, x, nodes, nodeh)  # the equations lead the tape
    fl, fh = np.empty(g), np.empty(g)
    for c in range(g):
        fl[c], fh[c] = nodes[end[c] - 1], nodeh[end[c] - 1]
    kl, kh = krawczyk_rows(C, sel, y, fl, fh, Jl, Jh, glo, ghi)
    status = 0
    for i in range(g):
        v = gvars[sel[i]]
        if kl[i] > lo[v]:
            lo[v], status = kl[i], 1
        if kh[i] < hi[v]:
            hi[v], status = kh[i], 1
        if lo[v] > hi[v]:
            return 2
    return status


@njit(cache=True, fastmath=False)
def certified_step(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    h: int,
    jop: np.ndarray,
    ja: np.ndarray,
    jb: np.ndarray,
    jclo: np.ndarray,
    jchi: np.ndarray,
    jstart: np.ndarray,
    jend: np.ndarray,
    rows: np.ndarray,
    cols: np.ndarray,
    x0: np.ndarray,
    margin: float,
    floor: float,
    tol: float,
    max_iter: int,
    inflations: int,
) -> tuple[int, np.ndarray, np.ndarray, np.ndarray]:
    """Newton from ``x0``, then Krawczyk on the box around the limit ``x`` whose half-width covers
    the step, ``margin·|x − x₀| + floor·max(1, ‖x‖∞) + ‖x − x₀‖∞²`` per component, widened
    ``inflations`` times to the Krawczyk hull (ε-inflation, Rump 1983): the tracking update of
    :mod:`taut.dgp._tracking`, compiled and called from its compiled code (hence the flat tape
    arguments).

    Parameters
    ----------
    op, a, b, clo, chi, start, end : ndarray
        The equations' tape (``System.tape.arrays[:7]``).
    h : int
        Number of equations.
    jop, ja, jb, jclo, jchi, jstart, jend : ndarray
        The Jacobian's tape.
    rows, cols : ndarray of int
        Where the Jacobian's entries go.
    x0 : ndarray, shape (n,)
    margin, floor : float
        Of the box's half-width (above).
    tol : float
        Newton's convergence tolerance, relative.
    max_iter : int
        Newton steps.
    inflations : int
        Krawczyk tries, each on the hull of the last.

    Returns
    -------
    status : int
        1: ``[lo, hi]`` holds exactly one solution, ``x``; 2: the box holds none; 0: undecided;
        −1: Newton failed.
    x : ndarray, shape (n,)
    lo, hi : ndarray, shape (n,)

    References
    ----------
    .. [1] S. M. Rump, "Solving algebraic problems with high accuracy", in U. Kulisch,
       W. L. Miranker (eds.), A New Approach to Scientific Computation, Academic Press, 1983.
       (docs/references.bib: rump1983)

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> s = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> status, x1, lo, hi = certified_step(
    ...     *s.tape.arrays[:7], s.n_equations, *s.jacobian.arrays[:7], s.rows, s.cols,
    ...     np.array([0.49, 0.87]), 2.0, 1e-12, 1e-13, 30, 3,
    ... )
    >>> status, x1
    (1, array([0.5      , 0.8660254]))
    """
    n = x0.size
    x = x0.copy()
    f = np.empty(h)
    jv = np.empty(jstart.size)
    converged = False
    for _ in range(max_iter):
        point_kernel(op, a, b, clo, chi, start[:h], end[:h], x, f)
        point_kernel(jop, ja, jb, jclo, jchi, jstart, jend, x, jv)
        J = np.zeros((h, n))
        for k in range(jv.size):
            J[rows[k], cols[k]] = jv[k]
        ok, C = float_inverse(J)
        if not ok:
            return -1, x, x, x
        dx = C @ f
        big, size = 0.0, 1.0
        for i in range(n):
            if not np.isfinite(dx[i]):
                return -1, x, x, x
            x[i] -= dx[i]
            big = max(big, abs(dx[i]))
            size = max(size, abs(x[i]))
        if big <= tol * size:
            converged = True
            break
    if not converged:
        return -1, x, x, x
    step = np.abs(x - x0)
    r = margin * step + floor * max(1.0, np.max(np.abs(x))) + np.max(step) ** 2
    status, rl, rh = 0, x, x
    for _ in range(inflations):
        status, rl, rh = _krawczyk_box(
            op, a, b, clo, chi, start, end, h, jop, ja, jb, jclo, jchi, jstart, jend, rows, cols, x - r, x + r
        )
        if status != 0:
            break
        r = np.maximum(r, 1.1 * np.maximum(rh - x, x - rl))
    return status, x, rl, rh


def inflate(system: System, x: npt.ArrayLike, *, delta: float = 1e-9, max_doublings: int = 60) -> float:
    """The half-width of the largest box ``x ± 2^k δ`` over which the Jacobian is proven regular
    (its preconditioned enclosure strictly diagonally dominant; Berti 2015, §3.2.1, Eqs.
    3.25–3.29): that box holds no other solution than ``x``.

    Parameters
    ----------
    system : System
    x : array_like, shape (n,)
        A solution (or a point near one).
    delta : float, default 1e-9
        The first half-width tried.
    max_doublings : int, default 60

    Returns
    -------
    float
        0 when even ``x ± δ`` fails.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.1, Eqs. 3.25–3.29. (docs/references.bib: berti2015)

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> inflate(circles, [0.5, np.sqrt(3) / 2])
    0.134217728
    """
    x = np.asarray(x, float)
    try:
        C = np.linalg.inv(jacobian_at(system, x))
    except np.linalg.LinAlgError:
        return 0.0
    best, d = 0.0, delta
    for _ in range(max_doublings):
        Jl, Jh = jacobian(system, x - d, x + d)
        Sl, Sh = precondition(C, Jl, Jh)
        if not _diagonally_dominant(Sl, Sh):
            break
        best, d = d, 2.0 * d
    return best


@dataclass(frozen=True)
class Certificate(Result):
    """A solution proven unique in a box (Krawczyk) and alone in a wider one (a frozen result,
    read-only arrays).

    Attributes
    ----------
    x : ndarray, shape (n,)
        The solution (Newton's limit).
    lo, hi : ndarray, shape (n,)
        A box proven to hold exactly one solution, ``x``.
    radius : float
        Half-width of the box ``x ± radius`` proven to hold no other solution
        (:func:`inflate`).

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> cert = certify(circles, [0.4, 0.8])
    >>> cert.x, cert.width < 1e-9, round(cert.radius, 3)
    (array([0.5      , 0.8660254]), True, 0.134)
    """

    x: np.ndarray
    lo: np.ndarray
    hi: np.ndarray
    radius: float

    @property
    def width(self) -> float:
        """Largest width of the box ``[lo, hi]``."""
        return float(np.max(self.hi - self.lo))

    def covers(self, lo: np.ndarray, hi: np.ndarray) -> bool:
        """Whether the box ``[lo, hi]`` lies in ``x ± radius``: it then holds no solution but ``x``.

        Parameters
        ----------
        lo, hi : ndarray, shape (n,)

        Returns
        -------
        bool
        """
        return bool(np.all(lo >= self.x - self.radius) and np.all(hi <= self.x + self.radius))


def certify(system: System, x0: npt.ArrayLike, *, scale: float = 1e-8) -> Certificate | None:
    """A certified solution near ``x0``: Newton from ``x0``, Krawczyk on a small box around its
    limit (widened until proven), then inflation of the uniqueness box.

    Parameters
    ----------
    system : System
    x0 : array_like, shape (n,)
    scale : float, default 1e-8
        Relative half-width of the first Krawczyk box.

    Returns
    -------
    Certificate or None
        None when Newton does not converge or no box is proven.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.2.1. (docs/references.bib: berti2015)

    Examples
    --------
    >>> from taut.interval import compile_system, variables
    >>> x, y = variables(2)
    >>> circles = compile_system(2, [x**2 + y**2 - 1, (x - 1) ** 2 + y**2 - 1])
    >>> certify(circles, [0.4, 0.8]).x
    array([0.5      , 0.8660254])
    >>> certify(circles, [0.5, 0.0]) is None
    True
    """
    x, ok = newton(system, x0)
    if not ok:
        return None
    r = scale * np.maximum(1.0, np.abs(x))
    for _ in range(8):
        res = krawczyk(system, x - r, x + r)
        if res.status == "unique":
            return Certificate(x, res.lo, res.hi, inflate(system, x))
        if res.status == "empty":
            return None
        r = 4.0 * r
    return None
