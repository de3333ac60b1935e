"""The inverse geometrico-static problem (IGP) of an under-constrained robot
(Berti 2015, §4.1.2, "Inverse kinematics"): with ``m`` chosen taut cables
(``2 ≤ m ≤ 6``) only ``m`` of the six pose coordinates can be controlled; assign them, and
find the other ``6 − m`` coordinates and the ``m`` tensions that put the platform in
static equilibrium (Eq. 2.3) with non-negative tensions.  The cable lengths to command are
then the anchor–exit distances (Eq. 2.2).  The thesis controls ``x, y, z`` with ``m = 3``,
adds ``φx`` or ``φy`` with ``m = 4`` and both with ``m = 5``; any ``m`` coordinates may be
assigned here.  A planar platform (pose ``x, y, θ``) takes ``1 ≤ m ≤ 3`` taut cables and
``m`` of its three coordinates (:func:`taut.dgp._planar.inverse_system`).

Where the thesis's control routine solved this square system locally, :func:`solve_igp`
returns *all* its solutions in a domain, each certified, as its §4.1.2 announces for a
future interval-analysis module:

* unknowns: the free position coordinates (in a box), ``(c_k, s_k) = (cos, sin)`` of each
  free angle with ``c_k² + s_k² = 1`` (so the rotation matrix of the robot's convention is
  a polynomial — no trigonometry in the interval code), and the scaled tensions
  ``t_i = τ_i/l_i`` (so that ``τ_i u_i = t_i (a_i − b_i)`` is polynomial as well);
* equations: the 6 equilibrium equations — forces ``Σ t_i (a_i − b_i) + f = 0`` and
  moments about the anchor ``b_0`` of the first taut cable,
  ``Σ t_i (b_i − b_0) × (a_i − b_i) + (g − b_0) × f + m_ext = 0``, written
  ``(R u_i) × (a_i − p) − R(u_i × r_i)`` with ``u_i = r_i − r_0``: linear in ``R``, free of
  ``t_0``, and with platform-sized arms, so a wide tension enclosure does not swamp the
  orientation (about an exit point, as in :mod:`taut.dgp._formulation`, the arms are
  cable-sized) — plus one circle per free angle: a square system;
* redundant constraints for the contractor: the moment about the axis through every two
  taut anchors and through every two taut exit points, each free of those two tensions
  (for ``m = 3`` it ties one tension to the pose alone; on the ``m = 3`` problems of the
  tests they cut the boxes 2.8-fold (suspended 3-cable robot), 12-fold (teaching
  prototype) and 66-fold (Robocrane)), and ``t_i² ‖a_i − b_i‖² ∈ [τ_min², τ_max²]`` when
  the robot bounds the tensions;
* solver: :func:`taut.interval.branch_and_prune` (HC4, the tension filter of
  §3.1.3 Eqs. 3.9–3.12 through :class:`~taut.interval.LinearFilter`, Krawczyk
  uniqueness and Newton refinement of §3.2.1).

A free ``σ`` of tilt-and-torsion is sought through ``ψ = σ − φ`` (``R = Rz(φ) Ry(θ) Rz(ψ)``
keeps degree one in each pair); an assigned one enters ``cos``/``sin`` of ``σ − φ`` by the
difference formulas.  The angle triples cover every rotation twice, so when the three
``xyz`` angles are free the middle one is kept in ``[−π/2, π/2]`` (``c ≥ 0``), and when
``φ`` and ``θ`` of tilt-and-torsion are free ``θ`` is kept in ``[0, π]`` (``s ≥ 0``); a
solution exactly on that boundary (gimbal lock) is not isolated in the angles and is not
reported.  Likewise a solution with a zero tension is reported by the smaller taut set,
not by this one (its enclosure straddles the domain: an ``undecided`` box here).

Slack cables (not in the taut set) carry no tension; their reported length is the span
from exit point to anchor — the least length they must be paid out to — and a cable whose
span exceeds its length bound, like a taut cable whose length is out of its bounds, is
listed in ``length_violations``: reported, not dropped.  Stability is the reduced-Hessian
test of :mod:`taut.dgp._stability` at the computed lengths.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §4.1.2, Eqs. 2.2–2.3, §3.1.3 (Eqs. 3.9–3.12).
   (docs/references.bib: berti2015)
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_count, as_number
from taut._results import Result, jsonable
from taut.dgp import _planar
from taut.dgp._formulation import load, refuse_unmodelled
from taut.dgp._point_mass import point_mass_igp, point_mass_stable
from taut.dgp._stability import is_stable
from taut.dgp._undecided import UndecidedBox, cause_of, scaled
from taut.errors import CableSetError, PoseError
from taut.interval import (
    MAX_BOXES,
    ONE,
    ZERO,
    Certificate,
    Expr,
    LinearFilter,
    System,
    branch_and_prune,
    compile_system,
    compile_tape,
    const,
    variables,
)
from taut.model import Robot

#: A 3×3 matrix of expressions (a rotation's entries as polynomials).
Matrix = list[list[Expr]]

#: Bound of the cosine and sine unknowns of the free angles, beyond their range [-1, 1].
COS_SIN_BOUND = 1.25

#: Alternative names of the angles of the ``xyz`` conventions (the thesis's ``φx, φy, φz``).
ALIASES = {"phix": "a", "phiy": "b", "phiz": "c", "φx": "a", "φy": "b", "φz": "c"}


@dataclass(frozen=True)
class IGPSolution(Result):
    """One certified solution of the inverse geometrico-static problem.

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
    lengths : ndarray, shape (n,)
        The length [m] to command for a taut cable; for a slack one its span, the least
        length it must be paid out to.
    slack : tuple of int
        The slack cables (0-based indices).
    length_violations : tuple of int
        Cables (0-based indices) outside the robot's length bounds.
    stable : bool
        The reduced Hessian is positive definite (:func:`is_stable`).
    certificate_width : float
        Width of the Krawczyk box proven to hold this solution.
    uniqueness_radius : float
        Half-width of the inflated box holding no other solution.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §4.1.2. (docs/references.bib: berti2015)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.dgp import solve_igp
    >>> from taut.model import example
    >>> res = solve_igp(example("suspended-3cable"), [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061})
    >>> s = res.solutions[0]
    >>> s.stable, np.round(s.orientation, 3), np.round(s.lengths, 3)
    (True, array([3.006, 0.342, 0.109]), array([ 7.5, 10. ,  9.5]))
    """

    taut: tuple[int, ...]  #: taut cables (0-based indices)
    position: np.ndarray
    orientation: np.ndarray  #: angles in the robot's convention
    tensions: np.ndarray  #: all n cables (0 for slack ones)
    lengths: np.ndarray  #: all n cables: the length to command (taut), the span (slack)
    slack: tuple[int, ...]  #: slack cables (0-based indices)
    length_violations: tuple[int, ...]  #: cables (0-based indices) outside the robot's length bounds
    stable: bool
    certificate_width: float  #: width of the Krawczyk box proven to hold this solution
    uniqueness_radius: float  #: half-width of the inflated box with no other solution

    def as_dict(self) -> dict:
        """The solution in plain JSON types (cables 0-based)."""
        return {
            "taut": list(self.taut),
            "position": jsonable(self.position),
            "orientation": jsonable(self.orientation),
            "tensions": jsonable(self.tensions),
            "lengths": jsonable(self.lengths),
            "slack": list(self.slack),
            "length_violations": list(self.length_violations),
            "stable": bool(self.stable),
            "certificate_width": jsonable(self.certificate_width),
            "uniqueness_radius": jsonable(self.uniqueness_radius),
        }


@dataclass(frozen=True)
class IGPResult(Result):
    """Every certified solution of the inverse geometrico-static problem in the search
    domain (:func:`solve_igp`), stable ones first.

    Attributes
    ----------
    solutions : tuple of IGPSolution
    fixed : dict
        The fixed pose coordinates by the robot's pose names (``taut igp --json`` prints
        them as ``"assigned"``).
    undecided_enclosures : tuple of UndecidedBox
        The boxes that could not be decided: narrower than ``tol`` around a solution with a
        zero tension (it belongs to a smaller taut set) or a singular one (a fold, a
        continuum), and those left when the box budget ran out.
    boxes : int
        Boxes processed.
    exhausted : bool
        The box budget ran out (typically on a continuum of solutions).
    elapsed_s : float
        Wall-clock time [s].
    complete : bool
        No box was left undecided (a property).

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §4.1.2. (docs/references.bib: berti2015)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.dgp import solve_igp
    >>> from taut.model import example
    >>> res = solve_igp(example("suspended-3cable"), [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061})
    >>> len(res.solutions), res.complete, res.fixed
    (4, True, {'x': 2.7505, 'y': 3.9798, 'z': 5.5061})
    """

    solutions: tuple[IGPSolution, ...]
    fixed: dict[str, float]  #: the fixed (assigned) coordinates, by the robot's pose names
    #: boxes that could not be decided (:mod:`taut.dgp._undecided`): of width < eps around a
    #: solution with a zero tension (it belongs to a smaller taut set) or a singular one (a
    #: fold, a continuum), and those left when the box budget ran out
    undecided_enclosures: tuple[UndecidedBox, ...]
    boxes: int
    exhausted: bool  #: the box budget ran out (typically on a continuum of solutions)
    elapsed_s: float

    @property
    def undecided(self) -> int:
        """How many boxes were left undecided."""
        return len(self.undecided_enclosures)

    @property
    def complete(self) -> bool:
        """Every solution in the domain is in ``solutions``: no box was left undecided."""
        return not self.undecided_enclosures

    def as_dict(self) -> dict:
        """The result as ``taut igp --json`` prints it, with 0-based cables (the coordinates
        it prints as ``assigned`` are ``fixed`` here): ``fixed``, ``solutions``,
        ``complete``, ``undecided_boxes``, ``undecided_enclosures``, ``boxes``,
        ``exhausted``, ``elapsed_s``."""
        return {
            "fixed": jsonable(self.fixed),
            "solutions": [s.as_dict() for s in self.solutions],
            "complete": self.complete,
            "undecided_boxes": self.undecided,
            "undecided_enclosures": [b.as_dict() for b in self.undecided_enclosures],
            "boxes": self.boxes,
            "exhausted": self.exhausted,
            "elapsed_s": self.elapsed_s,
        }


def _check_robot(robot: Robot) -> None:
    refuse_unmodelled(robot, "the inverse geometrico-static problem")


def _check_taut(robot: Robot, taut: Iterable[int]) -> tuple[int, ...]:
    """The taut cables' 0-based indices, sorted; messages name cables by their 1-based numbers."""
    n = robot.n_cables
    try:
        items = list(taut)
        indices = [int(i) for i in items]
    except (TypeError, ValueError):
        raise CableSetError(f"taut cables: expected cable indices 0..{n - 1}, got {taut!r}") from None
    if any(k != i for k, i in zip(indices, items)):
        raise CableSetError(f"taut cables: expected whole cable indices 0..{n - 1}, got {items}")
    bad = [i for i in indices if not 0 <= i < n]
    if bad:
        numbers = ", ".join(str(i + 1) for i in bad)
        raise CableSetError(f"taut cables: no cable {numbers} (0-based index {bad}); {robot.name} has cables 1..{n}")
    if len(set(indices)) != len(indices):
        raise CableSetError(f"taut cables: {[i + 1 for i in indices]} names a cable twice")
    least: int
    most: int
    if robot.is_point_mass:
        least, most = 1, robot.dimension
    else:
        least, most = (1, _planar.MAX_TAUT) if robot.dimension == 2 else (2, 6)
    if not least <= len(indices) <= most:
        kind = f" of a {robot.dimension}-D point mass" if robot.is_point_mass else ""
        raise CableSetError(
            f"the inverse geometrico-static problem{kind} takes {least} to {most} taut cables, got {len(indices)}"
        )
    return tuple(sorted(indices))


def _check_fixed(robot: Robot, fixed: Mapping[str, float], m: int) -> dict[int, float]:
    """Pose index (0…5) → value of the fixed (assigned) coordinates."""
    names = robot.pose_names[:6]
    if not isinstance(fixed, Mapping):
        raise PoseError(f"fixed coordinates: expected a mapping name → value, got {fixed!r}")
    out: dict[int, float] = {}
    for key, value in fixed.items():
        name = str(key).strip().lower().replace("_", "")
        if robot.orientation != "tilt-torsion":
            name = ALIASES.get(name, name)
        if name not in names:
            raise PoseError(f"unknown pose coordinate {key!r}; {robot.name} has {', '.join(names)}")
        k = names.index(name)
        if k in out:
            raise PoseError(f"pose coordinate {names[k]!r} is assigned twice")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise PoseError(f"pose coordinate {names[k]!r}: {value!r} is not a number") from None
        if not np.isfinite(v):
            raise PoseError(f"pose coordinate {names[k]!r} must be finite, got {value!r}")
        out[k] = v
    if len(out) != m:
        raise PoseError(
            f"with {m} taut cables assign exactly {m} of the pose coordinates ({', '.join(names)}), got {len(out)}"
        )
    return out


def _position_box(
    robot: Robot, taut: tuple[int, ...], box: tuple[npt.ArrayLike, npt.ArrayLike] | None
) -> tuple[np.ndarray, np.ndarray]:
    """The search box of the platform origin: given, or the intersection over the taut
    cables of ``a_i ± (reach_i + ‖r_i‖)`` with ``reach_i`` the cable's largest length, or
    the diagonal of the exit points' bounding box for a cable without one."""
    d = robot.dimension
    if box is not None:
        try:
            lo, hi = (np.asarray(b, float).ravel() for b in box)
        except (TypeError, ValueError):
            raise PoseError(f"box: expected (lower corner, upper corner) of {d} numbers each, got {box!r}") from None
        if lo.size != d or hi.size != d or not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
            raise PoseError(f"box: expected two finite corners of {d} numbers, got {box!r}")
        if np.any(lo >= hi):
            raise PoseError(f"box: the lower corner {lo.tolist()} must lie below the upper corner {hi.tolist()}")
        return lo, hi
    a, r = robot.exits, robot.anchors
    diagonal = float(np.linalg.norm(a.max(0) - a.min(0)))
    lmax = robot.length_bounds[1]
    lo, hi = np.full(d, -np.inf), np.full(d, np.inf)
    for i in taut:
        reach = (lmax[i] if np.isfinite(lmax[i]) else diagonal) + float(np.linalg.norm(r[i]))
        lo, hi = np.maximum(lo, a[i] - reach), np.minimum(hi, a[i] + reach)
    return lo, hi


def _cos_sin(angle: float) -> tuple[Expr, Expr]:
    """Enclosures of ``cos`` and ``sin`` of an assigned angle: ±2 ulp around the libm
    values (glibc's error is below 1 ulp), exact at 0 so that the rotation simplifies."""
    if angle == 0.0:
        return ONE, ZERO

    def enclose(v: float) -> Expr:
        down, up = math.nextafter(v, -math.inf), math.nextafter(v, math.inf)
        return const(math.nextafter(down, -math.inf), math.nextafter(up, math.inf))

    return enclose(math.cos(angle)), enclose(math.sin(angle))


def _matmul(A: Matrix, B: Matrix) -> Matrix:
    return [[sum((A[i][k] * B[k][j] for k in range(3)), ZERO) for j in range(3)] for i in range(3)]


def _rx(c: Expr, s: Expr) -> Matrix:
    return [[ONE, ZERO, ZERO], [ZERO, c, -s], [ZERO, s, c]]


def _ry(c: Expr, s: Expr) -> Matrix:
    return [[c, ZERO, s], [ZERO, ONE, ZERO], [-s, ZERO, c]]


def _rz(c: Expr, s: Expr) -> Matrix:
    return [[c, -s, ZERO], [s, c, ZERO], [ZERO, ZERO, ONE]]


def _rotation(cs: Sequence[tuple[Expr, Expr]], convention: str) -> Matrix:
    """``R`` of :func:`taut.geometry.rotation_matrix` as polynomials in the
    ``(cos, sin)`` pairs ``cs`` of its three elementary rotations — for tilt-and-torsion
    those of ``φ``, ``θ`` and ``σ − φ`` (``R = Rz(φ) Ry(θ) Rz(σ − φ)``)."""
    (ca, sa), (cb, sb), (cc, sc) = cs
    if convention == "xyz-fixed":
        return _matmul(_matmul(_rz(cc, sc), _ry(cb, sb)), _rx(ca, sa))
    if convention == "xyz-moving":
        return _matmul(_matmul(_rx(ca, sa), _ry(cb, sb)), _rz(cc, sc))
    return _matmul(_matmul(_rz(ca, sa), _ry(cb, sb)), _rz(cc, sc))


def _half_turn_restricted(convention: str, free_angles: list[int]) -> tuple[int, int] | None:
    """``(angle, 0 for its cosine | 1 for its sine)`` kept non-negative so that each
    rotation is found once (see the module docstring), or None."""
    if convention == "tilt-torsion":
        return (1, 1) if {0, 1} <= set(free_angles) else None
    return (1, 0) if len(free_angles) == 3 else None


@dataclass(frozen=True)
class _Problem:
    system: System
    statics: LinearFilter
    lo: np.ndarray
    hi: np.ndarray
    primary: np.ndarray
    free_pos: list[int]  #: pose indices 0–2 that are unknowns, in variable order
    free_ang: list[int]  #: pose indices 3–5 (as 0–2) that are unknowns, in variable order
    #: names of the unknowns between the angles and the tensions (the pulleys' ``d``, ``l_f``)
    extra_names: tuple[str, ...] = ()


def _build(
    robot: Robot, taut: tuple[int, ...], fixed: dict[int, float], pos_lo: np.ndarray, pos_hi: np.ndarray
) -> _Problem:
    a, r = robot.exits, robot.anchors
    f, mext, gp = load(robot)
    m = len(taut)
    free_pos = [k for k in range(3) if k not in fixed]
    free_ang = [k for k in range(3) if 3 + k not in fixed]
    nv = len(free_pos) + 2 * len(free_ang) + m
    v = iter(variables(nv))
    p = [next(v) if k in free_pos else const(fixed[k]) for k in range(3)]
    # a free σ of tilt-and-torsion is unknown through ψ = σ − φ, so that R stays of degree
    # one in each pair; an assigned σ enters by the difference formulas
    cs = [(next(v), next(v)) if k in free_ang else _cos_sin(fixed[3 + k]) for k in range(3)]
    if robot.orientation == "tilt-torsion" and 2 not in free_ang:
        (c_phi, s_phi), (c_sigma, s_sigma) = cs[0], cs[2]
        cs[2] = (c_sigma * c_phi + s_sigma * s_phi, s_sigma * c_phi - c_sigma * s_phi)
    t = {i: next(v) for i in taut}
    R = _rotation(cs, robot.orientation)

    def rotated(vec: np.ndarray) -> list[Expr]:
        return [sum((R[k][j] * float(vec[j]) for j in range(3)), ZERO) for k in range(3)]

    def cross(u: Sequence[Expr], w: Sequence[Expr | float]) -> list[Expr]:
        return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]

    def dot(u: Sequence[Expr], w: Sequence[Expr | float]) -> Expr:
        return sum((u[k] * w[k] for k in range(3)), ZERO)

    fl, ml = [float(x) for x in f], [float(x) for x in mext]
    Rr = {i: rotated(r[i]) for i in taut}
    b = {i: [p[k] + Rr[i][k] for k in range(3)] for i in taut}
    g = [p[k] + x for k, x in enumerate(rotated(gp))]
    ap = {i: [float(a[i][k]) - p[k] for k in range(3)] for i in taut}  # a_i − p
    span = {i: [ap[i][k] - Rr[i][k] for k in range(3)] for i in taut}  # a_i − b_i

    def anchor_arm(i: int, j: int) -> list[Expr]:
        """(b_i − b_j) × (a_i − b_i) = (R u) × (a_i − p) − R(u × r_i), u = r_i − r_j:
        linear in R, platform-sized."""
        u = r[i] - r[j]
        return [x - y for x, y in zip(cross(rotated(u), ap[i]), rotated(np.cross(u, r[i])))]

    def anchor_load(j: int) -> list[Expr]:
        return [x + ml[k] for k, x in enumerate(cross(rotated(gp - r[j]), fl))]

    def exit_arm(i: int, pole: np.ndarray) -> list[Expr]:
        """(b_i − pole) × (a_i − pole): one occurrence of b_i."""
        return cross([b[i][k] - float(pole[k]) for k in range(3)], [float(x) for x in a[i] - pole])

    def exit_load(pole: np.ndarray) -> list[Expr]:
        return [x + ml[k] for k, x in enumerate(cross([g[k] - float(pole[k]) for k in range(3)], fl))]

    def anchor_axis(i: int, j: int) -> Expr:
        """The moment about the axis b_i b_j, which drops t_i and t_j: with v = r_j − r_i and
        n = v × (r_q − r_i), term q is t_q (a_q − b_q)·R n = t_q ((a_q − p)·R n − r_q·n)."""
        v = r[j] - r[i]
        terms = []
        for q in taut:
            if q not in (i, j):
                n = np.cross(v, r[q] - r[i])
                terms.append(t[q] * (dot(ap[q], rotated(n)) - float(r[q] @ n)))
        return sum(terms, dot(rotated(np.cross(v, gp - r[i])), fl) + dot(rotated(v), ml))

    def exit_axis(i: int, j: int) -> Expr:
        """The moment about the axis a_i a_j, which drops t_i and t_j."""
        d = [float(x) for x in a[j] - a[i]]
        return sum((t[q] * dot(exit_arm(q, a[i]), d) for q in taut if q not in (i, j)), dot(exit_load(a[i]), d))

    # equations: forces, moments about the first taut anchor b_0 (t_0 drops out), circles
    j0 = taut[0]
    arms = {i: anchor_arm(i, j0) if i != j0 else [ZERO] * 3 for i in taut}
    load0 = anchor_load(j0)
    forces = [sum((t[i] * span[i][k] for i in taut), const(fl[k])) for k in range(3)]
    moments = [sum((t[i] * arms[i][k] for i in taut), load0[k]) for k in range(3)]
    circles = [c**2 + s**2 - 1.0 for k, (c, s) in enumerate(cs) if k in free_ang]
    # redundant: the moments about the axes through two anchors or two exit points, each
    # free of two tensions — what lets HC4 narrow the orientation before the tensions
    pairs = [(i, j) for n1, i in enumerate(taut) for j in taut[n1 + 1 :]]
    axes = [anchor_axis(i, j) for i, j in pairs if np.any(r[j] != r[i])]
    axes += [exit_axis(i, j) for i, j in pairs if np.any(a[j] != a[i])]
    extra = [(e, (0.0, 0.0)) for e in axes]
    tmin, tmax = robot.tension_bounds
    for i in taut:
        if tmin[i] > 0.0 or np.isfinite(tmax[i]):
            extra.append((t[i] ** 2 * dot(span[i], span[i]), (max(float(tmin[i]), 0.0) ** 2, float(tmax[i]) ** 2)))
    system = compile_system(nv, forces + moments + circles, extra)

    # the tension filter of §3.1.3: J(X) t = −w(X), J's 6·m entries row-major, then −w
    J = [[span[i][k] for i in taut] for k in range(3)] + [[arms[i][k] for i in taut] for k in range(3)]
    rhs = [const(-fl[k]) for k in range(3)] + [-x for x in load0]
    statics = LinearFilter(compile_tape([e for row in J for e in row] + rhs, [(-np.inf, np.inf)] * (6 * m + 6)), m)

    lo, hi = np.empty(nv), np.empty(nv)
    np_ = len(free_pos)
    lo[:np_], hi[:np_] = pos_lo[free_pos], pos_hi[free_pos]
    # cos and sin lie in [-1, 1], but a solution at a multiple of π/2 (an angle of 0, a
    # common one) has one of them on that bound, where no certified box fits in the domain:
    # the circle c² + s² = 1 contracts them into [-1, 1] anyway
    lo[np_ : nv - m], hi[np_ : nv - m] = -COS_SIN_BOUND, COS_SIN_BOUND
    half = _half_turn_restricted(robot.orientation, free_ang)
    if half is not None:
        lo[np_ + 2 * free_ang.index(half[0]) + half[1]] = 0.0
    lo[nv - m :], hi[nv - m :] = 0.0, np.inf
    primary = np.arange(nv) < nv - m
    return _Problem(system, statics, lo, hi, primary, free_pos, free_ang)


def solve_igp(
    robot: Robot,
    taut: Iterable[int],
    fixed: Mapping[str, float],
    *,
    box: tuple[npt.ArrayLike, npt.ArrayLike] | None = None,
    tol: float = 1e-7,
    max_boxes: int = MAX_BOXES,
    progress: Callable[[int, int | None], None] | None = None,
) -> IGPResult:
    """All certified solutions of the inverse geometrico-static problem: the free pose
    coordinates and the tensions of ``m`` taut cables for ``m`` fixed pose coordinates
    (module docstring).

    Parameters
    ----------
    robot : Robot
        A platform without joints: a rigid one, spatial or planar (pose ``x, y, theta``;
        :func:`taut.dgp._planar.inverse_system`), or a point mass, spatial or planar (the
        ``d`` force balances of :mod:`taut.dgp._point_mass`).  The cables of a spatial rigid
        platform may leave through swivelling pulleys
        (:func:`taut.dgp._pulleys.pulley_igp_problem`: the lengths to command are then the
        pulley IK's, the arcs included).
    taut : iterable of int
        The 0-based indices of the ``m`` taut cables, ``2 ≤ m ≤ 6`` (``1 ≤ m ≤ 3`` planar,
        ``1 ≤ m ≤ d`` for a point mass; the cables the command line numbers 1, 2, 3 are
        ``[0, 1, 2]``).
    fixed : mapping of str to float
        Exactly ``m`` pose coordinates by name [m, rad]: the robot's ``pose_names``
        (``x, y, z, a, b, c``; ``phix, phiy, phiz`` are accepted for the ``xyz``
        conventions; ``phi, theta, sigma`` for tilt-and-torsion).
    box : (array_like, array_like), optional
        Lower and upper corners [m] of the search box of the free position coordinates (3
        numbers each; 2 planar);
        default the intersection of the taut cables' reach.
    tol : float, optional
        Bisection threshold of :func:`~taut.interval.branch_and_prune` (metres, cosines and
        scaled tensions).
    max_boxes : int, optional
        Box budget (default :data:`taut.interval.MAX_BOXES`): the well-posed problems of the examples take
        10²–10⁴ boxes; a continuum of solutions (fixed coordinates that do not fix the pose,
        e.g. ``x, y, φ`` of the Robocrane with cables 1, 3, 5 at ``x = y = 0``) would take
        them all, at about 1 ms a box.  What is left when it runs out is undecided and
        ``exhausted`` is set.
    progress : callable, optional
        ``progress(boxes, None)`` as the boxes are processed (their number is not known in
        advance) and ``progress(boxes, boxes)`` at the end.

    Returns
    -------
    IGPResult

    Raises
    ------
    CableSetError
        Taut cables that are not 2 to 6 (planar: 1 to 3; point mass: 1 to ``d``) distinct
        cables of the robot.
    PoseError
        Fixed coordinates that are not ``m`` distinct pose coordinates with finite values,
        or a bad ``box``.
    UnsupportedRobotError
        A jointed robot, or swivelling pulleys on a planar or point-mass platform.
    TautError
        A bad ``tol`` or ``max_boxes``.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §4.1.2. (docs/references.bib: berti2015)

    Examples
    --------
    The stable pose of Table 4.3 of Berti (2015) at its position: four equilibria there.

    >>> import numpy as np
    >>> from taut.dgp import solve_igp
    >>> from taut.model import example
    >>> res = solve_igp(example("suspended-3cable"), [0, 1, 2], {"x": 2.7505, "y": 3.9798, "z": 5.5061})
    >>> [s.stable for s in res.solutions]
    [True, False, False, False]
    """
    _check_robot(robot)
    idx = _check_taut(robot, taut)
    values = _check_fixed(robot, fixed, len(idx))
    tol = as_number(tol, "tol", positive=True)
    max_boxes = as_count(max_boxes, "max_boxes")
    pos_lo, pos_hi = _position_box(robot, idx, box)
    names = robot.pose_names[:6]
    t0 = time.perf_counter()
    solutions: list[IGPSolution] = []
    undecided: tuple[UndecidedBox, ...] = ()
    boxes = 0
    exhausted = False
    if np.all(pos_lo < pos_hi):  # the taut cables' reach boxes can miss each other
        if robot.is_point_mass:
            system, statics, lo, hi, primary, free = point_mass_igp(robot, idx, values, pos_lo, pos_hi)
            pb = _Problem(system, statics, lo, hi, primary, free, [])
        elif robot.dimension == 2:
            angle = _cos_sin(values[2]) if 2 in values else None
            pb = _Problem(*_planar.inverse_system(robot, idx, values, pos_lo, pos_hi, angle, COS_SIN_BOUND))
        elif robot.swivel_cables:
            from taut.dgp._pulleys import pulley_igp_problem

            orientation = (COS_SIN_BOUND, _cos_sin, _half_turn_restricted, _rotation)
            pb = _Problem(*pulley_igp_problem(robot, idx, values, pos_lo, pos_hi, orientation))
        else:
            pb = _build(robot, idx, values, pos_lo, pos_hi)
        res = branch_and_prune(
            pb.system,
            pb.lo,
            pb.hi,
            primary=pb.primary,
            tol=tol,
            filters=(pb.statics,),
            certify_width=0.5,
            max_boxes=max_boxes,
            progress=None if progress is None else _within_budget(progress, max_boxes),
        )
        solutions = [_solution(robot, idx, values, pb, c) for c in res.solutions]
        solutions.sort(key=lambda s: (not s.stable, *s.position, *s.orientation))
        # a certified solution straddling a bound (a zero tension, a domain edge) may or may
        # not be an answer: it is reported as undecided, never dropped
        undecided = tuple(
            _undecided(robot, idx, values, pb, blo, bhi, cause_of(blo, bhi, tol)) for blo, bhi in res.undecided
        ) + tuple(_undecided(robot, idx, values, pb, c.lo, c.hi, "domain-border") for c in res.boundary)
        boxes, exhausted = min(res.boxes, max_boxes), res.exhausted
    elif progress is not None:
        progress(0, 0)
    return IGPResult(
        tuple(solutions),
        {names[k]: v for k, v in sorted(values.items())},
        undecided,
        boxes,
        exhausted,
        time.perf_counter() - t0,
    )


def _within_budget(progress: Callable[[int, int | None], None], budget: int) -> Callable[[int, int | None], None]:
    """``progress`` with box counts capped at the budget: when it runs out the solver has
    counted the one box it did not process, which the result does not count."""

    def report(done: int, total: int | None) -> None:
        progress(min(done, budget), None if total is None else min(total, budget))

    return report


def _unknown_names(robot: Robot, pb: _Problem) -> tuple[str, ...]:
    """Names of the pose unknowns: the free position coordinates, then the cosine and sine
    of every free angle (of ``σ − φ`` for a free ``σ`` of tilt-and-torsion)."""
    names = robot.pose_names[:6]
    angles = [names[robot.dimension + k] for k in pb.free_ang]
    if robot.orientation == "tilt-torsion" and 2 in pb.free_ang:
        angles[-1] = f"{names[5]}-{names[3]}"
    return (*(names[k] for k in pb.free_pos), *(f"{f}({a})" for a in angles for f in ("cos", "sin")), *pb.extra_names)


def _undecided(
    robot: Robot,
    taut: tuple[int, ...],
    fixed: dict[int, float],
    pb: _Problem,
    lo: np.ndarray,
    hi: np.ndarray,
    cause: str,
) -> UndecidedBox:
    """The undecided box ``[lo, hi]`` with the tensions ``τ_i = t_i ‖a_i − b_i‖`` enclosed
    through the cable lengths over it: the anchor ``b_i = p + R r_i`` lies within ``‖r_i‖``
    of the origin ``p``, which lies in the box's position range."""
    k = lo.size - len(taut)
    p_lo = np.array([fixed.get(c, 0.0) for c in range(robot.dimension)])
    p_hi = p_lo.copy()
    p_lo[pb.free_pos], p_hi[pb.free_pos] = lo[: len(pb.free_pos)], hi[: len(pb.free_pos)]
    a, r = robot.exits[list(taut)], robot.anchors[list(taut)]
    near = np.linalg.norm(np.clip(a, p_lo, p_hi) - a, axis=1)
    far = np.linalg.norm(np.maximum(np.abs(a - p_lo), np.abs(a - p_hi)), axis=1)
    arm = np.linalg.norm(r, axis=1)
    widen = 1.0 + 8.0 * np.finfo(float).eps  # covers the rounding of the norms and sums
    length_lo = np.maximum(0.0, (near - arm) / widen)
    length_hi = (far + arm) * widen
    for j, i in enumerate(taut):
        if robot.cables[i].swivel is not None:
            # τ = t Q through a pulley, 0 ≤ Q = ρ² − r d + h l_f ≤ 2ρ² (taut.dgp._pulleys)
            length_lo[j], length_hi[j] = 0.0, 2.0 * length_hi[j] ** 2 * widen
    t_lo, t_hi = lo[k:], hi[k:]
    tension_lo, _ = scaled(t_lo, t_lo, length_lo)
    _, tension_hi = scaled(t_hi, t_hi, length_hi)
    return UndecidedBox(
        taut, cause, _unknown_names(robot, pb), tuple(lo[:k].tolist()), tuple(hi[:k].tolist()), tension_lo, tension_hi
    )


def _solution(
    robot: Robot, taut: tuple[int, ...], fixed: dict[int, float], pb: _Problem, cert: Certificate
) -> IGPSolution:
    x, d = cert.x, robot.dimension
    pose = np.array([fixed.get(k, 0.0) for k in range(robot.wrench_dim)])
    pose[pb.free_pos] = x[: len(pb.free_pos)]
    cs = x[len(pb.free_pos) : len(pb.free_pos) + 2 * len(pb.free_ang)].reshape(-1, 2)
    pose[[d + k for k in pb.free_ang]] = np.arctan2(cs[:, 1], cs[:, 0])
    if d == 3 and robot.orientation == "tilt-torsion" and 2 in pb.free_ang:  # the unknown was ψ = σ − φ
        pose[5] = math.remainder(pose[3] + pose[5], 2 * math.pi)
    if robot.is_point_mass:  # no orientation: the anchors and the load point are at p
        p, R, gp = pose[:d], np.eye(d), np.zeros(d)
    else:
        p, R = pose[:d], _planar.rotation(robot, pose[d:])
        _, _, gp = load(robot)
    a, r = robot.exits, robot.anchors
    b = p + r @ R.T
    lengths = np.linalg.norm(a - b, axis=1)
    idx = list(taut)
    tensions = np.zeros(robot.n_cables)
    if robot.swivel_cables:
        from taut.dgp._pulleys import cable_spans, pulley_igp_tensions

        lengths = cable_spans(robot, b)
        tensions[idx] = pulley_igp_tensions(robot, taut, b, x[-len(taut) :])
    else:
        tensions[idx] = x[-len(taut) :] * lengths[idx]
    lmin, lmax = robot.length_bounds
    slack = [k for k in range(robot.n_cables) if k not in taut]
    # a slack cable can be paid out beyond its span, so only its upper bound can fail
    out_of_bounds = [k for k in range(robot.n_cables) if lengths[k] > lmax[k] or (k in taut and lengths[k] < lmin[k])]
    if robot.swivel_cables:
        from taut.dgp._pulleys import pulley_stable

        stable = pulley_stable(robot, b, p + R @ gp, tensions, idx)
    else:
        stable_at = point_mass_stable if robot.is_point_mass else is_stable
        stable = stable_at(a[idx], b[idx], p + R @ gp, tensions[idx], lengths[idx])
    return IGPSolution(
        tuple(taut),
        p,
        pose[d:],
        tensions,
        lengths,
        tuple(slack),
        tuple(out_of_bounds),
        stable,
        cert.width,
        cert.radius,
    )
