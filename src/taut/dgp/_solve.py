"""All equilibria of an under-constrained robot for given cable lengths — the direct
geometrico-static problem (Berti 2015, Ch. 2–3).

:func:`solve_dgp` enumerates the taut subsets of ``m = 1 … min(n, 6, max_taut)`` cables
(Eq. 2.1), solves each one — ``m = 1`` in closed form (:mod:`taut.dgp._single_cable`),
``m ≥ 2`` by certified branch-and-prune on the reference-point system of
:mod:`taut.dgp._formulation` (for ``3 ≤ m ≤ 5`` every box is also contracted onto the pose
manifold of the rigidity and length equations, its ``geometry``) — through a
:mod:`taut.parallel` executor, and classifies every solution by the reduced Hessian
(:mod:`taut.dgp._stability`).  A point mass, spatial or planar, hangs on subsets of up to
``d`` cables, each a square system of :mod:`taut.dgp._point_mass` solved the same way (one
taut cable included: a point, not a continuum).  An equilibrium on the border of two taut subsets — a
cable at its length with zero tension, so that its certified box straddles the bound of
one subset's tension or of the other's slack-cable inequality — is reported once, with the
smaller subset as ``taut`` and the larger as ``boundary``: at the certificate's precision it
solves one of the two.  A point mass has at most one equilibrium position
(:mod:`taut.dgp._point_mass`): when more than ``d`` of its cables are at their lengths there,
several taut subsets, none inside another, balance the load (a statically indeterminate
equilibrium), and they are reported as one solution — :func:`merge_point_mass`.  Boxes double precision leaves too narrow to split (two equilibria
about to merge) are searched again in 256-bit balls (:mod:`taut.interval._precise`).

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, Chs. 2–3 (Eq. 2.1), §4.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass, replace
from itertools import combinations
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count, as_number
from taut._results import Result, freeze, jsonable
from taut.dgp import _planar
from taut.dgp._formulation import Subproblem, build_subproblem, load, refuse_unmodelled
from taut.dgp._point_mass import (
    LeastSquaresFit,
    build_point_mass,
    least_squares_fit,
    point_mass_load,
    point_mass_stable,
)
from taut.dgp._pulleys import cable_spans, check_pulley_reach, pulley_single_cable, pulley_stable, pulley_subproblem
from taut.dgp._single_cable import single_cable_equilibria
from taut.dgp._stability import is_stable
from taut.dgp._undecided import MAX_SUBPROBLEM_BOXES, UndecidedBox, cause_of, subproblem_box
from taut.errors import TautError
from taut.interval import (
    MAX_BOXES,
    Box,
    Certificate,
    bisect,
    branch_and_prune,
    contract,
    precise_available,
    same_solution,
    solve_precise,
)
from taut.model import Robot
from taut.parallel import Executor, as_executor

if TYPE_CHECKING:
    from distributed import Client


@dataclass(frozen=True)
class DGPSolution(Result):
    """One certified equilibrium of the direct geometrico-static problem.

    Attributes
    ----------
    taut : tuple of int
        The taut cables (0-based indices).
    position : ndarray, shape (d,)
        Platform reference point [m] (``d`` = 3 in space, 2 in the plane).
    orientation : ndarray, shape (3,), (1,) or (0,)
        Angles [rad] in the robot's orientation convention: ``(θ,)`` for a planar platform,
        none for a point mass.
    tensions : ndarray, shape (n,)
        Every cable's tension [N] (0 for slack ones).
    stable : bool
        The reduced Hessian is positive definite (:func:`is_stable`).
    certificate_width : float
        Width of the Krawczyk box proven to hold this solution (0 for one taut cable of a
        rigid platform).
    uniqueness_radius : float
        Half-width of the inflated box holding no other solution.
    continuum : tuple of float or None
        For one taut cable, the arc ``(ϑ_lo, ϑ_hi)`` of spins about the cable that are all
        equilibria (the solution is its middle).
    boundary : tuple of int or None
        A border equilibrium: the cables of ``boundary`` not in ``taut`` are at their
        lengths with zero tension, to within the certificate.  For a point mass, every cable
        at its length: when they are more than ``d``, the tensions are not unique —
        ``tensions`` is one distribution that balances the load, that of the first taut
        subset in canonical order (:func:`merge_point_mass`).

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, Ch. 2, Eq. 2.1. (docs/references.bib: berti2015)

    Examples
    --------
    The stable equilibrium of Table 4.3 of Berti (2015), tracked from the inverse problem's
    solution at its reference lengths:

    >>> import numpy as np
    >>> from taut.dgp import solve_igp, track_equilibrium
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> start = solve_igp(robot, [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061}).solutions[0]
    >>> s = track_equilibrium(robot, start, robot.reference.lengths)
    >>> s.taut, np.round(s.position, 3), np.round(s.tensions, 3)
    ((0, 1, 2), array([2.751, 3.98 , 5.506]), array([0.526, 0.512, 0.581]))
    """

    taut: tuple[int, ...]  #: taut cables (0-based indices)
    position: np.ndarray
    orientation: np.ndarray  #: angles in the robot's convention (xyz-fixed by default)
    tensions: np.ndarray  #: all n cables (0 for slack ones)
    stable: bool
    certificate_width: float  #: width of the Krawczyk box proven to hold this solution
    uniqueness_radius: float  #: half-width of the inflated box with no other solution
    continuum: tuple[float, float] | None = None  #: spin arc of a one-cable family
    #: a border equilibrium: the cables of ``boundary`` not in ``taut`` are at their lengths
    #: with zero tension, to within the certificate — it solves ``taut`` or ``boundary``; for
    #: a point mass, every cable at its length (more than ``d``: the tensions are not unique)
    boundary: tuple[int, ...] | None = None

    def as_dict(self) -> dict:
        """The solution in plain JSON types (cables 0-based); ``continuum`` and ``boundary``
        only when set."""
        d = {
            "taut": list(self.taut),
            "position": jsonable(self.position),
            "orientation": jsonable(self.orientation),
            "tensions": jsonable(self.tensions),
            "stable": bool(self.stable),
            "certificate_width": jsonable(self.certificate_width),
            "uniqueness_radius": jsonable(self.uniqueness_radius),
        }
        if self.continuum is not None:
            d["continuum"] = jsonable(self.continuum)
        if self.boundary is not None:
            d["boundary"] = list(self.boundary)
        return d


@dataclass(frozen=True)
class DGPResult(Result):
    """All equilibria found, in canonical order (:func:`solution_key`), and the search's
    bookkeeping (:func:`solve_dgp`).

    Attributes
    ----------
    solutions : tuple of DGPSolution
        The certified equilibria.
    subproblems : int
        Taut subsets solved.
    undecided_enclosures : tuple of UndecidedBox
        The boxes no solution could be excluded from, in job order: every equilibrium not
        in ``solutions`` lies in one of them.
    boxes : int
        Boxes processed by branch-and-prune over all sub-problems.
    elapsed_s : float
        Wall-clock time [s].
    least_squares : LeastSquaresFit or None
        Point masses only: the least-squares fit of all the lengths that cable-printer
        firmware computes — not an equilibrium, an extra to compare with
        (:mod:`taut.dgp._point_mass`).
    complete : bool
        No box was left undecided (a property).
    exhausted : bool
        A sub-problem's box budget ran out (a property).

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, Chs. 2–3. (docs/references.bib: berti2015)

    Examples
    --------
    >>> from taut.dgp import solve_dgp
    >>> from taut.model import example
    >>> res = solve_dgp(example("suspended-3cable"), max_taut=2)
    >>> res.subproblems, len(res.solutions), res.complete, sorted(res.as_dict())[:3]
    (6, 0, True, ['boxes', 'complete', 'elapsed_s'])
    """

    solutions: tuple[DGPSolution, ...]
    subproblems: int  #: taut subsets solved
    #: the boxes no solution could be excluded from (:mod:`taut.dgp._undecided`), in job order
    undecided_enclosures: tuple[UndecidedBox, ...]
    boxes: int  #: boxes processed by branch-and-prune over all sub-problems
    elapsed_s: float
    #: point masses: the least-squares fit of all the lengths (firmware's answer, not an equilibrium)
    least_squares: LeastSquaresFit | None = None

    def __post_init__(self) -> None:
        # solutions computed by worker processes arrive unpickled, their arrays writeable
        for s in self.solutions:
            freeze(s)
        super().__post_init__()

    @property
    def undecided(self) -> int:
        """How many boxes were left undecided (should be 0)."""
        return len(self.undecided_enclosures)

    @property
    def complete(self) -> bool:
        """Every equilibrium is in ``solutions``: no box was left undecided."""
        return not self.undecided_enclosures

    @property
    def exhausted(self) -> bool:
        """The box budget ran out in some sub-problem (boxes undecided for ``"budget"``)."""
        return any(b.cause == "budget" for b in self.undecided_enclosures)

    def as_dict(self) -> dict:
        """The result as ``taut fk --json`` prints it, with 0-based cables: ``solutions``,
        ``complete``, ``exhausted``, ``subproblems``, ``undecided_boxes``,
        ``undecided_enclosures``, ``boxes``, ``elapsed_s``; ``least_squares`` for a point
        mass."""
        d = {
            "solutions": [s.as_dict() for s in self.solutions],
            "complete": self.complete,
            "exhausted": self.exhausted,
            "subproblems": self.subproblems,
            "undecided_boxes": self.undecided,
            "undecided_enclosures": [b.as_dict() for b in self.undecided_enclosures],
            "boxes": self.boxes,
            "elapsed_s": self.elapsed_s,
        }
        if self.least_squares is not None:
            d["least_squares"] = self.least_squares.as_dict()
        return d


def solution_key(solution: DGPSolution) -> tuple:
    """The canonical order of solutions: by taut set, then position and orientation."""
    return (solution.taut, *solution.position.tolist(), *solution.orientation.tolist())


#: Largest coordinate of a search domain, in units of the solver's ``tol``: beyond
#: ``2**40 tol`` (110 km for ``tol = 1e-7`` m) ``tol`` spans fewer than 4096 units in the
#: last place of the coordinates, and the rounding of the squared lengths (``L²``, an ulp
#: of ``L²`` moves a point by about ``L 2⁻⁵³``) leaves boxes of width ``tol`` that neither
#: shrink nor certify: a search of hours that proves nothing.
MAX_SCALE = 2.0**40


def check_scale(robot: Robot, lengths: np.ndarray, tol: float) -> None:
    """Refuse lengths that put the platform where double precision cannot resolve ``tol``
    (:data:`MAX_SCALE`): a reference point lies within its cable's length of the exit."""
    reach = float(np.max(np.abs(robot.exits).max(axis=1) + lengths)) + float(
        np.linalg.norm(robot.anchors, axis=1).max()
    )
    if reach > MAX_SCALE * tol:
        raise TautError(
            f"cable lengths up to {lengths.max():.3g} m put the platform up to {reach:.3g} m from the origin, where "
            f"doubles are {np.spacing(reach):.2g} m apart: the solver cannot resolve tol = {tol:g} m there "
            f"(it takes coordinates up to {MAX_SCALE * tol:.3g} m)"
        )


def check_lengths(robot: Robot, lengths: npt.ArrayLike) -> np.ndarray:
    arr = as_array(lengths, "cable lengths", finite=False).ravel()
    if arr.size != robot.n_cables:
        raise TautError(f"{robot.name} has {robot.n_cables} cables, got {arr.size} lengths")
    if not np.all(np.isfinite(arr)):
        raise TautError(f"cable lengths must be finite, got {arr.tolist()}")
    if np.any(arr <= 0):
        raise TautError(f"cable lengths must be positive, got {arr.tolist()}")
    return arr


def domain_pieces(sp: Subproblem | _planar.PlanarSubproblem, split: int) -> list[Box]:
    """The sub-problem's domain cut into up to ``2**split`` pieces that may hold solutions:
    breadth first, the widest piece is contracted (HC4, statics filter) and halved across
    its widest pose variable, empty pieces dropped — most of the initial box is empty, and
    pieces of it would leave all the work to one job."""
    target = 2**split
    live = [(sp.lo.copy(), sp.hi.copy())]
    for _ in range(8 * target):
        if len(live) >= target:
            break
        widths = [np.max(np.where(sp.primary, hi - lo, -1.0)) for lo, hi in live]
        lo, hi = live.pop(int(np.argmax(widths)))
        for part in bisect(lo, hi, primary=sp.primary):
            if contract(sp.system.tape, *part) and sp.statics(*part):
                live.append(part)
        if not live:
            break
    return live


#: HC4 sweeps stop when no domain shrank by this fraction: on the four thesis robots fewer
#: sweeps per box cost less than the 5–10 % more boxes they leave (0.05: 13.4 s, 0.1:
#: 12.5 s, 0.2: 12.1 s on five sample sub-problems, with 5 %, 15 % more boxes).
HC4_RATIO = 0.1


def certify_width(m: int) -> float:
    """Width (metres) of the pose variables below which the full Krawczyk operator is tried.
    With four or five taut cables, whose pose manifolds of dimension 2 and 1 the tube
    step already contracts boxes onto, it proves nothing more on wider boxes (0.3: 10 %
    faster than 1.0 on four CoGiRo and MARIONET-VR sub-problems, the same boxes); with
    three, 0.3 leaves 20 % more boxes on Table 4.3 than 1.0."""
    return 0.3 if 4 <= m <= 5 else 1.0


#: The bisection cuts the widest reference-point coordinate when it is this many times wider
#: than the smear's pick (:func:`~taut.interval.branch_and_prune`): seed 58 of
#: the random 3-cable suite, cables 1 and 3, 1.34 M boxes → 553; the same boxes on
#: Table 4.3, 87 661 instead of 88 231 on Table 4.6.
STARVE = 10.0


#: Per process, the sub-problems last built and their pieces, keyed by the job's data:
#: a worker running several pieces of one sub-problem builds it once (a build takes
#: ~20 ms, as long as solving many pieces).
_PREPARED: dict[tuple[str, bytes, tuple[int, ...], int], tuple[Subproblem | _planar.PlanarSubproblem, list[Box]]] = {}
PREPARED_SIZE = 8


def prepared_subproblem(
    robot: Robot, lengths: np.ndarray, taut: tuple[int, ...], split: int
) -> tuple[Subproblem | _planar.PlanarSubproblem, list[Box]]:
    """The sub-problem of ``taut`` at ``lengths`` and its :func:`domain_pieces`, built once
    per process for the last :data:`PREPARED_SIZE` of them."""
    key = (robot.model_dump_json(), lengths.tobytes(), taut, split)
    hit = _PREPARED.get(key)
    if hit is None:
        sp: Subproblem | _planar.PlanarSubproblem
        if robot.is_point_mass:
            sp = build_point_mass(robot, lengths, taut)
        elif robot.swivel_cables:
            sp = pulley_subproblem(robot, lengths, taut)
        else:
            sp = (_planar.build_subproblem if robot.dimension == 2 else build_subproblem)(robot, lengths, taut)
        hit = (sp, domain_pieces(sp, split))
        while len(_PREPARED) >= PREPARED_SIZE:
            _PREPARED.pop(next(iter(_PREPARED)))
        _PREPARED[key] = hit
    return hit


#: A job of :func:`solve_dgp`: robot, lengths, taut cables (0-based), eps, split, piece,
#: box budget of the sub-problem, multi-precision.
Job = tuple[Robot, np.ndarray, tuple[int, ...], float, int, int, int, bool]


def solve_piece(job: Job) -> tuple[list[DGPSolution], list[Certificate | None], list[UndecidedBox], int]:
    """One job of :func:`solve_dgp`: the sub-problem of ``taut`` on piece ``k`` of
    ``pieces`` of its domain, with an equal share of the sub-problem's box budget.
    Returns ``(solutions, certificates, undecided boxes, boxes)``."""
    robot, lengths, taut, eps, split, k, budget, multiprecision = job
    n = robot.n_cables
    a, r = robot.exits, robot.anchors
    gp = np.zeros(robot.dimension) if robot.is_point_mass else load(robot)[2]
    out: list[DGPSolution] = []
    if len(taut) == 1 and not robot.is_point_mass:
        if robot.swivel_cables:
            single = pulley_single_cable
        else:
            single = _planar.single_cable_equilibria if robot.dimension == 2 else single_cable_equilibria
        for s in single(robot, lengths, taut[0]):
            out.append(
                DGPSolution(
                    (taut[0],),
                    s["p"],
                    _planar.orientation(s["R"], robot.orientation),
                    s["tensions"],
                    s["stable"],
                    0.0,
                    0.0,
                    s["continuum"],
                )
            )
        return out, [None] * len(out), [], 0
    sp, pieces = prepared_subproblem(robot, lengths, taut, split)
    if k >= len(pieces):  # fewer pieces hold solutions than were asked for
        return out, [], [], 0
    lo, hi = pieces[k]
    width = certify_width(len(taut))
    # the statics filter on the boxes Krawczyk is tried on: on wider ones its interval Gauss
    # elimination fails (95 % of CoGiRo's 2, 3, 6, 7 boxes) and it prunes nothing
    res = branch_and_prune(
        sp.system,
        lo,
        hi,
        primary=sp.primary,
        tol=eps,
        filters=(sp.statics,),
        certify_width=width,
        passes=4,
        ratio=HC4_RATIO,
        domain=(sp.lo, sp.hi),
        bisection="smear",
        tube=sp.geometry,
        filter_width=width,
        max_boxes=-(-budget // len(pieces)),
        starve=STARVE,
    )
    found = [(c, False) for c in res.solutions] + [(c, True) for c in res.boundary]
    left = [(blo, bhi, cause_of(blo, bhi, eps)) for blo, bhi in res.undecided]
    if multiprecision and any(cause == "narrow" for *_, cause in left) and precise_available():
        found, left = _resolve_narrow(sp, found, left)
    undecided = [subproblem_box(sp, lengths, blo, bhi, cause) for blo, bhi, cause in left]
    certs: list[Certificate | None] = []
    for c, border in found:
        if sp.tension_unknowns:
            t_lo, t_hi = c.lo[sp.pose_unknowns :], c.hi[sp.pose_unknowns :]
        else:
            # the sign of the tensions over the certified box: all positive, or the
            # solution is infeasible or on the border of a smaller subset (a zero tension)
            enc = sp.statics.enclosure(c.lo, c.hi)
            if enc is None:
                undecided.append(subproblem_box(sp, lengths, c.lo, c.hi, "tension-sign"))
                continue
            t_lo, t_hi = enc
        if np.any(t_hi < 0.0):
            continue
        p, ang, R = sp.pose(c.x, robot.orientation)
        b = p + r @ R.T
        zero = [i for i, lo_i in zip(taut, t_lo) if lo_i <= 0.0]
        # slack cables at their lengths: within the certificate's width, widened
        spans = cable_spans(robot, b)
        near = [k for k in range(n) if k not in taut and abs(spans[k] - lengths[k]) <= _reach(c)]
        if not (border or zero):
            near = []
        elif not (zero or near):
            undecided.append(subproblem_box(sp, lengths, c.lo, c.hi, "domain-border"))
            continue
        tau = sp.tensions(c.x, lengths, n)
        tau[zero] = 0.0
        smaller = tuple(i for i in taut if i not in zero)
        idx = list(smaller)
        g = p + R @ gp
        if robot.swivel_cables:
            stable = pulley_stable(robot, b, g, tau, idx)
        else:
            stable_at = point_mass_stable if robot.is_point_mass else is_stable
            stable = stable_at(a[idx], b[idx], g, tau[idx], lengths[idx]) if idx else False
        boundary = tuple(sorted(set(taut) | set(near))) if zero or near else None
        out.append(DGPSolution(smaller, p, ang, tau, stable, c.width, c.radius, boundary=boundary))
        certs.append(None if boundary else c)
    return out, certs, undecided, res.boxes


def _resolve_narrow(
    sp: Subproblem | _planar.PlanarSubproblem,
    found: list[tuple[Certificate, bool]],
    left: list[tuple[np.ndarray, np.ndarray, str]],
) -> tuple[list[tuple[Certificate, bool]], list[tuple[np.ndarray, np.ndarray, str]]]:
    """The boxes double precision left too narrow to bisect (a singular or nearly double
    solution), searched again in multi-precision balls (:mod:`taut.interval._precise`).
    Each is widened by :data:`NARROW_PAD` of its width, so that a root on a face two of them
    share is inside one; a root the margin takes from a decided neighbour is one this
    piece certified already, and is dropped (one certified by another piece is dropped by
    :func:`solve_dgp`).  They share one budget of
    :data:`taut.interval.MAX_PRECISE_BOXES`; the boxes left when it runs out stay undecided,
    so a continuum of solutions (thousands of narrow boxes) costs seconds, not hours.
    Returns the certificates and the boxes still undecided: ``"singular"`` those the
    multi-precision search shrank to its own limit, ``"narrow"`` those it did not reach."""
    pad = [(blo, bhi, NARROW_PAD * (bhi - blo)) for blo, bhi, cause in left if cause == "narrow"]
    res = solve_precise(
        sp.system,
        [(np.nextafter(blo - w, -np.inf), np.nextafter(bhi + w, np.inf)) for blo, bhi, w in pad],
        domain=(sp.lo, sp.hi),
    )
    new = [(c, False) for c in res.solutions] + [(c, True) for c in res.boundary]
    # a root the margins took from a neighbour that double precision certified
    found = list(found) + [
        (c, border) for c, border in new if not any(same_solution(c, d) or same_solution(d, c) for d, _ in found)
    ]
    still = [(blo, bhi, cause) for blo, bhi, cause in left if cause != "narrow"]
    return found, still + [(u, v, "singular") for u, v in res.undecided] + [(u, v, "narrow") for u, v in res.unsearched]


#: Relative margin by which :func:`_resolve_narrow` widens a narrow box.
NARROW_PAD = 0.01


def _reach(c: Certificate) -> float:
    """How far a slack cable's reach may be from its length for the solution certified by
    ``c`` to count as on the border of that cable's taut subset: the certificate box's
    width times a safety factor of 100 (the reach is 1-Lipschitz in the anchor's position,
    which the pose unknowns move by at most about their width), at least 1e-9 m."""
    return max(1e-9, 100.0 * c.width)


def solve_subset(job: tuple[Robot, np.ndarray, tuple[int, ...], float]) -> tuple[list[DGPSolution], int, int]:
    """The whole sub-problem of one taut subset, in one piece, as a job an executor can map.

    Parameters
    ----------
    job : tuple
        ``(robot, lengths, taut, tol)``: a spatial :class:`~taut.model.Robot`, the cable
        lengths ``(n,)`` [m], the taut cables (0-based) and the bisection threshold.

    Returns
    -------
    solutions : list of DGPSolution
        The sub-problem's certified equilibria with non-negative tensions.
    undecided : int
        How many boxes were left undecided (budget :data:`taut.interval.MAX_BOXES`).
    boxes : int
        Boxes processed.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, Ch. 3. (docs/references.bib: berti2015)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.dgp import solve_subset
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> sols, undecided, boxes = solve_subset((robot, np.array(robot.reference.lengths), (0, 1), 1e-7))
    >>> len(sols), undecided
    (0, 0)
    """
    robot, lengths, taut, eps = job
    sols, _, undecided, boxes = solve_piece((robot, lengths, taut, eps, 0, 0, MAX_BOXES, True))
    return sols, len(undecided), boxes


def _same_border(border: DGPSolution, other: DGPSolution) -> bool:
    """``other`` is the equilibrium ``border`` (a border one): it solves a taut subset between
    ``border.taut`` and ``border.boundary`` at the same pose, to within :data:`BORDER_TOL`."""
    assert border.boundary is not None
    subset = set(border.taut) <= set(other.taut) <= set(border.boundary)
    return bool(
        subset
        and np.allclose(other.position, border.position, rtol=0.0, atol=BORDER_TOL)
        and np.allclose(other.orientation, border.orientation, rtol=0.0, atol=BORDER_TOL)
    )


def merge_point_mass(solutions: list[DGPSolution]) -> list[DGPSolution]:
    """A point mass's solutions at one position, to within :data:`BORDER_TOL`, as one.

    The potential is linear and the allowed set strictly convex: a point mass has at most
    one equilibrium position (:mod:`taut.dgp._point_mass`), and solutions at one position
    are one equilibrium.  Several arise when more than ``d`` cables are at their lengths
    there: each ``d``-subset whose tensions balance the load is a border solution, none
    inside another (which :func:`_same_border` merges).  The tensions are then statically
    indeterminate — every convex combination of those subsets' distributions balances the
    load — and the one reported is that of the first subset by size, then cable numbers,
    its ``boundary`` every cable at its length (the union of the solutions' ``boundary``
    and ``taut``).

    Examples
    --------
    The camera crane at the exact lengths of a pose under its four exits: all four cables
    at their lengths, one solution that balances the load on three of them.

    >>> import numpy as np
    >>> from taut.dgp import solve_dgp
    >>> from taut.model import example
    >>> robot = example("camera-4cable")
    >>> lengths = np.linalg.norm(robot.exits - [1.0, -0.5, 5.0], axis=1)
    >>> [(s.taut, s.boundary, s.position.round(9)) for s in solve_dgp(robot, lengths).solutions]
    [((0, 1, 2), (0, 1, 2, 3), array([ 1. , -0.5,  5. ]))]
    """
    out: list[DGPSolution] = []
    for sol in sorted(solutions, key=lambda s: (len(s.taut), s.taut)):
        k = next(
            (i for i, o in enumerate(out) if np.allclose(o.position, sol.position, rtol=0.0, atol=BORDER_TOL)), None
        )
        if k is None:
            out.append(sol)
            continue
        first = out[k]
        cables = {*first.taut, *(first.boundary or ()), *sol.taut, *(sol.boundary or ())}
        out[k] = replace(first, boundary=tuple(sorted(cables)))
    return out


#: Distance (metres, radians) under which two border equilibria are the same: the
#: certificates are ~1e-10 wide, distinct equilibria of a robot are centimetres apart.
BORDER_TOL = 1e-6


#: Default ``split`` of :func:`solve_dgp`, whatever the executor, so that every executor
#: runs the same jobs and returns bitwise the same solutions.  The pieces cost nothing in
#: serial (CPU time with 1 and 16 pieces per sub-problem: Table 4.3 1.37 s and 1.37 s,
#: Table 4.6 3.83 s and 3.75 s, CoGiRo's Table 4.4 124 s and 115 s).
SPLIT = 4


def solve_dgp(
    robot: Robot,
    lengths: npt.ArrayLike | None = None,
    *,
    max_taut: int | None = None,
    executor: Executor | Client | None = None,
    tol: float = 1e-7,
    split: int | None = None,
    max_boxes: int = MAX_SUBPROBLEM_BOXES,
    progress: Callable[[int, int | None], None] | None = None,
    multiprecision: bool = True,
) -> DGPResult:
    """All admissible equilibria (``τ ≥ 0``) for given cable lengths, each certified and
    classified by stability.

    The taut subsets of ``m = 1 … min(n, 6, max_taut)`` cables are solved as jobs of
    ``executor``; a solution found by two neighbouring pieces of a domain is reported once,
    from the first piece in job order.  Each job is computed by the same code whatever the
    executor, so for a given ``split`` the solutions are bitwise identical on every
    executor; they are sorted by :func:`solution_key`.

    Parameters
    ----------
    robot : Robot
        A platform without joints: a rigid one, spatial or planar (:mod:`taut.dgp._planar`),
        or a point mass, spatial or planar (:mod:`taut.dgp._point_mass`: subsets of up to
        ``d`` taut cables).  The cables of a spatial rigid platform may leave through
        swivelling pulleys (:mod:`taut.dgp._pulleys`).
    lengths : array_like, shape (n,), optional
        Cable lengths [m], the arcs wound on pulleys included; default the robot's
        ``reference.lengths``.
    max_taut : int, optional
        Largest taut subset searched (default ``min(n, 6)``; ``min(n, 3)`` for a planar
        platform, ``min(n, d)`` for a point mass).
    executor : Executor or distributed.Client, optional
        Where the jobs run, as for :func:`~taut.workspace.evaluate_workspace`: ``None``
        (serial), an executor of :func:`taut.parallel.get_executor`, or a
        ``distributed.Client``; it is not closed.
    tol : float, optional
        Bisection threshold of :func:`~taut.interval.branch_and_prune`, in metres (the
        reference points) and scaled tensions.
    split : int, optional
        The domain of every sub-problem with at least 3 taut cables is cut into
        ``2**split`` pieces (0 to 10; default :data:`SPLIT`), solved as separate jobs, so
        that one hard sub-problem is shared by the workers.
    max_boxes : int, optional
        Box budget of every sub-problem, shared equally by its pieces (default
        :data:`MAX_SUBPROBLEM_BOXES`); a certification counts as
        :data:`~taut.interval._branch_prune.CERTIFY_BOXES` boxes, so that the budget bounds
        the time; the boxes left when it runs out are undecided.
    progress : callable, optional
        ``progress(done, total)`` with the number of jobs done (pieces of sub-problems) out
        of all of them, from 0 to the total.
    multiprecision : bool, optional
        Search again, in multi-precision balls, the boxes double precision leaves too narrow
        to bisect (a singular or nearly double solution) when python-flint is installed
        (:mod:`taut.interval._precise`); without it, or with ``False``, they stay undecided.

    Returns
    -------
    DGPResult
        :attr:`~DGPResult.complete` when no box was left undecided; otherwise every
        equilibrium it does not list lies in one of its
        :attr:`~DGPResult.undecided_enclosures` (:mod:`taut.dgp._undecided`).  Lengths that
        admit no equilibrium give no solution, complete; for a point mass
        :attr:`~DGPResult.least_squares` holds, apart, the least-squares fit of the lengths.

    Raises
    ------
    TautError
        A jointed robot, a point mass without a load, lengths that are not ``n`` positive
        numbers,
        no reference lengths to default to, lengths that put the platform beyond
        :data:`MAX_SCALE` ``tol`` from the origin (where double precision cannot resolve
        ``tol``), a pulley radius not smaller than its cable's length, or a bad option.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, Chs. 2–3, §4.2 (Tables 4.3–4.6).
       (docs/references.bib: berti2015)

    Examples
    --------
    Table 4.3 of Berti (2015): six equilibria, one of them stable.

    >>> from taut.dgp import solve_dgp
    >>> from taut.model import example
    >>> res = solve_dgp(example("suspended-3cable"))
    >>> len(res.solutions), sum(s.stable for s in res.solutions), res.complete
    (6, 1, True)

    A planar bar hung from two cables: two equilibria, the stable one tilted.

    >>> stable = [s for s in solve_dgp(example("planar-2cable")).solutions if s.stable]
    >>> [(s.taut, s.position.round(3), s.orientation.round(3)) for s in stable]
    [((0, 1), array([-0.085,  0.592]), array([-0.275]))]
    """
    refuse_unmodelled(robot, "the DGP solver")
    most: int
    if robot.is_point_mass:
        most = robot.dimension
        point_mass_load(robot)  # refuses a point mass without a load
    else:
        most = _planar.MAX_TAUT if robot.dimension == 2 else 6
    if lengths is None:
        if robot.reference is None or robot.reference.lengths is None:
            raise TautError(f"{robot.name} has no reference lengths: give the cable lengths")
        lengths = robot.reference.lengths
    checked = check_lengths(robot, lengths)
    check_pulley_reach(robot, checked)
    tol = as_number(tol, "tol", positive=True)
    check_scale(robot, checked, tol)
    n = robot.n_cables
    top = min(n, most) if max_taut is None else min(n, most, as_count(max_taut, "max_taut"))
    split = SPLIT if split is None else as_count(split, "split", minimum=0)
    if split > 10:
        raise TautError(f"split must be between 0 and 10 (up to 1024 pieces), got {split}")
    max_boxes = as_count(max_boxes, "max_boxes")
    runner = as_executor(executor)
    t0 = time.perf_counter()
    subsets = [taut for m in range(top, 0, -1) for taut in combinations(range(n), m)]
    jobs = [
        (robot, checked, taut, tol, split if len(taut) >= 3 else 0, k, max_boxes, multiprecision)
        for taut in subsets
        for k in range(2**split if len(taut) >= 3 else 1)
    ]
    done = 0

    def callback(_: int) -> None:
        nonlocal done
        done += 1
        if progress is not None:
            progress(done, len(jobs))

    if progress is not None:
        progress(0, len(jobs))
    try:
        parts = runner.map(solve_piece, jobs, callback=callback if progress is not None else None)
    finally:
        if runner is not executor:  # a client made here for a cluster object
            runner.close()
    solutions: list[DGPSolution] = []
    kept: dict[tuple[int, ...], list] = {}
    undecided: list[UndecidedBox] = []
    boxes = 0
    borders: list[DGPSolution] = []
    for sols, certs, und, count in parts:
        for sol, cert in zip(sols, certs):
            if sol.boundary is not None:
                borders.append(sol)
                continue
            seen = kept.setdefault(sol.taut, [])
            if cert is not None and any(same_solution(c, cert) or same_solution(cert, c) for c in seen):
                continue
            seen.append(cert)
            solutions.append(sol)
        undecided += und
        boxes += count
    # a border equilibrium is found by both subsets it borders, or beside a regular
    # solution of one of them: reported once
    for sol in borders:
        if not any(_same_border(sol, other) for other in solutions):
            solutions.append(sol)
    if robot.is_point_mass:
        solutions = merge_point_mass(solutions)
    solutions.sort(key=solution_key)
    fit = least_squares_fit(robot, checked) if robot.is_point_mass else None
    return DGPResult(tuple(solutions), len(subsets), tuple(undecided), boxes, time.perf_counter() - t0, fit)
