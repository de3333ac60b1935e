"""Branch-and-prune solver for square polynomial systems (``001_eb92e2f6589fc229.txt``
§1.3.3 Algorithm 1, with the bisection rule of §3.1.4 and the evaluation operator of
§3.2.1–3.2.2).

Each box popped from the list is

1. *filtered* (operator ``F``): HC4 contraction (:mod:`taut.interval.hc4`) of the
   equations and of the redundant constraints; boxes inside the uniqueness box of an
   already certified solution are dropped;
2. *evaluated* (operator ``E``): once the box is small, the Krawczyk operator is applied
   to it and Newton is started from its midpoint; a solution proven unique by Krawczyk
   is stored with the radius of its inflated uniqueness box (:mod:`taut.interval.krawczyk`);
3. *bisected*: the widest of the ``primary`` variables (the pose variables ``X``) while
   their largest width is at least ``eps``, then the widest variable of all (§3.1.4).

Boxes narrower than ``eps`` in every variable that could not be certified are returned as
``undecided`` (singular or nearly-coincident solutions): nothing is silently dropped.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from taut.interval.expression import System
from taut.interval.hc4 import contract, evaluate
from taut.interval.krawczyk import Certificate, certify, krawczyk


@dataclass
class BranchAndPruneResult:
    solutions: list[Certificate] = field(default_factory=list)
    undecided: list[tuple[np.ndarray, np.ndarray]] = field(default_factory=list)
    boxes: int = 0  #: boxes processed


def _bisect_index(width: np.ndarray, primary: np.ndarray, eps: float) -> int:
    wp = np.where(primary, width, -1.0)
    j = int(np.argmax(wp))
    if wp[j] >= eps:
        return j
    return int(np.argmax(width))


def _split(lo, hi, j):
    m = 0.5 * lo[j] + 0.5 * hi[j]
    if not np.isfinite(m):  # unbounded variable: split at a finite point
        m = max(2.0 * lo[j], 1.0) if np.isfinite(lo[j]) else (min(2.0 * hi[j], -1.0) if np.isfinite(hi[j]) else 0.0)
    a_hi = hi.copy()
    a_hi[j] = m
    b_lo = lo.copy()
    b_lo[j] = m
    return (lo, a_hi), (b_lo, hi.copy())


def branch_and_prune(
    system: System,
    lo,
    hi,
    *,
    primary=None,
    eps: float = 1e-7,
    certify_width: float = 0.5,
    newton_width: float = 1e-3,
    max_boxes: int = 2_000_000,
    filters=(),
) -> BranchAndPruneResult:
    """All solutions of ``system`` in the box ``[lo, hi]`` (see module docstring).

    ``primary`` (boolean mask) marks the variables bisected first; ``certify_width`` is
    the width of the primary variables below which the Krawczyk operator contracts a box,
    and Newton is started when Krawczyk proves uniqueness or the box is narrower than
    ``newton_width``;
    ``filters`` are extra contractors ``f(lo, hi) -> bool`` (in place, False = empty)
    applied after HC4.
    """
    lo0, hi0 = np.array(lo, float), np.array(hi, float)
    primary = np.ones(lo0.size, bool) if primary is None else np.asarray(primary, bool)
    out = BranchAndPruneResult()
    stack = [(lo0.copy(), hi0.copy())]
    while stack:
        lo, hi = stack.pop()
        out.boxes += 1
        if out.boxes > max_boxes:
            out.undecided.append((lo, hi))
            out.undecided.extend(stack)
            break
        if not contract(system.tape, lo, hi) or not all(f(lo, hi) for f in filters):
            continue
        if any(np.all(lo >= c.x - c.radius) and np.all(hi <= c.x + c.radius) for c in out.solutions):
            continue
        width = hi - lo
        if np.max(np.where(primary, width, 0.0)) < certify_width and np.all(np.isfinite(width)):
            # Krawczyk cannot prove K(X) ⊂ int X on a box HC4 shrank to a few ulps: widen it
            pad = np.maximum(1e-3 * width, 1e-10 * (1.0 + np.abs(lo) + np.abs(hi)))
            klo, khi = np.maximum(lo - pad, lo0), np.minimum(hi + pad, hi0)
            res = krawczyk(system, klo, khi)
            if res.status == "empty":
                continue
            unique = res.status == "unique"
            if unique or np.max(width) < newton_width:
                cert = certify(system, 0.5 * res.lo + 0.5 * res.hi)
                if cert is not None and np.all(cert.x >= klo) and np.all(cert.x <= khi):
                    if _admissible(system, cert, lo0, hi0) and not any(
                        np.all(np.abs(cert.x - c.x) <= max(c.radius, 1e-9)) for c in out.solutions
                    ):
                        out.solutions.append(cert)
                    if unique:
                        continue
                    if np.all(lo >= cert.x - cert.radius) and np.all(hi <= cert.x + cert.radius):
                        continue
            lo, hi = np.maximum(lo, res.lo), np.minimum(hi, res.hi)
            if np.any(lo > hi):
                continue
            width = hi - lo
        if np.max(width) < eps:
            out.undecided.append((lo, hi))
            continue
        a, b = _split(lo, hi, _bisect_index(width, primary, eps))
        stack.append(b)
        stack.append(a)
    return out


def _admissible(system: System, cert: Certificate, lo0, hi0) -> bool:
    """The certified box lies in the search domain and satisfies the redundant constraints
    (a solution whose enclosure straddles a bound — e.g. a zero tension — is rejected: it
    belongs to the boundary, see :mod:`taut.dgp`)."""
    if np.any(cert.lo < lo0) or np.any(cert.hi > hi0):
        return False
    vl, vh = evaluate(system.tape, cert.lo, cert.hi)
    t, h = system.tape, system.n_equations
    vl, vh, bl, bh = vl[h:], vh[h:], t.blo[h:], t.bhi[h:]
    equality = bl == bh  # redundant equations: the solution satisfies them, the enclosure meets them
    inside = (vl >= bl) & (vh <= bh)
    meets = (vl <= bl) & (vh >= bh)
    return bool(np.all(np.where(equality, meets, inside)))
