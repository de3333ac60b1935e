"""Branch-and-prune solver for square polynomial systems (Berti (2015)
§1.3.3 Algorithm 1, with the bisection rule of §3.1.4 and the evaluation operator of
§3.2.1–3.2.2).

Each box popped from the list is

1. *filtered* (operator ``F``): HC4 contraction (:mod:`taut.interval._hc4`) of the
   equations and of the redundant constraints; boxes inside the uniqueness box of an
   already certified solution are dropped; when the leading equations are
   under-determined (``tube``), the box is contracted onto their solution manifold by
   the parametric Krawczyk operator;
2. *evaluated* (operator ``E``): once the box is small, the Krawczyk operator is applied
   to it and Newton is started from its midpoint; a solution proven unique by Krawczyk
   is stored with the radius of its inflated uniqueness box (:mod:`taut.interval._krawczyk`).
   Both Krawczyk steps use the slope enclosure of :mod:`taut.interval._slope` instead of
   the Jacobian over the box when the equations are polynomials of degree ≤ 4 (about half
   as wide, so boxes are proven empty wider); uniqueness is still proven with the
   Jacobian;
3. *bisected*: one of the ``primary`` variables (the pose variables ``X``) while their
   largest width is at least ``eps``, then the widest variable of all (§3.1.4); the
   primary variable is the widest one, or with ``bisection="smear"`` the one of largest
   relative smear (:func:`smear_scores`: the equations' sensitivity times the width), which the
   DGP uses because its reference points and tensions are scaled unevenly.

Boxes narrower than ``eps`` in every variable that could not be certified are returned as
``undecided`` (singular or nearly-coincident solutions): nothing is silently dropped.

The loop runs in a Numba kernel (:func:`_drive`, a depth-first stack of boxes) when the
filters are :class:`~taut.interval.LinearFilter` s; it hands a box back to Python
only to certify a solution (Newton, Krawczyk, inflation: a handful of calls per solution).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §1.3.3 (Algorithm 1), §3.1.4, §3.2.1–3.2.2.
   (docs/references.bib: berti2015)
.. [2] R. B. Kearfott, M. Novoa, "Algorithm 681: INTBIS, a portable interval Newton/bisection
   package", ACM Transactions on Mathematical Software 16(2), 1990.
   (docs/references.bib: kearfott1990)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import cast

import numpy as np
import numpy.typing as npt
from numba import njit

from taut.errors import ArgumentError
from taut.interval._expression import System
from taut.interval._hc4 import contract, contract_kernel, evaluate, evaluate_kernel
from taut.interval._krawczyk import Certificate, certify, krawczyk, krawczyk_jacobian, tube_kernel
from taut.interval._linear import LinearFilter, linear_filter_kernel
from taut.interval._slope import points_for, slope_kernel, slopes


@dataclass
class BranchAndPruneResult:
    solutions: list[Certificate] = field(default_factory=list)
    undecided: list[tuple[np.ndarray, np.ndarray]] = field(default_factory=list)
    #: solutions proven unique whose box straddles a bound of the domain or of a redundant
    #: inequality (e.g. a zero tension): neither inside nor outside at this precision
    boundary: list[Certificate] = field(default_factory=list)
    boxes: int = 0  #: boxes processed
    #: the budget ran out (boxes and certifications, see :func:`branch_and_prune`)
    exhausted: bool = False
    #: boxes discarded by each operator (compiled loop only) and the ``certifications`` tried
    stats: dict = field(default_factory=dict)


@njit(cache=True, fastmath=False)
def smear_scores(
    jop: np.ndarray,
    ja: np.ndarray,
    jb: np.ndarray,
    jclo: np.ndarray,
    jchi: np.ndarray,
    jstart: np.ndarray,
    jend: np.ndarray,
    rows: np.ndarray,
    cols: np.ndarray,
    h: int,
    lo: np.ndarray,
    hi: np.ndarray,
    primary: np.ndarray,
) -> np.ndarray:
    """Relative smear of each primary variable over the box: ``Σ_i s_ij / Σ_k s_ik`` with
    ``s_ij = mag(J_ij(X)) w(X_j)`` (Kearfott & Novoa 1990; "smearsumrel" of Ibex), the
    share of each equation's width that the variable is responsible for.  Zeros (no
    preference) when a smear is unbounded."""
    nj = jstart.size
    vl, vh = np.empty(nj), np.empty(nj)
    evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, lo, hi, vl, vh)
    return _smear_of(rows, cols, h, vl, vh, lo, hi, primary)


@njit(cache=True, fastmath=False)
def _smear_of(
    rows: np.ndarray,
    cols: np.ndarray,
    h: int,
    vl: np.ndarray,
    vh: np.ndarray,
    lo: np.ndarray,
    hi: np.ndarray,
    primary: np.ndarray,
) -> np.ndarray:
    """:func:`smear_scores` from the Jacobian's nonzero entries ``[vl, vh]`` (at ``rows, cols``)."""
    n, nj = lo.size, rows.size
    sm = np.zeros(nj)
    total = np.zeros(h)
    score = np.zeros(n)
    for k in range(nj):
        if primary[cols[k]]:
            sm[k] = max(abs(vl[k]), abs(vh[k])) * (hi[cols[k]] - lo[cols[k]])
            if not np.isfinite(sm[k]):
                return score
            total[rows[k]] += sm[k]
    for k in range(nj):
        if total[rows[k]] > 0.0:
            score[cols[k]] += sm[k] / total[rows[k]]
    return score


@njit(cache=True, fastmath=False)
def bisect_index(width: np.ndarray, primary: np.ndarray, eps: float, score: np.ndarray, starve: float) -> int:
    """The variable to bisect (§3.1.4): a primary one while the widest of them is at least
    ``eps`` — the one of largest ``score`` (:func:`smear_scores`) when any is positive, else the
    widest, or the widest when it is ``starve`` times wider than the score's pick — then the
    widest variable of all."""
    j, best = -1, -1.0
    for i in range(width.size):
        if primary[i] and width[i] > best:
            best, j = width[i], i
    if best < eps:
        return int(np.argmax(width))
    widest = j
    top = 0.0
    for i in range(width.size):
        if primary[i] and width[i] >= eps and score[i] > top:
            top, j = score[i], i
    if width[j] * starve < best:
        return widest
    return j


Box = tuple[np.ndarray, np.ndarray]


def bisect(
    lo: npt.ArrayLike,
    hi: npt.ArrayLike,
    *,
    primary: npt.ArrayLike | None = None,
    eps: float = 0.0,
    score: npt.ArrayLike | None = None,
    starve: float = np.inf,
) -> tuple[Box, Box]:
    """The two halves ``((lo, mid), (mid, hi))`` of the box ``[lo, hi]`` cut across the
    variable chosen by the bisection rule of the solver (§3.1.4): a ``primary`` one (all
    variables by default) while the widest of them is at least ``eps`` — the one of
    largest ``score`` when any is positive (e.g. the relative smear), else the widest, or the
    widest when it is ``starve`` times wider than the score's pick —
    then the widest variable of all.  The cut is at the midpoint, or at a finite point of
    an unbounded variable.  The halves are new arrays.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.4. (docs/references.bib: berti2015)
    """
    lo, hi = np.array(lo, float), np.array(hi, float)
    mask = np.ones(lo.size, bool) if primary is None else np.asarray(primary, bool)
    weights = np.zeros(lo.size) if score is None else np.asarray(score, float)
    j = bisect_index(hi - lo, mask, float(eps), weights, float(starve))
    a, b = float(lo[j]), float(hi[j])
    if np.isfinite(a) and np.isfinite(b):
        m = 0.5 * a + 0.5 * b
    else:  # unbounded variable: split at a finite point
        m = max(2.0 * a, 1.0) if np.isfinite(a) else (min(2.0 * b, -1.0) if np.isfinite(b) else 0.0)
    a_hi, b_lo = hi.copy(), lo.copy()
    a_hi[j] = b_lo[j] = m
    return (lo, a_hi), (b_lo, hi)


def branch_and_prune(
    system: System,
    lo: npt.ArrayLike,
    hi: npt.ArrayLike,
    *,
    primary: npt.ArrayLike | None = None,
    eps: float = 1e-7,
    certify_width: float = 0.5,
    newton_width: float = 1e-3,
    max_boxes: int = 2_000_000,
    filters: Sequence[Callable[[np.ndarray, np.ndarray], bool]] = (),
    method: str = "auto",
    passes: int = 1,
    gain: float = 0.2,
    ratio: float = 0.05,
    domain: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    bisection: str = "width",
    tube: int = 0,
    filter_width: float = np.inf,
    starve: float = np.inf,
    progress: Callable[[int, int | None], None] | None = None,
) -> BranchAndPruneResult:
    """All solutions of ``system`` in the box ``[lo, hi]`` (see module docstring).

    ``domain`` (``(lo, hi)``, default the box itself) is the whole search domain when
    ``[lo, hi]`` is one piece of it: a solution counts when its certified box lies in the
    domain, so a solution on the border between two pieces is kept by both (merge them
    with :func:`same_solution`).

    ``primary`` (boolean mask) marks the variables bisected first; ``certify_width`` is
    the width of the primary variables below which the Krawczyk operator contracts a box,
    and Newton is started when Krawczyk proves uniqueness or the box is narrower than
    ``newton_width``;
    ``filters`` are extra contractors ``f(lo, hi) -> bool`` (in place, False = empty)
    applied after HC4 to the boxes whose primary variables are narrower than
    ``filter_width`` (an interval linear solve fails on wide boxes: its cost buys nothing
    there).  ``bisection``: ``"width"`` bisects the widest primary variable
    (§3.1.4), ``"smear"`` the primary variable of largest relative smear
    (:func:`smear_scores`), which follows the variables the equations are most sensitive to
    when they are scaled unevenly; ``starve``: the smear rule gives way to the widest
    primary variable when that is ``starve`` times wider than the smear's pick — for
    primary variables in one unit, where the smear can keep cutting a few of them while
    another stays wide and every cut only trims a sliver (a random suspended robot, seed
    58, cables 1 and 3: 1.34 M boxes with the smear alone, 553 with ``starve=10``).  ``tube``: how many leading equations form an
    under-determined subsystem (fewer equations than the variables they involve: the
    DGP's rigidity and cable lengths); every box is then contracted onto its solution
    manifold by the parametric Krawczyk operator (:func:`taut.interval._krawczyk.tube_kernel`)
    after HC4 and the filters; it solves for the non-primary variables of those equations
    (at most ``tube`` of them) and for the best conditioned primary ones.

    ``method="numba"`` runs the box loop in a compiled kernel (:func:`_drive`) and returns
    to Python only to certify a solution; it needs every filter to be a
    :class:`~taut.interval.LinearFilter`.  ``"python"`` is the reference loop (any
    filter); ``"auto"`` picks ``"numba"`` when it can.  With ``passes=1`` both run the same
    algorithm (box counts may differ by a few: the preconditioners are inverted by
    different float routines).  With ``passes > 1`` the compiled loop repeats
    HC4 → filter → Krawczyk narrowing on a box while Krawczyk shrinks its widest
    primary variable by more than the fraction ``gain`` (a fixpoint of the contractors
    before bisecting); ``ratio`` is the HC4 stopping threshold of
    :func:`taut.interval.contract` in the compiled loop.  The result's ``stats`` count
    the boxes each operator discarded (compiled loop only) and the certifications tried.

    ``max_boxes`` bounds the work: every box processed counts one, every certification
    (Newton and Krawczyk in Python) :data:`CERTIFY_BOXES`; the boxes left when it runs out
    are returned as ``undecided``.

    ``progress(boxes, None)`` is called every :data:`PROGRESS_BOXES` boxes processed (the
    total is unknown until the end), and ``progress(boxes, boxes)`` once the search is done.

    Raises :class:`~taut.errors.ArgumentError` for an unknown ``method`` or ``bisection``,
    filters the compiled loop cannot run with ``method="numba"``, a start box or ``primary``
    of the wrong size, a box outside ``domain``, or a ``tube`` that is not under-determined.
    """
    kernel_ok = all(isinstance(f, LinearFilter) for f in filters) and len(filters) <= 1
    if method not in ("auto", "numba", "python"):
        raise ArgumentError(f"method must be 'auto', 'numba' or 'python', got {method!r}")
    if method == "numba" and not kernel_ok:
        raise ArgumentError("method='numba' takes at most one filter, a LinearFilter")
    if bisection not in ("width", "smear"):
        raise ArgumentError(f"bisection must be 'width' or 'smear', got {bisection!r}")
    _start_box(system, lo, hi, primary)
    smear = bisection == "smear"
    if method != "python" and kernel_ok:
        return _branch_and_prune_numba(
            system,
            lo,
            hi,
            primary,
            eps,
            certify_width,
            newton_width,
            max_boxes,
            filters,
            passes,
            gain,
            ratio,
            domain,
            smear,
            tube,
            filter_width,
            starve,
            progress,
        )
    lo0, hi0 = _domain(lo, hi, domain)
    primary = np.ones(lo0.size, bool) if primary is None else np.asarray(primary, bool)
    jac = (*system.jacobian.arrays[:7], system.rows, system.cols, system.n_equations)
    tube_vars, dependent = tube_variables(system, tube, primary)
    tube_points, krawczyk_points = _slope_points(system, tube), _slope_points(system, system.n_equations)
    out = BranchAndPruneResult()
    stack = [(np.array(lo, float), np.array(hi, float))]
    certifications = 0
    while stack:
        lo, hi = stack.pop()
        out.boxes += 1
        if progress is not None and out.boxes % PROGRESS_BOXES == 0:
            progress(out.boxes, None)
        if out.boxes + CERTIFY_BOXES * certifications > max_boxes:
            out.undecided.append((lo, hi))
            out.undecided.extend(stack)
            out.exhausted = True
            break
        if not contract(system.tape, lo, hi):
            continue
        if _primary_width(lo, hi, primary) < filter_width and not all(f(lo, hi) for f in filters):
            continue
        if any(c.covers(lo, hi) for c in out.solutions + out.boundary):
            continue
        if tube:
            vl, vh = slopes(system, lo, hi, tube_points)
            if (
                tube_kernel(
                    *system.tape.arrays[:5],
                    system.tape.end,
                    tube,
                    tube_vars,
                    dependent,
                    system.rows,
                    system.cols,
                    vl,
                    vh,
                    lo,
                    hi,
                )
                == 2
            ):
                continue
        width = hi - lo
        if _primary_width(lo, hi, primary) < certify_width and np.all(np.isfinite(width)):
            klo, khi = _pad(lo, hi)
            res = krawczyk(system, klo, khi, krawczyk_points)
            if res.status == "empty":
                continue
            unique = res.status == "unique"
            if unique or np.max(width) < newton_width:
                certifications += 1
                cert = certify(system, 0.5 * res.lo + 0.5 * res.hi)
                if cert is not None and np.all(cert.x >= klo) and np.all(cert.x <= khi):
                    file_certificate(system, cert, lo0, hi0, out)
                    if unique:
                        continue
                    if cert.covers(lo, hi):
                        continue
            # casts: numpy types the ufuncs' result Any, which would widen lo, hi back to ArrayLike
            lo, hi = cast(np.ndarray, np.maximum(lo, res.lo)), cast(np.ndarray, np.minimum(hi, res.hi))
            if np.any(lo > hi):
                continue
            width = hi - lo
        if np.max(width) < eps:
            out.undecided.append((lo, hi))
            continue
        score = smear_scores(*jac, lo, hi, primary) if smear else None
        a, b = bisect(lo, hi, primary=primary, eps=eps, score=score, starve=starve)
        stack.append(b)
        stack.append(a)
    out.stats = {"certifications": certifications}
    if progress is not None:
        progress(out.boxes, out.boxes)
    return _drop_covered(out)


@njit(cache=True, fastmath=False)
def _primary_width(lo: np.ndarray, hi: np.ndarray, primary: np.ndarray) -> float:
    w = 0.0
    for i in range(lo.size):
        if primary[i] and hi[i] - lo[i] > w:
            w = hi[i] - lo[i]
    return w


@njit(cache=True, fastmath=False)
def _pad(lo: np.ndarray, hi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The box widened by 0.1 % of its widths (at least ~1e-10 relative): Krawczyk cannot
    prove ``K(X) ⊂ int X`` on a box HC4 shrank to a few ulps.  Not clipped to the search
    domain: a solution on the domain's border (a zero tension) is then proven unique in the
    padded box and filed by :func:`file_certificate` as inside, outside or on the boundary, instead of
    being left undecided at ``eps``."""
    klo, khi = np.empty(lo.size), np.empty(lo.size)
    for i in range(lo.size):
        pad = max(1e-3 * (hi[i] - lo[i]), 1e-10 * (1.0 + abs(lo[i]) + abs(hi[i])))
        klo[i] = lo[i] - pad
        khi[i] = hi[i] + pad
    return klo, khi


# Return codes of :func:`_drive`.
_DONE, _CERTIFY, _UNDECIDED, _MAX_BOXES, _STACK_FULL, _PAUSE = range(6)

#: Boxes between two calls of ``progress`` in :func:`branch_and_prune` (the compiled loop
#: hands back to Python for each: about a millisecond of boxes or more).
PROGRESS_BOXES = 1000

#: Boxes of the budget ``max_boxes`` a certification costs: Newton, Krawczyk and inflation
#: run in Python, 1.5–3.5 ms against 60–80 µs for a box of the compiled loop (the suspended
#: robot of Berti 2015, Table 4.3), so that the budget bounds the time also where nearly
#: every box is a candidate (lengths at the limit of double precision, a continuum).
CERTIFY_BOXES = 32


@njit(cache=True, fastmath=False)
def _drive(
    op: np.ndarray,
    a: np.ndarray,
    b: np.ndarray,
    clo: np.ndarray,
    chi: np.ndarray,
    start: np.ndarray,
    end: np.ndarray,
    blo: np.ndarray,
    bhi: np.ndarray,
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
    fop: np.ndarray,
    fa: np.ndarray,
    fb: np.ndarray,
    fclo: np.ndarray,
    fchi: np.ndarray,
    fstart: np.ndarray,
    fend: np.ndarray,
    fm: int,
    fsign: bool,
    stk_lo: np.ndarray,
    stk_hi: np.ndarray,
    sp: int,
    sol_x: np.ndarray,
    sol_r: np.ndarray,
    nsol: int,
    lo0: np.ndarray,
    primary: np.ndarray,
    eps: float,
    certify_width: float,
    newton_width: float,
    max_boxes: int,
    boxes: int,
    out: np.ndarray,
    passes: int,
    gain: float,
    ratio: float,
    stats: np.ndarray,
    smear: bool,
    tube_g: int,
    tube_vars: np.ndarray,
    dependent: int,
    tube_points: int,
    krawczyk_points: int,
    filter_width: float,
    starve: float,
    pause_at: int,
) -> tuple[int, int, int, bool]:
    """The loop of :func:`branch_and_prune` on the stack ``stk_lo[:sp], stk_hi[:sp]``
    until a box needs Python (a certification, an undecided box, the box budget, a full
    stack) or ``pause_at`` boxes are processed (to report progress).  Returns
    ``(code, sp, boxes, unique)``; ``out`` rows hold the box, the Krawczyk box and the
    Krawczyk result (code ``_CERTIFY``)."""
    n = lo0.size
    cap = stk_lo.shape[0]
    jl, jh = np.empty(jstart.size), np.empty(jstart.size)
    while sp > 0:
        if boxes >= pause_at:
            return _PAUSE, sp, boxes, False
        sp -= 1
        lo = stk_lo[sp].copy()
        hi = stk_hi[sp].copy()
        boxes += 1
        if boxes > max_boxes:
            return _MAX_BOXES, sp + 1, boxes, False
        dead = False
        cert = False
        unique = False
        have_j = False
        klo, khi, rl, rh = lo, hi, lo, hi
        jlo, jhi = lo, hi
        for _ in range(passes):
            if not contract_kernel(op, a, b, clo, chi, start, end, blo, bhi, lo, hi, ratio, 50):
                stats[0] += 1
                dead = True
                break
            # the tensions it bounds reach the equilibrium equations at the next pass's HC4 (a
            # second HC4 right after it cost more than it pruned: 0.3 % of boxes)
            if (
                fm > 0
                and _primary_width(lo, hi, primary) < filter_width
                and not linear_filter_kernel(fop, fa, fb, fclo, fchi, fstart, fend, fm, fsign, lo, hi)
            ):
                stats[1] += 1
                dead = True
                break
            for s in range(nsol):
                inside = True
                for i in range(n):
                    if not (lo[i] >= sol_x[s, i] - sol_r[s] and hi[i] <= sol_x[s, i] + sol_r[s]):
                        inside = False
                        break
                if inside:
                    stats[2] += 1
                    dead = True
                    break
            if dead:
                break
            width = hi - lo
            wp = 0.0
            finite = True
            for i in range(n):
                if not np.isfinite(width[i]):
                    finite = False
                if primary[i] and width[i] > wp:
                    wp = width[i]
            narrowed = False
            padded = False  # jl, jh hold the Jacobian over the box padded for Krawczyk
            if tube_g > 0:
                if tube_points > 0:
                    # slopes hold about the box's own centre: they serve this step alone
                    slope_kernel(jop, ja, jb, jclo, jchi, jstart, jend, lo, hi, tube_points, jl, jh)
                elif wp < certify_width and finite:
                    # over the padded box, the Jacobian also serves Krawczyk on the padded
                    # contracted box (clipped to this one): one evaluation for both
                    jlo, jhi = _pad(lo, hi)
                    evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, jlo, jhi, jl, jh)
                    padded = True
                else:
                    evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, lo, hi, jl, jh)
                have_j = True
                stats[6] += 1
                status = tube_kernel(op, a, b, clo, chi, end, tube_g, tube_vars, dependent, rows, cols, jl, jh, lo, hi)
                if status == 2:
                    stats[7] += 1
                    dead = True
                    break
                if status == 1:
                    wp2 = 0.0
                    for i in range(n):
                        width[i] = hi[i] - lo[i]
                        if primary[i]:
                            wp2 = max(wp2, width[i])
                    narrowed = wp2 < (1.0 - gain) * wp
                    wp = wp2
            if not (wp < certify_width and finite):
                if narrowed:
                    continue
                break
            klo, khi = _pad(lo, hi)
            if padded:
                klo, khi = np.maximum(klo, jlo), np.minimum(khi, jhi)
            elif krawczyk_points > 0:
                slope_kernel(jop, ja, jb, jclo, jchi, jstart, jend, klo, khi, krawczyk_points, jl, jh)
            else:
                evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, klo, khi, jl, jh)
            status, rl, rh = krawczyk_jacobian(op, a, b, clo, chi, start, end, h, rows, cols, jl, jh, klo, khi)
            if status == 1 and krawczyk_points > 0:  # (never padded: that needs degree > 4)
                # slopes exclude and contract; only the Jacobian proves a solution unique
                evaluate_kernel(jop, ja, jb, jclo, jchi, jstart, jend, klo, khi, jl, jh)
                status, rl, rh = krawczyk_jacobian(op, a, b, clo, chi, start, end, h, rows, cols, jl, jh, klo, khi)
            have_j = True
            stats[5] += 1
            if status == 2:
                stats[3] += 1
                dead = True
                break
            if status == 1 or np.max(width) < newton_width:
                cert, unique = True, status == 1
                break
            wp2 = 0.0
            for i in range(n):
                lo[i] = max(lo[i], rl[i])
                hi[i] = min(hi[i], rh[i])
                if lo[i] > hi[i]:
                    dead = True
                if primary[i]:
                    wp2 = max(wp2, hi[i] - lo[i])
            width = hi - lo
            if dead or (wp2 > (1.0 - gain) * wp and not narrowed):  # narrowed little: bisect
                break
        if dead:
            continue
        if cert:
            out[0], out[1], out[2], out[3], out[4], out[5] = lo, hi, klo, khi, rl, rh
            return _CERTIFY, sp, boxes, unique
        if np.max(width) < eps:
            out[0], out[1] = lo, hi
            return _UNDECIDED, sp, boxes, False
        if sp + 2 > cap:
            stk_lo[sp], stk_hi[sp] = lo, hi
            return _STACK_FULL, sp + 1, boxes - 1, False
        # bisection rule of §3.1.4 (as bisect); the smear reuses the Jacobian of the last
        # Krawczyk step, taken over a box a little wider than this one
        if smear and have_j:
            score = _smear_of(rows, cols, h, jl, jh, lo, hi, primary)
        elif smear:
            score = smear_scores(jop, ja, jb, jclo, jchi, jstart, jend, rows, cols, h, lo, hi, primary)
        else:
            score = np.zeros(n)
        j = bisect_index(width, primary, eps, score, starve)
        m = 0.5 * lo[j] + 0.5 * hi[j]
        if not np.isfinite(m):
            if np.isfinite(lo[j]):
                m = max(2.0 * lo[j], 1.0)
            elif np.isfinite(hi[j]):
                m = min(2.0 * hi[j], -1.0)
            else:
                m = 0.0
        stats[4] += 1
        stk_lo[sp], stk_hi[sp] = lo, hi
        stk_lo[sp, j] = m
        stk_lo[sp + 1], stk_hi[sp + 1] = lo, hi
        stk_hi[sp + 1, j] = m
        sp += 2
    return _DONE, sp, boxes, False


def tube_variables(system: System, tube: int, primary: np.ndarray) -> tuple[np.ndarray, int]:
    """The variables of the first ``tube`` equations (see :func:`branch_and_prune`), the
    non-primary ones first, and how many of them lead (the tube step solves for them: a
    variable that is not bisected is a function of the primary ones)."""
    if not 0 <= tube < system.n_equations:
        raise ArgumentError(f"tube must be between 0 and {system.n_equations - 1}, got {tube}")
    used = np.unique(system.cols[system.rows < tube])
    if tube and used.size <= tube:
        raise ArgumentError(f"the first {tube} equations involve {used.size} variables: not under-determined")
    dependent = used[~primary[used]]
    if dependent.size > tube:
        raise ArgumentError(
            f"the first {tube} equations involve {dependent.size} non-primary variables: they cannot all be solved for"
        )
    return np.concatenate([dependent, used[primary[used]]]).astype(np.int64), int(dependent.size)


def _slope_points(system: System, k: int) -> int:
    """Gauss–Legendre nodes of the slope enclosure of the first ``k`` equations, by their
    degree (:func:`taut.interval._slope.points_for`; 0, the Jacobian over the box, when
    ``k`` is 0): the tube step's, and with ``k = h`` the Krawczyk step's."""
    return points_for(int(np.max(system.degrees[:k]))) if k else 0


def _start_box(system: System, lo: npt.ArrayLike, hi: npt.ArrayLike, primary: npt.ArrayLike | None) -> None:
    """Raise :class:`~taut.errors.ArgumentError` unless ``[lo, hi]`` is a box of
    ``system.n`` variables without NaN (an empty one, ``lo > hi`` somewhere, holds no
    solution) and ``primary`` a mask of as many."""
    try:
        box = [np.asarray(lo, dtype=float), np.asarray(hi, dtype=float)]
    except (TypeError, ValueError):
        raise ArgumentError("the start box must be two arrays of numbers (lo, hi)") from None
    if any(b.shape != (system.n,) for b in box):
        raise ArgumentError(
            f"the start box needs {system.n} lower and upper bounds, got shapes {box[0].shape} and {box[1].shape}"
        )
    if np.isnan(box[0]).any() or np.isnan(box[1]).any():
        raise ArgumentError("the start box has NaN bounds")
    if primary is not None and np.shape(primary) != (system.n,):
        raise ArgumentError(f"primary must mark each of the {system.n} variables, got shape {np.shape(primary)}")


def _domain(
    lo: npt.ArrayLike, hi: npt.ArrayLike, domain: tuple[npt.ArrayLike, npt.ArrayLike] | None
) -> tuple[np.ndarray, np.ndarray]:
    if domain is None:
        return np.array(lo, float), np.array(hi, float)
    dlo, dhi = (np.array(d, float) for d in domain)
    if np.any(np.asarray(lo, float) < dlo) or np.any(np.asarray(hi, float) > dhi):
        raise ArgumentError("the start box must lie in the search domain")
    return dlo, dhi


def same_solution(a: Certificate, b: Certificate) -> bool:
    """``b`` is the solution certified by ``a``: it lies in ``a``'s box, which holds one."""
    return bool(np.all(b.x >= a.lo) and np.all(b.x <= a.hi)) or bool(np.all(np.abs(a.x - b.x) <= a.radius))


def _branch_and_prune_numba(
    system: System,
    lo: npt.ArrayLike,
    hi: npt.ArrayLike,
    primary: npt.ArrayLike | None,
    eps: float,
    certify_width: float,
    newton_width: float,
    max_boxes: int,
    filters: Sequence[Callable[[np.ndarray, np.ndarray], bool]],
    passes: int,
    gain: float,
    ratio: float,
    domain: tuple[npt.ArrayLike, npt.ArrayLike] | None,
    smear: bool,
    tube: int,
    filter_width: float,
    starve: float,
    progress: Callable[[int, int | None], None] | None,
) -> BranchAndPruneResult:
    lo0, hi0 = _domain(lo, hi, domain)
    n = lo0.size
    primary = np.ones(n, bool) if primary is None else np.asarray(primary, bool)
    out = BranchAndPruneResult()
    t, jt = system.tape, system.jacobian
    t_jac = (*jt.arrays[:7], system.rows, system.cols, system.n_equations)
    if filters:
        f = filters[0]
        assert isinstance(f, LinearFilter)  # the caller runs this loop only with LinearFilters
        ftape, fm, fsign = f.tape.arrays[:7], f.m, f.sign_only
    else:
        ftape, fm, fsign = jt.arrays[:7], 0, False
    cap = 4096
    stk_lo, stk_hi = np.empty((cap, n)), np.empty((cap, n))
    stk_lo[0], stk_hi[0] = lo, hi
    sp, boxes = 1, 0
    sol_x, sol_r = np.zeros((0, n)), np.zeros(0)
    buf = np.empty((6, n))
    stats = np.zeros(8, np.int64)
    tube_vars, dependent = tube_variables(system, tube, primary)
    tube_points, krawczyk_points = _slope_points(system, tube), _slope_points(system, system.n_equations)
    never = np.iinfo(np.int64).max
    pause_at = PROGRESS_BOXES if progress is not None else never
    certifications = 0

    def push(blo: np.ndarray, bhi: np.ndarray) -> None:
        nonlocal sp, stk_lo, stk_hi
        if sp >= stk_lo.shape[0]:
            stk_lo = np.concatenate([stk_lo, np.empty_like(stk_lo)])
            stk_hi = np.concatenate([stk_hi, np.empty_like(stk_hi)])
        stk_lo[sp], stk_hi[sp] = blo, bhi
        sp += 1

    while True:
        code, sp, boxes, unique = _drive(
            *t.arrays,
            system.n_equations,
            *jt.arrays[:7],
            system.rows,
            system.cols,
            *ftape,
            fm,
            fsign,
            stk_lo,
            stk_hi,
            sp,
            sol_x,
            sol_r,
            len(sol_r),
            lo0,
            primary,
            float(eps),
            float(certify_width),
            float(newton_width),
            int(max_boxes) - CERTIFY_BOXES * certifications,
            boxes,
            buf,
            int(passes),
            float(gain),
            float(ratio),
            stats,
            smear,
            int(tube),
            tube_vars,
            dependent,
            tube_points,
            krawczyk_points,
            float(filter_width),
            float(starve),
            pause_at,
        )
        if code == _DONE:
            break
        if code == _PAUSE:
            assert progress is not None, "the loop pauses only to report progress"
            progress(boxes, None)
            pause_at = boxes + PROGRESS_BOXES
            continue
        if code == _MAX_BOXES:
            out.undecided.extend((stk_lo[i].copy(), stk_hi[i].copy()) for i in range(sp))
            out.exhausted = True
            break
        if code == _STACK_FULL:
            stk_lo = np.concatenate([stk_lo, np.empty_like(stk_lo)])
            stk_hi = np.concatenate([stk_hi, np.empty_like(stk_hi)])
            continue
        blo, bhi = buf[0].copy(), buf[1].copy()
        if code == _UNDECIDED:
            out.undecided.append((blo, bhi))
            continue
        # _CERTIFY: the Python tail of the evaluation operator, as in the reference loop
        klo, khi, rl, rh = buf[2].copy(), buf[3].copy(), buf[4].copy(), buf[5].copy()
        certifications += 1
        cert = certify(system, 0.5 * rl + 0.5 * rh)
        if cert is not None and np.all(cert.x >= klo) and np.all(cert.x <= khi):
            if file_certificate(system, cert, lo0, hi0, out):
                known = out.solutions + out.boundary
                sol_x = np.array([c.x for c in known])
                sol_r = np.array([c.radius for c in known])
            if unique:
                continue
            if cert.covers(blo, bhi):
                continue
        blo, bhi = np.maximum(blo, rl), np.minimum(bhi, rh)
        if np.any(blo > bhi):
            continue
        width = bhi - blo
        if np.max(width) < eps:
            out.undecided.append((blo, bhi))
            continue
        score = smear_scores(*t_jac, blo, bhi, primary) if smear else None
        (alo, ahi), (b2lo, b2hi) = bisect(blo, bhi, primary=primary, eps=eps, score=score, starve=starve)
        push(b2lo, b2hi)
        push(alo, ahi)
    out.boxes = boxes
    out.stats = dict(
        zip(
            ("hc4", "statics", "covered", "krawczyk_empty", "bisections", "krawczyk", "tube", "tube_empty"),
            stats.tolist(),
        )
    ) | {"certifications": certifications}
    if progress is not None:
        progress(boxes, boxes)
    return _drop_covered(out)


def _drop_covered(out: BranchAndPruneResult) -> BranchAndPruneResult:
    """Undecided boxes inside the uniqueness box ``x ± radius`` of a solution (or a boundary
    one) hold no other
    one: a box that reached ``eps`` beside a solution before that solution was certified
    (depth first, its neighbour may come later) is decided after all."""
    known = out.solutions + out.boundary
    out.undecided = [(lo, hi) for lo, hi in out.undecided if not any(c.covers(lo, hi) for c in known)]
    return out


def file_certificate(
    system: System, cert: Certificate, lo0: np.ndarray, hi0: np.ndarray, out: BranchAndPruneResult
) -> bool:
    """Add a new certified solution to ``out.solutions`` when its box lies in the search
    domain and satisfies the redundant constraints, to ``out.boundary`` when it straddles a
    bound of either (e.g. a zero tension: it may belong to a smaller subset, see
    :mod:`taut.dgp`); a box proven outside one of them holds no solution.  True when added."""
    if any(np.all(np.abs(cert.x - c.x) <= max(c.radius, 1e-9)) for c in out.solutions + out.boundary):
        return False
    if np.any(cert.hi < lo0) or np.any(cert.lo > hi0):
        return False
    vl, vh = evaluate(system.tape, cert.lo, cert.hi)
    t, h = system.tape, system.n_equations
    vl, vh, bl, bh = vl[h:], vh[h:], t.blo[h:], t.bhi[h:]
    equality = bl == bh  # redundant equations: the solution satisfies them, the enclosure meets them
    if np.any(np.where(equality, (vl > bl) | (vh < bh), (vl > bh) | (vh < bl))):
        return False
    inside = bool(np.all(np.where(equality, True, (vl >= bl) & (vh <= bh))))
    if inside and np.all(cert.lo >= lo0) and np.all(cert.hi <= hi0):
        out.solutions.append(cert)
    else:
        out.boundary.append(cert)
    return True
