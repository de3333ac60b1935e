"""The geometrico-static equations of a point-mass platform, spatial ``(x, y, z)`` or planar
``(x, y)``: one square system per taut subset of ``m ≤ d`` cables (Berti 2015, §2.3, with
the platform shrunk to a point: every anchor is its origin, no moment balance).

Unknowns: the position ``p`` (``d``) and the scaled tensions ``t_i = τ_i/ρ_i`` of the ``m``
taut cables.  Equations (quadratic, no trigonometry):

* ``m`` cable lengths ``‖p − a_i‖² = ρ_i²``;
* ``d`` force balances ``Σ t_i (a_i − p) + f = 0`` (Eq. 2.3, forces only).

Redundant constraints for the contractor (§3.1.3): the slack cables' reach
``‖p − a_k‖² ≤ ρ_k²`` (Eq. 3.7); the moment of the forces about every taut exit point
``a_j``, ``Σ_{i≠j} t_i (p − a_j) × (a_i − a_j) + (p − a_j) × f = 0`` (a vector in space, a
scalar in the plane), where ``(p − a_j) × (a_i − p) = (p − a_j) × (a_i − a_j)`` is linear in
``p``; and in space the moment about the axis through every two taut exit points, free of
both tensions — with two taut cables it is the plane through them parallel to the load, on
which the platform must hang.  The initial box (§3.1.1) is the intersection of the cables'
bounding cubes ``a_j ± ρ_j`` (every cable, taut or slack, reaches at most its length), the
tensions ``[0, ∞)``; the statics filter (Eqs. 3.9–3.12) bounds them.

The potential ``−f·p`` is linear and the set of positions the cables allow,
``⋂ {‖p − a_i‖ ≤ ρ_i}``, strictly convex: an equilibrium with ``τ ≥ 0`` is a KKT point of
the lowest potential over that set, of which there is at most one.  Its reduced Hessian
(§3.2.2) is ``Nᵀ (Σ t_i I) N``, ``N`` spanning the motions that keep the taut lengths: it is
stable whenever a tension is positive.  The solver does not rely on this: it searches every
taut subset, and the uniqueness is what the tests check it against.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §2.3, §3.1.1, §3.1.3, §3.2.2, §4.1.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Protocol

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.dgp._formulation import StaticsFilter, Subproblem, rational_constant
from taut.errors import TautError
from taut.interval import Expr, LinearFilter, System, certified_step, compile_system, compile_tape, const, variables
from taut.model import Robot

#: Names of the unknowns of a point mass's position, as undecided boxes list them.
POSITION_UNKNOWNS = ("x", "y", "z")


def point_mass_load(robot: Robot) -> tuple[np.ndarray, list[Fraction]]:
    """The force on a point-mass platform, its ``wrench`` plus its weight: as floats ``(d,)``
    and exactly (the rational sum of the two floats).

    Raises
    ------
    TautError
        No load: without one a point mass is in equilibrium wherever its cables reach (a
        continuum, with every tension zero).
    """
    plat = robot.platform
    d = robot.dimension
    wrench = [0.0] * d if plat.wrench is None else [float(w) for w in plat.wrench]
    exact = [Fraction(w) + Fraction(float(g)) for w, g in zip(wrench, robot.weight)]
    if not any(exact):
        raise TautError(
            f"{robot.name}: a point mass without a load (platform.mass or platform.wrench) is in equilibrium "
            "wherever its cables reach, with zero tensions: give it a mass or a wrench"
        )
    return np.array([float(x) for x in exact]), exact


def _exact(v: npt.ArrayLike) -> list[Fraction]:
    return [Fraction(float(c)) for c in np.ravel(v)]


def _cross(u: Sequence[Fraction], w: Sequence[Fraction]) -> list[Fraction]:
    return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]


def _dot(xs: Sequence[Expr], cs: Sequence[Fraction]) -> Expr:
    """``Σ x_k c_k`` for expressions ``x`` and exact constants ``c`` (zero terms dropped)."""
    terms = [x * rational_constant(c) for x, c in zip(xs, cs) if c != 0]
    return sum(terms[1:], terms[0]) if terms else const(0.0)


def moment_rows(
    p: Sequence[Expr], taut: Sequence[int], a: np.ndarray, f: Sequence[Fraction], j: int
) -> list[tuple[list[Expr], Expr]]:
    """The moment balance about the exit point ``a_j`` as rows ``(coefficients of the taut
    cables' t_i, load term)``, ``Σ t_i c_i + l = 0``: one row in the plane, three in space.
    ``(p − a_j) × (a_i − a_j) = (p − a_j) · ((a_i − a_j) × e_k)`` is linear in ``p``."""
    d = len(p)
    r = [p[k] - float(a[j][k]) for k in range(d)]
    aj = _exact(a[j])
    arms = {i: [x - y for x, y in zip(_exact(a[i]), aj)] for i in taut}
    if d == 2:
        return [([_dot(r, [c[1], -c[0]]) for c in arms.values()], _dot(r, [f[1], -f[0]]))]
    rows = []
    for k in range(3):
        unit = [Fraction(int(q == k)) for q in range(3)]
        rows.append(([_dot(r, _cross(c, unit)) for c in arms.values()], _dot(r, _cross(f, unit))))
    return rows


def moment_constraints(p: Sequence[Expr], t: dict[int, Expr], a: np.ndarray, f: Sequence[Fraction]) -> list[Expr]:
    """The redundant moment balances (module docstring), each ``= 0``: about every taut exit
    point ``a_j``, and in space about the axis through every two of them (free of both
    tensions)."""
    taut = list(t)
    out: list[Expr] = []
    for j in taut:
        for coefficients, load in moment_rows(p, taut, a, f, j):
            acc = load
            for i, c in zip(taut, coefficients):
                if i != j:
                    acc = acc + t[i] * c
            out.append(acc)
        if len(p) == 2:
            continue
        r = [p[k] - float(a[j][k]) for k in range(3)]
        aj = _exact(a[j])
        for i in taut:
            e = [x - y for x, y in zip(_exact(a[i]), aj)]
            if i <= j or not any(e):
                continue
            # about the axis a_j a_i: ((p − a_j) × c) · e = (p − a_j) · (c × e)
            acc = _dot(r, _cross(f, e))
            for q in taut:
                if q not in (i, j):
                    acc = acc + t[q] * _dot(r, _cross([x - y for x, y in zip(_exact(a[q]), aj)], e))
            out.append(acc)
    return out


@dataclass(frozen=True)
class PointMassSubproblem(Subproblem):
    """The system of one taut subset of a point-mass platform, with the interface of the rigid
    :class:`~taut.dgp._formulation.Subproblem` that :func:`~taut.dgp.solve_dgp` uses: the
    unknowns are the position (``pose_unknowns = d``), then the scaled tensions."""

    @property
    def names(self) -> tuple[str, ...]:
        """Names of the pose unknowns (the position's coordinates)."""
        return POSITION_UNKNOWNS[: self.pose_unknowns]

    def pose(self, x: np.ndarray, convention: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(position p, no angles, identity)``: the anchors (all zero) map to ``p``."""
        p, R = self.frame(x)
        return p, np.zeros(0), R

    def unknowns(self, p: npt.ArrayLike, R: npt.ArrayLike = (), t: npt.ArrayLike = ()) -> np.ndarray:
        """The unknowns of the position ``p`` and the scaled tensions ``t = τ/ρ``."""
        return np.concatenate([np.asarray(p, float), np.asarray(t, float)])

    def frame(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return np.array(x[: self.pose_unknowns], float), np.eye(self.pose_unknowns)

    @property
    def tension_unknowns(self) -> bool:
        return True

    @property
    def geometry(self) -> int:
        """0: no manifold contraction (``tube``): HC4 on the moment constraints already
        narrows the position of ``m < d`` taut cables to a plane or a line."""
        return 0

    def tensions(self, x: np.ndarray, lengths: np.ndarray, n: int) -> np.ndarray:
        idx = list(self.taut)
        tau = np.zeros(n)
        tau[idx] = x[self.pose_unknowns :] * lengths[idx]
        return tau


def statics_filter(p: Sequence[Expr], taut: Sequence[int], a: np.ndarray, f: Sequence[Fraction]) -> StaticsFilter:
    """The tension filter's system (§3.1.3, Eqs. 3.9–3.12), ``J(X) t = −w(X)``: the force
    balance, and in space the moments about the first taut exit point below it — the
    ``6 × m`` force-then-moment layout whose preconditioner (Eq. 3.12) swaps the halves."""
    d = len(p)
    rows = [([float(a[i][k]) - p[k] for i in taut], rational_constant(f[k])) for k in range(d)]
    if d == 3:
        rows += moment_rows(p, taut, a, f, taut[0])
    entries = [e for coefficients, _ in rows for e in coefficients] + [-load for _, load in rows]
    return StaticsFilter(compile_tape(entries, [(-np.inf, np.inf)] * len(entries)), len(taut))


#: Relative margin of the initial box beyond the cables' reach.
DOMAIN_MARGIN = 1e-6


def build_point_mass(robot: Robot, lengths: np.ndarray, taut: tuple[int, ...]) -> PointMassSubproblem:
    """The square system of the taut subset ``taut`` (``1 ≤ m ≤ d`` distinct 0-based cables)
    of a point-mass robot at the cable ``lengths``, its initial box and statics filter
    (module docstring).  Constants derived from the data (the load, exit-point differences)
    are exact rationals entered as the float intervals enclosing them."""
    d = robot.dimension
    m = len(taut)
    if not 1 <= m <= d:
        raise TautError(f"a {d}-D point mass hangs on 1 to {d} taut cables, got {m}")
    a = robot.exits
    _, f = point_mass_load(robot)
    v = variables(d + m)
    p, t = v[:d], dict(zip(taut, v[d:]))

    def dist2(i: int) -> Expr:
        return sum(((p[k] - float(a[i][k])) ** 2 for k in range(d)), const(0.0))

    eqs = [dist2(i) - const(float(lengths[i])) ** 2 for i in taut]
    eqs += [sum((t[i] * (float(a[i][k]) - p[k]) for i in taut), const(0.0)) + rational_constant(f[k]) for k in range(d)]
    extra = [(e, (0.0, 0.0)) for e in moment_constraints(p, t, a, f)]
    extra += [(dist2(k) - const(float(lengths[k])) ** 2, (-np.inf, 0.0)) for k in range(robot.n_cables) if k not in t]
    system: System = compile_system(d + m, eqs, extra)
    statics = statics_filter(p, taut, a, f)
    # every cable reaches at most its length: the box of all the balls, widened by DOMAIN_MARGIN
    # so that the position of one taut cable along an axis (a − ρ ẑ) is inside, not on its face
    rad = lengths * (1.0 + DOMAIN_MARGIN)
    lo = np.concatenate([np.nextafter(np.max(a - rad[:, None], axis=0), -np.inf), np.zeros(m)])
    hi = np.concatenate([np.nextafter(np.min(a + rad[:, None], axis=0), np.inf), np.full(m, np.inf)])
    if np.any(lo[:d] > hi[:d]):
        # the balls miss each other: no position at all (a point box HC4 empties at once)
        lo[:d] = hi[:d] = a[0]
    return PointMassSubproblem(
        tuple(taut), system, lo, hi, np.arange(d + m) < d, np.zeros((0, d)), statics, pose_unknowns=d
    )


def point_mass_hessian(exits: np.ndarray, p: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> np.ndarray:
    """The reduced Hessian of the potential on the set of positions that keep the taut lengths
    (Berti 2015, §3.2.2, for a point): ``Nᵀ (Σ τ_i/ρ_i) I N`` with ``N`` an orthonormal basis
    of the null space of the rows ``(p − a_i)ᵀ`` of the taut cables.

    Parameters
    ----------
    exits : ndarray, shape (m, d)
        Exit points [m] of the taut cables.
    p : ndarray, shape (d,)
        The position [m].
    tau, rho : ndarray, shape (m,)
        Tensions [N] and lengths [m] of the taut cables.

    Returns
    -------
    ndarray, shape (k, k)
        ``k = d − rank``; empty when the taut cables fix the position.
    """
    d = p.size
    J = (p - exits) / rho[:, None]
    _, s, vt = np.linalg.svd(J.reshape(-1, d))
    rank = int(np.sum(s > 1e-10 * max(1.0, s[0]))) if s.size else 0
    N = vt[rank:].T
    return float(np.sum(tau / rho)) * (N.T @ N)


def point_mass_stable(exits: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> bool:
    """Whether the reduced Hessian of :func:`point_mass_hessian` is positive definite (a
    position the taut cables fix is stable); the arguments of
    :func:`~taut.dgp.is_stable`, the anchors ``b`` and the load point ``g`` all at the
    position."""
    H = point_mass_hessian(exits, np.asarray(g, float), tau, rho)
    return bool(H.size == 0 or np.linalg.eigvalsh(H)[0] > 0.0)


class _Tracked(Protocol):
    @property
    def p(self) -> np.ndarray: ...

    @property
    def tensions(self) -> np.ndarray: ...


#: Newton's relative tolerance, steps and Krawczyk inflations of a tracking update (as the
#: rigid update of :mod:`taut.dgp._tracking`).
NEWTON_TOL, NEWTON_STEPS, INFLATIONS = 1e-13, 30, 10


@dataclass(frozen=True)
class PointMassTracker:
    """One taut subset of a point-mass robot for tracking: :meth:`update` has the signature
    and the result of the rigid one of :mod:`taut.dgp._tracking`."""

    robot: Robot
    taut: tuple[int, ...]
    margin: float
    floor: float

    def update(
        self, lengths: np.ndarray, s: _Tracked
    ) -> tuple[int, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, float, float]:
        """Newton from the state ``s``'s position at the new ``lengths`` (the tensions from the
        statics there), then Krawczyk on the box that covers the step (:func:`taut.interval.certified_step`).  Returns ``(status, p, R,
        angles, tensions, spans, smallest eigenvalue of the reduced Hessian, box width)``."""
        robot, taut = self.robot, self.taut
        d, n = robot.dimension, robot.n_cables
        idx = list(taut)
        sp = build_point_mass(robot, lengths, taut)
        system = sp.system
        p0 = np.asarray(s.p, float)
        # the tensions are linear at a given position: start from the least-squares ones of this
        # subset, not from the previous subset's (a cable that just became taut has none)
        f, _ = point_mass_load(robot)
        t0 = np.linalg.lstsq((robot.exits[idx] - p0).T, -f, rcond=None)[0]
        x0 = np.concatenate([p0, t0])
        status, x, lo, hi = certified_step(
            *system.tape.arrays[:7],
            system.n_equations,
            *system.jacobian.arrays[:7],
            system.rows,
            system.cols,
            x0,
            self.margin,
            self.floor,
            NEWTON_TOL,
            NEWTON_STEPS,
            INFLATIONS,
        )
        width = float(np.max(hi - lo))
        if status != 1:
            return status, np.asarray(s.p, float), np.eye(d), np.zeros(0), np.zeros(n), np.zeros(n), 0.0, width
        p = x[:d].copy()
        tau = sp.tensions(x, lengths, n)
        spans = np.linalg.norm(robot.exits - p, axis=1)
        H = point_mass_hessian(robot.exits[idx], p, tau[idx], lengths[idx])
        eig = float(np.linalg.eigvalsh(H)[0]) if H.size else np.inf
        return status, p, np.eye(d), np.zeros(0), tau, spans, eig, width


def pivot(
    robot: Robot, p: np.ndarray, tensions: np.ndarray, lengths: np.ndarray, taut: tuple[int, ...], add: int
) -> tuple[int, ...]:
    """The taut set after cable ``add`` becomes taut beside the ``d`` cables of ``taut`` at the
    position ``p``: the ``d + 1`` cables' scaled tensions that balance the load form a line
    ``t + λ n`` (``n`` spanning the null space of the statics); from the current ones
    (``add``'s zero) ``λ`` grows until another tension reaches zero — that cable goes slack
    (the simplex method's ratio test).  ``taut + add`` when no tension decreases."""
    cables = sorted((*taut, add))
    A = (robot.exits[cables] - p).T
    n = np.linalg.svd(A)[2][-1]
    k = cables.index(add)
    if n[k] < 0:
        n = -n
    t = np.asarray(tensions, float)[cables] / lengths[cables]
    steps = [(t[j] / -n[j], i) for j, i in enumerate(cables) if i != add and n[j] < 0]
    if not steps:
        return tuple(cables)
    drop = min(steps)[1]
    return tuple(i for i in cables if i != drop)


def point_mass_igp(
    robot: Robot, taut: tuple[int, ...], fixed: dict[int, float], pos_lo: np.ndarray, pos_hi: np.ndarray
) -> tuple[System, LinearFilter, np.ndarray, np.ndarray, np.ndarray, list[int]]:
    """The inverse problem of a point mass (Berti 2015, §4.1.2): with ``m`` taut cables and
    ``m`` fixed coordinates, the ``d − m`` free coordinates and ``m`` scaled tensions solve
    the ``d`` force balances ``Σ t_i (a_i − p) + f = 0``; the moments about the taut exit
    points are redundant, and so are the tension bounds ``t_i² ‖a_i − p‖² ∈ [τ_min², τ_max²]``.
    Returns ``(system, statics filter, lo, hi, primary, free coordinates)``."""
    d = robot.dimension
    a = robot.exits
    _, f = point_mass_load(robot)
    free = [k for k in range(d) if k not in fixed]
    m = len(taut)
    v = iter(variables(len(free) + m))
    p = [next(v) if k in free else const(fixed[k]) for k in range(d)]
    t = {i: next(v) for i in taut}
    span = {i: [float(a[i][k]) - p[k] for k in range(d)] for i in taut}
    forces = [sum((t[i] * span[i][k] for i in taut), rational_constant(f[k])) for k in range(d)]
    extra = [(e, (0.0, 0.0)) for e in moment_constraints(p, t, a, f)]
    tmin, tmax = robot.tension_bounds
    for i in taut:
        if tmin[i] > 0.0 or np.isfinite(tmax[i]):
            norm2 = sum((s * s for s in span[i][1:]), span[i][0] * span[i][0])
            extra.append((t[i] ** 2 * norm2, (max(float(tmin[i]), 0.0) ** 2, float(tmax[i]) ** 2)))
    nv = len(free) + m
    system = compile_system(nv, forces, extra)
    statics = statics_filter(p, taut, a, f)
    lo = np.concatenate([pos_lo[free], np.zeros(m)])
    hi = np.concatenate([pos_hi[free], np.full(m, np.inf)])
    return system, statics, lo, hi, np.arange(nv) < len(free), free


@dataclass(frozen=True)
class LeastSquaresFit(Result):
    """The position that cable-printer firmware computes from measured lengths — not an
    equilibrium: the least-squares fit of every cable's length, ``min Σ (‖p − a_i‖ − ρ_i)²``,
    which assumes every cable taut, found by trust-region least squares from the exits' centroid
    moved along the load by half the mean length (from the centroid itself it may end on the
    mirror image above the exits).  A local minimum, with no statics: where it differs from
    the certified equilibria, the firmware is wrong.

    Attributes
    ----------
    position : ndarray, shape (d,)
        The fitted position [m].
    residuals : ndarray, shape (n,)
        ``‖p − a_i‖ − ρ_i`` [m] at it.
    rms_residual : float
        Their root mean square [m].

    Examples
    --------
    >>> import numpy as np
    >>> from taut.dgp import solve_dgp
    >>> from taut.model import example
    >>> fit = solve_dgp(example("camera-4cable")).least_squares
    >>> np.round(fit.position, 3), bool(fit.rms_residual < 1e-3)
    (array([ 2.999, -4.   ,  6.   ]), True)
    """

    position: np.ndarray
    residuals: np.ndarray
    rms_residual: float

    def as_dict(self) -> dict:
        """``position``, ``residuals`` (per cable) and ``rms_residual``, in metres."""
        return {
            "position": jsonable(self.position),
            "residuals": jsonable(self.residuals),
            "rms_residual": jsonable(self.rms_residual),
        }


def least_squares_fit(robot: Robot, lengths: np.ndarray) -> LeastSquaresFit:
    """:class:`LeastSquaresFit` of a point-mass robot at the cable ``lengths``."""
    from scipy.optimize import least_squares

    a = robot.exits
    f, _ = point_mass_load(robot)
    start = a.mean(axis=0) + float(np.mean(lengths)) * f / np.linalg.norm(f) / 2.0

    def residuals(p: np.ndarray) -> np.ndarray:
        return np.linalg.norm(p - a, axis=1) - lengths

    fit = least_squares(residuals, start, method="trf", xtol=1e-15, ftol=1e-15, gtol=1e-15)
    return LeastSquaresFit(fit.x, fit.fun, float(np.sqrt(np.mean(fit.fun**2))))
