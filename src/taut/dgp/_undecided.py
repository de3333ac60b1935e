"""The boxes a certified search could not decide: where an equilibrium may hide that the
solutions do not list.  A result with any of them is incomplete, and says where.

Every box is an enclosure, in the solver's own unknowns, of the part of a sub-problem's
domain the search gave up on: any solution of that sub-problem with positive tensions that
the result does not list lies in one of its undecided boxes (one with a zero tension belongs
to the sub-problem of the other taut cables, :mod:`taut.dgp._solve`).  A box is left
undecided for one of five causes (:data:`CAUSES`): it became narrower than the bisection
threshold without being discarded or certified (a singular or nearly double solution; the
direct problem searches such boxes again in multi-precision, :mod:`taut.interval._precise`,
when python-flint is installed); it shrank to the multi-precision search's own limit (a
singular solution); it was still waiting when the box budget ran out; it holds a certified
solution whose tensions' signs could not be decided; or it holds a certified solution on the
search domain's bound that borders no other taut subset.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §3.1.4–3.2.1. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from taut._results import Result

if TYPE_CHECKING:
    from taut.dgp._formulation import Subproblem

#: Why a box is undecided: ``"narrow"`` — below the bisection threshold, neither discarded
#: nor certified in double precision (and not reached by the multi-precision search, which
#: needs python-flint and has a budget); ``"singular"`` — narrowed to ``2^-128`` (relative) in
#: 256-bit balls, still neither discarded nor certified: around a singular (double) solution,
#: or solutions closer than ``2^-64``; ``"budget"`` — not yet processed when the box budget
#: ran out; ``"tension-sign"`` — a certified solution whose tensions' signs are not decided;
#: ``"domain-border"`` — a certified solution straddling the search domain's bound where no
#: cable is slack at its length (not the border of two taut subsets).
CAUSES = ("narrow", "singular", "budget", "tension-sign", "domain-border")

#: The box budget of every sub-problem of the direct problem when none is given, shared by
#: its pieces: :data:`taut.interval.MAX_BOXES` for each of the up to 16 pieces (the budget
#: the published tables were reproduced with).  It bounds the time and memory of a search
#: that would not end (a continuum of solutions); the boxes left when it runs out are
#: undecided (``"budget"``).
MAX_SUBPROBLEM_BOXES = 32_000_000

#: Names of the reference-point unknowns of :mod:`taut.dgp._formulation`: the fixed-frame
#: coordinates of the three reference points, then the normal of their plane.
REFERENCE_UNKNOWNS = (*(f"q{i}_{c}" for i in (1, 2, 3) for c in "xyz"), "n_x", "n_y", "n_z")


def _bound(v: float) -> float | None:
    """A bound for JSON: an infinite one (an unbounded side) is ``None``."""
    return float(v) if math.isfinite(v) else None


@dataclass(frozen=True)
class UndecidedBox(Result):
    """One undecided box of a sub-problem: where a solution the result does not list may lie.

    Attributes
    ----------
    taut : tuple of int
        The sub-problem's taut cables (0-based).
    cause : str
        One of :data:`CAUSES`.
    variables : tuple of str
        Names of the pose unknowns: for the direct problem the fixed-frame coordinates
        ``q1_x … q3_z`` of the reference points (and the normal ``n_x, n_y, n_z =
        (q2 − q1) × (q3 − q1)``), the position ``x, y[, z]`` of a point mass; for the inverse problem the free position coordinates and
        the cosine and sine of each free angle.
    lo, hi : tuple of float
        The enclosure of the pose unknowns.
    tension_lo, tension_hi : tuple of float
        The enclosure of the taut cables' tensions [N], in the order of ``taut``.
    points : tuple of tuple of float
        Direct problem: the body-frame coordinates [m] of the reference points ``q1, q2,
        q3`` (a pose ``(p, R)`` puts them at ``p + R @ point``); empty otherwise.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.4–3.2.1. (docs/references.bib: berti2015)

    Examples
    --------
    A box budget too small for the inverse problem leaves boxes undecided:

    >>> from taut.dgp import solve_igp
    >>> from taut.model import example
    >>> res = solve_igp(example("suspended-3cable"), [0, 1, 2], {"x": 2.75, "y": 3.98, "z": 5.51}, max_boxes=50)
    >>> box = res.undecided_enclosures[0]
    >>> res.complete, box.cause, box.variables[:2]
    (False, 'budget', ('cos(a)', 'sin(a)'))
    """

    taut: tuple[int, ...]
    cause: str  #: one of :data:`CAUSES`
    variables: tuple[str, ...]
    lo: tuple[float, ...]
    hi: tuple[float, ...]
    tension_lo: tuple[float, ...]
    tension_hi: tuple[float, ...]
    points: tuple[tuple[float, float, float], ...] = ()

    def as_dict(self) -> dict:
        """The box in plain JSON types, ``None`` for an unbounded side: ``taut`` (0-based),
        ``cause``, ``enclosure`` (unknown name → ``[lo, hi]``), ``tensions`` (``[lo, hi]``
        per taut cable) and, for the direct problem, ``reference_points``."""
        d = {
            "taut": list(self.taut),
            "cause": self.cause,
            "enclosure": {name: [_bound(a), _bound(b)] for name, a, b in zip(self.variables, self.lo, self.hi)},
            "tensions": [[_bound(a), _bound(b)] for a, b in zip(self.tension_lo, self.tension_hi)],
        }
        if self.points:
            d["reference_points"] = [list(p) for p in self.points]
        return d


def cause_of(lo: np.ndarray, hi: np.ndarray, eps: float) -> str:
    """``"narrow"`` for a box branch-and-prune stopped bisecting (every side below ``eps``),
    ``"budget"`` for one it left unprocessed when its budget ran out."""
    return "narrow" if float(np.max(hi - lo)) < eps else "budget"


def scaled(t_lo: np.ndarray, t_hi: np.ndarray, scale: np.ndarray) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """The enclosure of ``t · scale`` (``scale > 0``) rounded outwards: the tensions of
    scaled-tension unknowns ``t = τ/ρ``."""
    lo = np.nextafter(np.asarray(t_lo, float) * scale, -np.inf)
    hi = np.nextafter(np.asarray(t_hi, float) * scale, np.inf)
    return tuple(lo.tolist()), tuple(hi.tolist())


def subproblem_box(sp: Subproblem, lengths: np.ndarray, lo: np.ndarray, hi: np.ndarray, cause: str) -> UndecidedBox:
    """The undecided box ``[lo, hi]`` of the direct problem's sub-problem ``sp`` at the cable
    ``lengths``.  With six taut cables the tensions are not unknowns: they are enclosed by
    the statics over the box, or unbounded when it has no enclosure there."""
    rho = np.asarray(lengths, float)[list(sp.taut)]
    k = sp.pose_unknowns
    if sp.tension_unknowns:
        t_lo, t_hi = lo[k:], hi[k:]
    else:
        enc = sp.statics.enclosure(lo, hi)
        t_lo, t_hi = enc if enc is not None else (np.full(rho.size, -np.inf), np.full(rho.size, np.inf))
    tension_lo, tension_hi = scaled(t_lo, t_hi, rho)
    return UndecidedBox(
        tuple(sp.taut),
        cause,
        getattr(sp, "names", REFERENCE_UNKNOWNS)[:k],  # a point mass's: its position
        tuple(lo[:k].tolist()),
        tuple(hi[:k].tolist()),
        tension_lo,
        tension_hi,
        tuple((float(x), float(y), float(z)) for x, y, z in sp.body_refs),
    )
