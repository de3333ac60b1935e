"""The geometrico-static equations of a robot whose cables leave through swivelling pulleys
(``cables[].swivel``): the formulation of :mod:`taut.dgp._formulation` with the pulley model
of :mod:`taut.kinematics._swivel` (Pott 2018, pulley kinematics) written in closed form.

**The pulley in closed form.**  For the cable through the pulley of radius ``r`` whose swivel
axis (unit ``k``) passes through the point ``D`` where the cable runs onto it, and the
platform anchor ``b``: with ``v = b − D``, ``ρ² = ‖v‖²``, ``h = k·v``, the anchor's distance
from the axis ``d = √(ρ² − h²)`` and the free length ``l_f = √(ρ² − 2 r d)`` (the tangent from
``b`` to the pulley circle, whose centre ``D + r e`` lies at ``(d − r, h)`` from ``b`` in the
pulley plane), the tangent point ``C`` at the wrap angle ``β`` satisfies
``cot(β/2) = (h + l_f)/d``: the chord from the circle's far point ``(r, 0)`` to ``C`` meets
the polar line of ``b`` there (the tangency ``(d − r + r cos β, h − r sin β) = l_f (sin β,
cos β)`` of the IK, with ``cos β``, ``sin β`` in terms of ``cot(β/2)``, is a quadratic in it
whose root of the model's branch is this one).  Hence, for ``β ∈ (0, 2π)``,

    L = r β + l_f = r (π − 2 atan((h + l_f)/d)) + l_f,

one arctangent (:func:`taut.interval.atan`) and no other trigonometry.  The cable pulls the
anchor towards ``C``: ``C − b = l_f ((D − b)(l_f + h) + r d k)/Q`` with
``Q = ρ² − r d + h l_f = ½(d² + (h + l_f)²) > 0``, so with the scaled tension ``t = τ/Q``
its force on the platform is the polynomial

    t ((D − b)(l_f + h) + r d k),

and its moment about a pole ``P`` is ``t ((l_f + h)(b − P) × (D − P) + r d (b − P) × k)``
(``(b − P) × (D − b) = (b − P) × (D − P)``, one occurrence of ``b`` as in Berti's moments).
At ``r = 0`` these are the point-exit force ``t (D − b)`` with ``t = τ/ρ`` and length ``ρ``.

**Unknowns and equations.**  Each taut cable through a pulley adds ``d`` and ``l_f`` to the
unknowns of Berti (2015, §2.3.5–2.3.6) — after the reference points and the normal, before
the tensions — and the two equations ``d² + h² − ρ² = 0``, ``l_f² − ρ² + 2 r d = 0`` (after
the normal relations, so that they belong to the pose manifold of the tube step), and its
length equation is ``L − ℓ = 0`` above in place of ``‖b − a‖² = ℓ²``: the system stays
square, and Krawczyk's certificate (its Jacobian through ``d atan u = du/(1 + u²)``) holds
for the pulley model itself.  ``d ≥ 0`` and ``0 ≤ l_f ≤ ℓ`` bound the new unknowns
(``l_f ≥ ℓ − 2π r`` as ``β < 2π``).  A slack cable through a pulley is constrained by its
length ``L(b) ≤ ℓ`` with ``d``, ``l_f`` as square roots, and by ``‖b − D‖ ≤ ℓ`` (a chord is
no longer than its arc); so are the sphere bounds of §3.1.1 (Eq. 3.6), with
``ℓ − 2π r ≤ ‖b − D‖ ≤ ℓ`` for a taut one.  Every constant is an outward-rounded
enclosure of the data's exact value (the unit axis ``k = axis/‖axis‖``, ``π``).

**Stability.**  The length's gradient is ``n = (b − C)/l_f`` and its Hessian is
``t tᵀ/l_f + (sin β/d) g gᵀ`` (``t = cos β e − sin β k``, ``g = k × e`` the direction the
pulley swivels): the point-exit Hessian ``(I − n nᵀ)/l_f`` of a cable leaving from ``C``, less
``(1/l_f − sin β/d) g gᵀ``.  The reduced Hessian of Berti (2015, §3.2.2) is taken with the
exit point ``C`` and length ``l_f``, corrected by that term.

**One taut cable.**  The free segment hangs along the load ``f``: ``n = f/‖f‖``, so
``cos β = k·n``, the pulley faces ``e = ±(n − (k·n)k)/‖·‖`` (two branches), the wrap
``β = atan2(sin β, cos β)`` and ``l_f = ℓ − r β`` are fixed, and the platform hangs from the
fixed point ``C`` as from an exit point, spinning by ``ϑ`` about the vertical through the
anchor (Berti 2015, §2.3.3); it is stable with ``G`` below the anchor, as there, unless the
wrap exceeds half a turn (the swivel's stiffness ``τ sin β/d`` is then negative).  A slack
cable through a pulley fits when ``L(b_k(ϑ)) ≤ ℓ_k``;
the ends of those arcs are isolated with the Lipschitz bound ``|dL/dϑ| ≤ ‖b_k − axis‖``
(``∇L`` is a unit vector), so that no arc is missed between samples.

References
----------
.. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
   Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
.. [2] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
   Università di Bologna, 2015, §2.3, §3.1.1, §3.1.3, §3.2.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from fractions import Fraction

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_index
from taut.dgp._formulation import (
    OTHER_POLES_UP_TO,
    StaticsFilter,
    Subproblem,
    _cross,
    _exact,
    _exact_load,
    load,
    rational_constant,
    reference_choice,
    secondary_coordinates,
)
from taut.dgp._single_cable import TWO_PI, _axis_rotation, _rotation_to
from taut.dgp._undecided import REFERENCE_UNKNOWNS
from taut.errors import CableSetError, TautError
from taut.interval import (
    Expr,
    Interval,
    Tape,
    atan,
    compile_system,
    compile_tape,
    const,
    evaluate,
    evaluate_point,
    sqrt,
    variables,
)
from taut.kinematics import swivel_parameters, swivel_paths
from taut.model import Robot

#: ``π`` between two floats: ``np.pi`` is the float below it.
PI = const(float(np.pi), float(np.nextafter(np.pi, np.inf)))

#: Interval width (radians) below which a sub-arc whose slack-cable condition changes sign
#: is cut at its middle (an end of an arc of one-cable equilibria).
ARC_TOL = 1e-12


def _unit_enclosure(axis: Sequence[float]) -> list[Expr]:
    """The unit vector ``axis/‖axis‖`` of a float axis, each component as an interval proven
    (in rational arithmetic) to hold the exact quotient."""
    q = [Fraction(float(c)) for c in axis]
    n2 = sum((c * c for c in q), Fraction(0))
    out = []
    for c in q:
        est = float(c) / float(np.sqrt(float(n2)))
        lo, hi = est, est
        for _ in range(60):
            lo, hi = float(np.nextafter(lo, -np.inf)), float(np.nextafter(hi, np.inf))
            # c/√n2 ≥ lo ⇔ lo ≤ 0 ≤ c, or the squares compare (by the signs)
            below = (
                (lo <= 0 <= c)
                or (c < 0 and lo < 0 and Fraction(lo) ** 2 * n2 >= c * c)
                or (c > 0 < lo and Fraction(lo) ** 2 * n2 <= c * c)
            )
            above = (
                (hi >= 0 >= c)
                or (c > 0 and hi > 0 and Fraction(hi) ** 2 * n2 >= c * c)
                or (c < 0 > hi and Fraction(hi) ** 2 * n2 <= c * c)
            )
            if below and above:
                break
        else:  # pragma: no cover - the float quotient is within a few ulps
            raise AssertionError("no enclosure of a unit axis component")
        out.append(const(0.0) if c == 0 else const(lo, hi))
    return out


@dataclass(frozen=True)
class _Pulley:
    """The closed-form pulley quantities of one cable, as expressions of its anchor."""

    rho2: Expr  #: ‖b − D‖²
    h: Expr  #: k·(b − D)
    k: list[Expr]  #: the unit axis


def _pulley(b: Sequence[Expr], exit_point: np.ndarray, axis: Sequence[float]) -> _Pulley:
    k = _unit_enclosure(axis)
    v = [b[c] - float(exit_point[c]) for c in range(3)]
    rho2 = sum((x**2 for x in v), const(0.0))
    h = sum((kc * x for kc, x in zip(k, v) if not kc.is_const(0.0)), const(0.0))
    return _Pulley(rho2, h, k)


def _length(r: float, d: Expr, lf: Expr, h: Expr) -> Expr:
    """``L = r (π − 2 atan((h + l_f)/d)) + l_f`` (module docstring)."""
    return const(r) * PI - const(2.0 * r) * atan((h + lf) / d) + lf


@dataclass(frozen=True)
class PulleySubproblem(Subproblem):
    """A :class:`~taut.dgp._formulation.Subproblem` whose taut cables may leave through
    swivelling pulleys: the pose unknowns include ``d`` and ``l_f`` of each such cable
    (module docstring), and a tension is ``τ = t Q`` for them (``τ = t ρ`` otherwise)."""

    robot: Robot | None = None
    scale: Tape | None = None  #: ``Q`` (pulley) or ``ρ`` (fixed exit) of each taut cable
    names: tuple[str, ...] = ()  #: names of the pose unknowns

    def unknowns(self, p: npt.ArrayLike, R: npt.ArrayLike, t: npt.ArrayLike = ()) -> np.ndarray:
        """The unknowns of the platform frame ``(p, R)``; ``t`` are the scaled tensions."""
        assert self.robot is not None
        p, R = np.asarray(p, float), np.asarray(R, float)
        q = p + self.body_refs @ R.T
        normal = [np.cross(q[1] - q[0], q[2] - q[0])] if len(self.names) - 9 - 2 * self._pulleys() == 3 else []
        b = p + self.robot.anchors @ R.T
        extra = []
        for i in self._swivel_taut():
            d, lf, _, _ = _plane(self.robot, i, b[i])
            extra += [d, lf]
        return np.concatenate([q.ravel(), *normal, np.array(extra, float), np.asarray(t, float)])

    def _swivel_taut(self) -> list[int]:
        assert self.robot is not None
        return [i for i in self.taut if self.robot.cables[i].swivel is not None]

    def _pulleys(self) -> int:
        return len(self._swivel_taut())

    @property
    def unknown_names(self) -> tuple[str, ...]:
        return self.names

    def tensions(self, x: np.ndarray, lengths: np.ndarray, n: int) -> np.ndarray:
        """Tensions of all ``n`` cables (0 for slack ones) at the unknowns ``x``."""
        assert self.scale is not None
        idx = list(self.taut)
        tau = np.zeros(n)
        q = evaluate_point(self.scale, np.asarray(x, float))
        if self.tension_unknowns:
            tau[idx] = x[self.pose_unknowns :] * q
        else:
            v = evaluate_point(self.statics.tape, np.asarray(x, float))
            m = len(idx)
            tau[idx] = np.linalg.solve(v[: 6 * m].reshape(6, m), v[6 * m :]) * q
        return tau

    def tension_enclosure(
        self, t_lo: np.ndarray, t_hi: np.ndarray, lengths: np.ndarray, lo: np.ndarray, hi: np.ndarray
    ) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """Bounds of the tensions ``t Q`` over the box ``[lo, hi]`` (``Q > 0`` enclosed there)."""
        assert self.scale is not None
        s_lo, s_hi = evaluate(self.scale, lo, hi)
        s = Interval(np.maximum(s_lo, 0.0), s_hi)
        tau = Interval(np.asarray(t_lo, float), np.asarray(t_hi, float)) * s
        return tuple(np.asarray(tau.lo, float).tolist()), tuple(np.asarray(tau.hi, float).tolist())


def _plane(robot: Robot, i: int, b: np.ndarray) -> tuple[float, float, float, np.ndarray]:
    """``(d, l_f, h, k)`` of cable ``i``'s pulley for the anchor at ``b`` (floats)."""
    swivel = robot.cables[i].swivel
    assert swivel is not None
    k = np.asarray(swivel.axis, float)
    k = k / np.linalg.norm(k)
    v = b - robot.exits[i]
    h = float(k @ v)
    rho2 = float(v @ v)
    d = float(np.sqrt(max(rho2 - h * h, 0.0)))
    lf = float(np.sqrt(max(rho2 - 2.0 * swivel.radius * d, 0.0)))
    return d, lf, h, k


def pulley_subproblem(
    robot: Robot, lengths: npt.ArrayLike, taut: tuple[int, ...], *, normal: bool = True
) -> PulleySubproblem:
    """The square system of one taut subset of a robot with swivelling pulleys (module
    docstring), its initial box and the maps back to poses and tensions.

    Parameters
    ----------
    robot : Robot
        A spatial rigid platform; cables with and without ``swivel`` may be mixed.
    lengths : array_like, shape (n,)
        Cable lengths [m], the arcs wound on the pulleys included.
    taut : tuple of int
        The taut cables (0-based), ``1 ≤ m ≤ 6``.
    normal : bool, optional
        Make the plane normal of the reference points an unknown when some cable anchor lies
        off their plane.

    Returns
    -------
    PulleySubproblem

    Raises
    ------
    CableSetError
        Taut cables that are not 1 to 6 distinct cables of the robot.
    TautError
        Lengths that are not ``n`` finite numbers.

    References
    ----------
    .. [1] A. Pott, "Cable-Driven Parallel Robots: Theory and Application", Springer Tracts in
       Advanced Robotics 120, Springer, 2018, pulley kinematics. (docs/references.bib: pott2018)
    .. [2] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §2.3, §3.1.1, §3.1.3. (docs/references.bib: berti2015)

    Examples
    --------
    Three taut cables through pulleys: 9 reference-point coordinates, ``d`` and ``l_f`` of
    each pulley, 3 scaled tensions.

    >>> from taut.dgp import pulley_subproblem
    >>> from taut.model import example
    >>> robot = example("suspended-3pulley")
    >>> sp = pulley_subproblem(robot, robot.reference.lengths, (0, 1, 2))
    >>> sp.system.n, sp.pose_unknowns
    (18, 15)
    """
    n = robot.n_cables
    lengths = as_array(lengths, "cable lengths", shape=(n,))
    try:
        taut = tuple(as_index(i, "taut cables", n, error=CableSetError) for i in taut)
    except TypeError:
        raise CableSetError(f"taut cables: expected cable indices 0..{n - 1}, got {taut!r}") from None
    if not 1 <= len(taut) <= 6 or len(set(taut)) != len(taut):
        raise CableSetError(f"taut cables: expected 1 to 6 distinct cables, got {list(taut)}")
    m = len(taut)
    a, r = robot.exits, robot.anchors
    swivels = {i: c.swivel for i, c in enumerate(robot.cables) if c.swivel is not None}
    pulleys = [i for i in taut if i in swivels]
    _, _, gp = load(robot)
    f, mext = _exact_load(robot)
    labels, refs = reference_choice(robot, taut, gp)
    betas = {lab: secondary_coordinates(refs, body) for lab, body in [*enumerate(r), ("G", gp)] if lab not in labels}
    normal = normal and any(betas[k][2] != 0 for k in range(n) if k in betas)
    pose = (12 if normal else 9) + 2 * len(pulleys)
    unknowns = pose if m == 6 else pose + m
    v = variables(unknowns)
    q = [v[0:3], v[3:6], v[6:9]]
    base = 12 if normal else 9
    plane = {i: (v[base + 2 * j], v[base + 2 * j + 1]) for j, i in enumerate(pulleys)}  # (d, l_f)
    t = dict(zip(taut, v[pose:]))
    e1 = [q[1][k] - q[0][k] for k in range(3)]
    e2 = [q[2][k] - q[0][k] for k in range(3)]
    n12 = v[9:12] if normal else _cross(e1, e2)

    def point(label: int | str) -> list[Expr]:
        """A secondary point (Eqs. 2.23–2.24), as in :func:`~taut.dgp._formulation.build_subproblem`."""
        if label in labels:
            return q[labels.index(label)]
        beta = betas[label]
        weights = (1 - beta[0] - beta[1], beta[0], beta[1])
        out = []
        for k in range(3):
            terms = [qj[k] if c == 1 else rational_constant(c) * qj[k] for c, qj in zip(weights, q) if c != 0]
            if beta[2] != 0:
                terms.append(rational_constant(beta[2]) * n12[k])
            out.append(sum(terms[1:], terms[0]) if terms else const(0.0))
        return out

    b = {i: point(i) for i in range(n)}
    g = point("G")
    geo = {i: _pulley(b[i], a[i], s.axis) for i, s in swivels.items()}

    def dist2(p: Sequence[Expr], c: np.ndarray) -> Expr:
        return sum(((p[k] - float(c[k])) ** 2 for k in range(3)), const(0.0))

    eqs: list[Expr] = []
    for i, j in ((0, 1), (0, 2), (1, 2)):
        d2 = sum(((x - y) ** 2 for x, y in zip(_exact(refs[i]), _exact(refs[j]))), Fraction(0))
        eqs.append(sum(((q[i][k] - q[j][k]) ** 2 for k in range(3)), const(0.0)) - rational_constant(d2))
    for i in taut:
        if i in swivels:
            d, lf = plane[i]
            eqs.append(_length(swivels[i].radius, d, lf, geo[i].h) - float(lengths[i]))
        else:
            eqs.append(dist2(b[i], a[i]) - const(float(lengths[i])) ** 2)
    if normal:
        eqs += [nk - ck for nk, ck in zip(n12, _cross(e1, e2))]
    for i in pulleys:
        d, lf = plane[i]
        eqs.append(d**2 + geo[i].h ** 2 - geo[i].rho2)
        eqs.append(lf**2 - geo[i].rho2 + const(2.0 * swivels[i].radius) * d)

    def force(i: int, k: int) -> Expr:
        """Component ``k`` of cable ``i``'s force per unit scaled tension."""
        if i in swivels:
            d, lf = plane[i]
            return (float(a[i][k]) - b[i][k]) * (lf + geo[i].h) + const(swivels[i].radius) * d * geo[i].k[k]
        return float(a[i][k]) - b[i][k]

    def moment_arm(i: int, pole: np.ndarray, k: int) -> Expr:
        """Component ``k`` of cable ``i``'s moment about ``pole`` per unit scaled tension."""
        k1, k2 = (k + 1) % 3, (k + 2) % 3
        c = [x - y for x, y in zip(_exact(a[i]), _exact(pole))]
        arm = (b[i][k1] - float(pole[k1])) * rational_constant(c[k2]) - (b[i][k2] - float(pole[k2])) * (
            rational_constant(c[k1])
        )
        if i not in swivels:
            return arm
        d, lf = plane[i]
        kk = geo[i].k
        bp = [b[i][c] - float(pole[c]) for c in range(3)]
        axial = bp[k1] * kk[k2] - bp[k2] * kk[k1]
        return arm * (lf + geo[i].h) + const(swivels[i].radius) * d * axial

    def load_moment(pole: np.ndarray, k: int) -> Expr:
        k1, k2 = (k + 1) % 3, (k + 2) % 3
        return (
            (g[k1] - float(pole[k1])) * rational_constant(f[k2]) - (g[k2] - float(pole[k2])) * rational_constant(f[k1])
        ) + rational_constant(mext[k])

    def moments(pole: np.ndarray) -> list[Expr]:
        out = []
        for k in range(3):
            acc: Expr = load_moment(pole, k)
            for i in taut:
                acc = acc + t[i] * moment_arm(i, pole, k)
            out.append(acc)
        return out

    widen = 1.0 + 4.0 * np.finfo(float).eps

    def shortest(j: int) -> float:
        """A lower bound of ``‖b_j − a_j‖`` for taut cable ``j``: ``ℓ``, less a full turn
        of its pulley."""
        if j not in swivels:
            return float(lengths[j])
        return float(lengths[j]) - 2.0 * np.pi * swivels[j].radius * widen

    if m < 6:
        for k in range(3):
            eqs.append(sum((t[i] * force(i, k) for i in taut), const(0.0)) + rational_constant(f[k]))
    extra = []
    if normal:
        d01, d02, d12 = (
            sum(((x - y) ** 2 for x, y in zip(_exact(refs[i]), _exact(refs[j]))), Fraction(0))
            for i, j in ((0, 1), (0, 2), (1, 2))
        )
        dot = (d01 + d02 - d12) / 2
        area2 = d01 * d02 - dot * dot
        extra.append((sum((nk * nk for nk in n12), const(0.0)) - rational_constant(area2), (0.0, 0.0)))
        extra += [(sum((nk * ek for nk, ek in zip(n12, e)), const(0.0)), (0.0, 0.0)) for e in (e1, e2)]
    if m < 6:
        eqs += moments(a[taut[0]])
        if m <= OTHER_POLES_UP_TO:
            extra += [(e, (0.0, 0.0)) for j in taut[1:] for e in moments(a[j])]
    for i in pulleys:
        # the chord ‖b − D‖ lies between the free length and the whole length
        near = float(np.nextafter(max(0.0, shortest(i) / widen) ** 2, -np.inf))
        extra.append((geo[i].rho2, (near, float(np.nextafter((lengths[i] * widen) ** 2, np.inf)))))
    for k in range(n):
        if k not in taut:
            extra.append((dist2(b[k], a[k]) - const(float(lengths[k])) ** 2, (-np.inf, 0.0)))
            if k in swivels:
                gk = geo[k]
                d = sqrt(gk.rho2 - gk.h**2)
                lf = sqrt(gk.rho2 - const(2.0 * swivels[k].radius) * d)
                extra.append((_length(swivels[k].radius, d, lf, gk.h), (-np.inf, float(lengths[k]))))
    for s, (lab, body) in enumerate(zip(labels, refs)):
        for j in range(n):
            if j == lab:
                continue
            dq = float(np.linalg.norm(body - r[j]))
            upper = float(np.nextafter(((lengths[j] + dq) * widen) ** 2, np.inf))
            near = (shortest(j) - dq) / widen
            lower = float(np.nextafter(near**2, -np.inf)) if j in taut and near > 0.0 else -np.inf
            extra.append((dist2(q[s], a[j]), (lower, upper)))
    system = compile_system(unknowns, eqs, extra)
    pole = a[taut[0]]
    J = [[force(i, k) for i in taut] for k in range(3)] + [[moment_arm(i, pole, k) for i in taut] for k in range(3)]
    rhs = [-rational_constant(f[k]) for k in range(3)] + [-load_moment(pole, k) for k in range(3)]
    statics_tape = compile_tape([e for row in J for e in row] + rhs, [(-np.inf, np.inf)] * (6 * m + 6))
    scale = []
    for i in taut:
        if i in swivels:
            d, lf = plane[i]
            scale.append(geo[i].rho2 - const(swivels[i].radius) * d + geo[i].h * lf)
        else:
            scale.append(const(float(lengths[i])))
    scale_tape = compile_tape(scale, [(-np.inf, np.inf)] * m)

    lo = np.full(unknowns, -np.inf)
    hi = np.full(unknowns, np.inf)
    for s, body in enumerate(refs):
        for j in taut:
            rad = (lengths[j] + float(np.linalg.norm(body - r[j]))) * (1.0 + 4.0 * np.finfo(float).eps)
            lo[3 * s : 3 * s + 3] = np.maximum(lo[3 * s : 3 * s + 3], np.nextafter(a[j] - rad, -np.inf))
            hi[3 * s : 3 * s + 3] = np.minimum(hi[3 * s : 3 * s + 3], np.nextafter(a[j] + rad, np.inf))
    if normal:
        rad = float(np.nextafter(np.sqrt(float(area2)) * (1.0 + 4.0 * np.finfo(float).eps), np.inf))
        lo[9:12], hi[9:12] = -rad, rad
    for j, i in enumerate(pulleys):
        top = float(np.nextafter(lengths[i] * widen, np.inf))
        lo[base + 2 * j], hi[base + 2 * j] = 0.0, top
        lo[base + 2 * j + 1], hi[base + 2 * j + 1] = max(0.0, shortest(i) / widen), top
    lo[pose:], hi[pose:] = 0.0, np.inf
    primary = np.arange(unknowns) < 9
    names = REFERENCE_UNKNOWNS[:base] + tuple(f"{x}_{i + 1}" for i in pulleys for x in ("d", "l_f"))
    return PulleySubproblem(
        tuple(taut),
        system,
        lo,
        hi,
        primary,
        refs,
        StaticsFilter(statics_tape, m, sign_only=m == 6),
        pose,
        robot,
        scale_tape,
        names,
    )


def cable_spans(robot: Robot, b: np.ndarray) -> np.ndarray:
    """The length each cable needs to reach its anchor ``b`` (fixed frame, ``(n, 3)``): the
    distance from its exit point, or through its swivelling pulley the arc and the free
    length (:func:`taut.kinematics.swivel_paths`)."""
    spans = np.array([np.linalg.norm(b[k] - robot.exits[k]) for k in range(robot.n_cables)])
    if robot.swivel_cables:
        idx, axes, radii = swivel_parameters(robot)
        spans[idx] = swivel_paths(robot.exits[idx], axes, radii, b[idx][None]).lengths[0]
    return spans


def _skew(v: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def pulley_stable(robot: Robot, b: np.ndarray, g: np.ndarray, tau: np.ndarray, idx: Sequence[int]) -> bool:
    """Whether an equilibrium with the taut cables ``idx`` is stable: the reduced Hessian of
    Berti (2015, §3.2.2) with each pulley's cable leaving from its tangent point, corrected by
    the pulley's swivel (module docstring), is positive definite.

    Parameters
    ----------
    robot : Robot
    b : ndarray, shape (n, 3)
        Every anchor [m] at the equilibrium, fixed frame.
    g : ndarray, shape (3,)
        Load point [m], fixed frame.
    tau : ndarray, shape (n,)
        Tensions [N].
    idx : sequence of int
        The taut cables.

    Returns
    -------
    bool
    """
    H = np.zeros((6, 6))
    rows = []
    swivel = set(robot.swivel_cables)
    for i in idx:
        d, lf, h, k = _plane(robot, i, b[i]) if i in swivel else (0.0, 0.0, 0.0, np.zeros(3))
        if d > 1e-12 * (lf + h + 1.0):
            pulley = robot.cables[i].swivel
            assert pulley is not None
            e = (b[i] - robot.exits[i] - h * k) / d
            paths = swivel_paths(robot.exits[[i]], k[None], [pulley.radius], b[[i]][None])
            exit_point, beta = paths.tangent_points[0, 0], float(paths.wrap[0, 0])
            soft = 1.0 / lf - np.sin(beta) / d  # the swivel's softening, 1/l_f − sin β / d
            swing = np.cross(k, e)
        else:  # a fixed exit, or an anchor on the swivel axis: the cable pivots about the exit
            exit_point, lf, soft, swing = robot.exits[i], float(np.linalg.norm(b[i] - robot.exits[i])), 0.0, None
        w = tau[i] / lf
        Bg = _skew(b[i] - g)
        Ga = _skew(g - exit_point)
        H[:3, :3] += w * np.eye(3)
        H[:3, 3:] -= w * Bg
        H[3:, :3] += w * Bg
        H[3:, 3:] += w * 0.5 * (Bg @ Ga + Ga @ Bg)
        if swing is not None:
            A = np.hstack([np.eye(3), -Bg])  # δb of the twist (δp, δθ) about G
            s = swing @ A
            H -= tau[i] * soft * np.outer(s, s)
        u = (b[i] - exit_point) / lf
        rows.append(np.concatenate([u, np.cross(b[i] - g, u)]))
    if not rows:
        return False
    _, sv, vt = np.linalg.svd(np.array(rows))
    rank = int(np.sum(sv > 1e-10 * max(1.0, sv[0])))
    N = vt[rank:].T
    if N.size == 0:
        return True
    Hr = N.T @ H @ N
    return bool(np.linalg.eigvalsh(0.5 * (Hr + Hr.T))[0] > 0.0)


def _roots(fun: Callable[[float], float], slope: float, lo: float, hi: float) -> list[float]:
    """Points where ``fun`` (Lipschitz with constant ``slope``) may change sign on
    ``[lo, hi]``: sub-intervals whose ends' values cannot meet zero between them are dropped,
    the others halved down to :data:`ARC_TOL` and cut at their middle."""
    out: list[float] = []
    stack = [(lo, hi, fun(lo), fun(hi))]
    slack = slope * (1.0 + 1e-9) + 1e-12
    while stack:
        x0, x1, f0, f1 = stack.pop()
        if f0 * f1 > 0.0 and abs(f0) + abs(f1) > slack * (x1 - x0):
            continue
        if x1 - x0 <= ARC_TOL:
            out.append(0.5 * (x0 + x1))
            continue
        xm = 0.5 * (x0 + x1)
        fm = fun(xm)
        stack += [(x0, xm, f0, fm), (xm, x1, fm, f1)]
    return out


def pulley_single_cable(robot: Robot, lengths: np.ndarray, i: int) -> list[dict]:
    """Equilibria of a robot with swivelling pulleys with cable ``i`` alone taut, as
    :func:`~taut.dgp._single_cable.single_cable_equilibria` gives them (module docstring,
    "One taut cable"): dicts with ``R``, ``p``, ``tensions``, ``stable`` and the spin arc
    ``continuum``.  A load along the cable's swivel axis, the way the cable comes, hangs the
    platform straight from the exit point, unwrapped; a load against it would wrap the cable
    half a turn with the pulley free to swivel (a family of two parameters, not isolated
    even in the spin): none is reported for it."""
    f, mext, gp = load(robot)
    F = float(np.linalg.norm(f))
    if F == 0.0 or np.any(mext != 0.0):
        return []
    fh = f / F
    a, r = robot.exits, robot.anchors
    v = gp - r[i]
    if np.linalg.norm(v) == 0.0:
        return []
    hangs = []  # (point the cable hangs from, free length)
    pulley = robot.cables[i].swivel
    if pulley is None:
        hangs.append(a[i])
        free = [float(lengths[i])]
        wraps = [0.0]
    else:
        k = np.asarray(pulley.axis, float) / np.linalg.norm(pulley.axis)
        c = float(k @ fh)
        side = fh - c * k
        s = float(np.linalg.norm(side))
        free, wraps = [], []
        if s <= 1e-12 and c > 0.0:
            # the load along the axis: the cable runs straight on, unwrapped, from the exit
            # point (the pulley's swivel angle does not matter)
            hangs.append(a[i])
            free.append(float(lengths[i]))
            wraps.append(0.0)
        elif s > 1e-12:
            for sign in (1.0, -1.0):
                e = sign * side / s
                beta = float(np.arctan2(sign * s, c)) % TWO_PI
                lf = float(lengths[i]) - pulley.radius * beta
                tangent = a[i] + pulley.radius * e + pulley.radius * (-c * e + sign * s * k)
                # the pulley faces the anchor: d > 0 on this branch
                if lf > 0.0 and e @ (tangent + lf * fh - a[i]) > 0.0:
                    hangs.append(tangent)
                    free.append(lf)
                    wraps.append(beta)
    swivel = set(robot.swivel_cables)
    out = []
    for hang, lf, beta in zip(hangs, free, wraps):
        bi = hang + lf * fh
        for side_sign in (1.0, -1.0):
            R0 = _rotation_to(v / np.linalg.norm(v), side_sign * fh)
            excesses: list[Callable[[float], float]] = []  # ≤ 0 where slack cable k fits
            cuts = [0.0, TWO_PI]
            for k in range(robot.n_cables):
                if k == i:
                    continue
                w0 = R0 @ (r[k] - r[i])

                def anchor(th: float, w0: np.ndarray = w0, bi: np.ndarray = bi) -> np.ndarray:
                    return bi + _axis_rotation(fh, th) @ w0

                if k in swivel:

                    def excess(th: float, k: int = k, anchor: Callable = anchor) -> float:
                        return float(_span(robot, k, anchor(th)) - lengths[k])

                    radius = float(np.linalg.norm(w0 - (w0 @ fh) * fh))
                    cuts += _roots(excess, radius, 0.0, TWO_PI)
                    excesses.append(excess)
                else:
                    cvec = bi - a[k]
                    wpar = (w0 @ fh) * fh
                    wperp = w0 - wpar
                    base_v = cvec + wpar
                    A = base_v @ base_v + wperp @ wperp - lengths[k] ** 2
                    B, C = 2.0 * base_v @ wperp, 2.0 * base_v @ np.cross(fh, wperp)
                    rr = np.hypot(B, C)
                    if rr > 0 and abs(A) <= rr:
                        phi = np.arctan2(C, B)
                        dd = np.arccos(np.clip(-A / rr, -1.0, 1.0))
                        cuts += [(phi + dd) % TWO_PI, (phi - dd) % TWO_PI]

                    def trig(th: float, A: float = A, B: float = B, C: float = C) -> float:
                        return float(A + B * np.cos(th) + C * np.sin(th))

                    excesses.append(trig)
            ends = np.unique(cuts)
            arcs = [
                (lo, hi)
                for lo, hi in zip(ends[:-1], ends[1:])
                if hi > lo and all(fn(0.5 * (lo + hi)) <= 0.0 for fn in excesses)
            ]
            merged: list[list[float]] = []
            for lo, hi in arcs:
                if merged and abs(merged[-1][1] - lo) < 1e-15:
                    merged[-1][1] = hi
                else:
                    merged.append([lo, hi])
            if len(merged) > 1 and merged[0][0] == 0.0 and merged[-1][1] == TWO_PI:
                first = merged.pop(0)
                merged[-1][1] = TWO_PI + first[1]
            for lo, hi in merged:
                R = _axis_rotation(fh, 0.5 * (lo + hi)) @ R0
                p = bi - R @ r[i]
                tau = np.zeros(robot.n_cables)
                tau[i] = F
                # as for a fixed exit, G below the anchor (the spin is neutral); a pulley
                # wrapped beyond half a turn swivels away from the vertical (stiffness
                # τ sin β / d < 0)
                stable = side_sign > 0 and np.sin(beta) >= 0.0
                out.append({"R": R, "p": p, "tensions": tau, "stable": stable, "continuum": (lo, hi)})
    return out


def _span(robot: Robot, k: int, bk: np.ndarray) -> float:
    """Cable ``k``'s length to the anchor ``bk`` through its pulley."""
    idx, axes, radii = swivel_parameters(robot)
    j = int(np.flatnonzero(idx == k)[0])
    return float(swivel_paths(robot.exits[[k]], axes[[j]], radii[[j]], bk[None, None]).lengths[0, 0])


def check_pulley_reach(robot: Robot, lengths: np.ndarray) -> None:
    """Refuse a pulley whose radius is not smaller than its cable's length, the reach of the
    anchor from the exit point: the cable would not clear its own pulley.

    Raises
    ------
    TautError
        Such a pulley, named by its cable's 1-based number.
    """
    for i in robot.swivel_cables:
        pulley = robot.cables[i].swivel
        assert pulley is not None
        if pulley.radius >= lengths[i]:
            raise TautError(
                f"{robot.name}: cable {i + 1}'s pulley radius {pulley.radius:g} m is not smaller than the cable's "
                f"length {lengths[i]:g} m, the anchor's reach from its exit point"
            )


def pulley_update(
    robot: Robot,
    taut: tuple[int, ...],
    lengths: np.ndarray,
    p0: np.ndarray,
    R0: np.ndarray,
    tau0: np.ndarray,
    margin: float,
    floor: float,
) -> tuple[int, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, float, float]:
    """One certified tracking update of a robot with swivelling pulleys (the steps 1–2 of
    :mod:`taut.dgp._tracking`): Newton from the state ``(p0, R0, tau0)`` on the pulley
    sub-problem of ``taut`` at the new ``lengths`` (built afresh: its lengths enter through the
    arctangent equations, not as patchable squares), then Krawczyk on the box about the
    limit (:func:`taut.interval.certified_step`, half-width ``margin`` times the step plus
    ``floor``).  Returns ``(status, p, R, angles, tensions, spans, eigenvalue sign, box
    width)`` as the compiled update of :mod:`taut.dgp._tracking` does (status 1: certified;
    the stability as ``±1``)."""
    from taut.geometry import angles_from_matrix
    from taut.interval import certified_step

    n = robot.n_cables
    sp = pulley_subproblem(robot, lengths, taut, normal=False)
    idx = list(taut)
    m = len(idx)
    x0 = sp.unknowns(p0, R0, np.zeros(m) if sp.tension_unknowns else ())
    if sp.tension_unknowns:
        assert sp.scale is not None
        x0[sp.pose_unknowns :] = tau0[idx] / evaluate_point(sp.scale, x0)
    system = sp.system
    status, x, lo, hi = certified_step(
        *system.tape.arrays[:7],
        system.n_equations,
        *system.jacobian.arrays[:7],
        system.rows,
        system.cols,
        x0,
        margin,
        floor,
        1e-13,
        30,
        10,
    )
    width = float(np.max(hi - lo))
    if status != 1:
        return int(status), p0, R0, np.zeros(3), np.zeros(n), np.zeros(n), 0.0, width
    p, R = sp.frame(x)
    tau = sp.tensions(x, lengths, n)
    b = p + robot.anchors @ R.T
    g = p + R @ load(robot)[2]
    stable = pulley_stable(robot, b, g, tau, idx)
    ang = angles_from_matrix(R, robot.orientation)
    return 1, p, R, ang, tau, cable_spans(robot, b), 1.0 if stable else -1.0, width


def pulley_igp_problem(
    robot: Robot,
    taut: tuple[int, ...],
    fixed: dict[int, float],
    pos_lo: np.ndarray,
    pos_hi: np.ndarray,
    orientation: tuple[float, Callable, Callable, Callable],
) -> tuple:
    """The inverse geometrico-static problem of :mod:`taut.dgp._inverse` for a robot whose
    taut cables may leave through swivelling pulleys: the unknowns gain ``d`` and ``l_f`` of
    each such cable (before the tensions, which stay last) with the equations
    ``d² + h² − ρ² = 0`` and ``l_f² − ρ² + 2 r d = 0``; a pulley cable's force is
    ``t ((D − b)(l_f + h) + r d k)`` with ``t = τ/Q`` (module docstring), its moments about
    the first taut anchor and about the axes through two anchors follow from it (the axes
    through two exit points only for fixed exits: a pulley cable's force passes through its
    tangent point).  No length enters: the lengths to command are the pulley IK's at the
    solution.

    ``orientation`` holds what :mod:`taut.dgp._inverse` writes the orientation with (it
    imports this module, so this module does not import it): the bound of the cosine and sine
    unknowns, the enclosures of an assigned angle's cosine and sine, the half-turn
    restriction and the rotation matrix as polynomials.  Returns the fields of its
    ``_Problem``: system, statics filter, box, primary unknowns, free position coordinates,
    free angles and the names of the pulley unknowns."""
    from taut.interval import ZERO, LinearFilter

    cos_sin_bound, cos_sin, half_turn_restricted, rotation = orientation

    a, r = robot.exits, robot.anchors
    f, mext, gp = load(robot)
    m = len(taut)
    swivels = {i: c.swivel for i, c in enumerate(robot.cables) if c.swivel is not None}
    pulleys = [i for i in taut if i in swivels]
    free_pos = [k for k in range(3) if k not in fixed]
    free_ang = [k for k in range(3) if 3 + k not in fixed]
    nv = len(free_pos) + 2 * len(free_ang) + 2 * len(pulleys) + m
    v = iter(variables(nv))
    p = [next(v) if k in free_pos else const(fixed[k]) for k in range(3)]
    cs = [(next(v), next(v)) if k in free_ang else cos_sin(fixed[3 + k]) for k in range(3)]
    if robot.orientation == "tilt-torsion" and 2 not in free_ang:
        (c_phi, s_phi), (c_sigma, s_sigma) = cs[0], cs[2]
        cs[2] = (c_sigma * c_phi + s_sigma * s_phi, s_sigma * c_phi - c_sigma * s_phi)
    plane = {i: (next(v), next(v)) for i in pulleys}
    t = {i: next(v) for i in taut}
    R = rotation(cs, robot.orientation)

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
    geo = {i: _pulley(b[i], a[i], swivels[i].axis) for i in pulleys}

    def weight(i: int) -> Expr:
        """``l_f + h`` of a pulley cable, 1 for a fixed exit: the factor of its ``a − b`` terms."""
        return plane[i][1] + geo[i].h if i in swivels else const(1.0)

    def axial(i: int) -> Expr:
        """``r d`` of a pulley cable: the factor of its ``k`` terms."""
        return const(swivels[i].radius) * plane[i][0]

    def force(i: int) -> list[Expr]:
        if i not in swivels:
            return span[i]
        return [span[i][k] * weight(i) + axial(i) * geo[i].k[k] for k in range(3)]

    def anchor_arm(i: int, j: int) -> list[Expr]:
        """(b_i − b_j) × F_i: the fixed-exit arm of :mod:`taut.dgp._inverse` times
        ``l_f + h``, plus ``r d (R u) × k`` (``u = r_i − r_j``)."""
        u = r[i] - r[j]
        arm = [x - y for x, y in zip(cross(rotated(u), ap[i]), rotated(np.cross(u, r[i])))]
        if i not in swivels:
            return arm
        ax = cross(rotated(u), geo[i].k)
        return [arm[k] * weight(i) + axial(i) * ax[k] for k in range(3)]

    def anchor_load(j: int) -> list[Expr]:
        return [x + ml[k] for k, x in enumerate(cross(rotated(gp - r[j]), fl))]

    def exit_arm(i: int, pole: np.ndarray) -> list[Expr]:
        """(b_i − pole) × F_i."""
        bp = [b[i][k] - float(pole[k]) for k in range(3)]
        arm = cross(bp, [float(x) for x in a[i] - pole])
        if i not in swivels:
            return arm
        ax = cross(bp, geo[i].k)
        return [arm[k] * weight(i) + axial(i) * ax[k] for k in range(3)]

    def exit_load(pole: np.ndarray) -> list[Expr]:
        return [x + ml[k] for k, x in enumerate(cross([g[k] - float(pole[k]) for k in range(3)], fl))]

    def anchor_axis(i: int, j: int) -> Expr:
        """The moment about the axis b_i b_j, free of t_i and t_j."""
        vr = rotated(r[j] - r[i])
        terms = [t[q] * dot(anchor_arm(q, i), vr) for q in taut if q not in (i, j)]
        return sum(terms, dot(rotated(np.cross(r[j] - r[i], gp - r[i])), fl) + dot(vr, ml))

    def exit_axis(i: int, j: int) -> Expr:
        """The moment about the axis a_i a_j, free of t_i and t_j."""
        d = [float(x) for x in a[j] - a[i]]
        return sum((t[q] * dot(exit_arm(q, a[i]), d) for q in taut if q not in (i, j)), dot(exit_load(a[i]), d))

    j0 = taut[0]
    arms = {i: anchor_arm(i, j0) if i != j0 else [ZERO] * 3 for i in taut}
    load0 = anchor_load(j0)
    forces = [sum((t[i] * force(i)[k] for i in taut), const(fl[k])) for k in range(3)]
    moments = [sum((t[i] * arms[i][k] for i in taut), load0[k]) for k in range(3)]
    circles = [c**2 + s**2 - 1.0 for k, (c, s) in enumerate(cs) if k in free_ang]
    pulley_eqs = []
    for i in pulleys:
        d, lf = plane[i]
        pulley_eqs += [d**2 + geo[i].h ** 2 - geo[i].rho2, lf**2 - geo[i].rho2 + const(2.0 * swivels[i].radius) * d]
    pairs = [(i, j) for n1, i in enumerate(taut) for j in taut[n1 + 1 :]]
    axes = [anchor_axis(i, j) for i, j in pairs if np.any(r[j] != r[i])]
    # a pulley cable's force passes through its tangent point, not its exit point: only the
    # axes through two fixed exits are free of their cables' tensions
    axes += [exit_axis(i, j) for i, j in pairs if np.any(a[j] != a[i]) and i not in swivels and j not in swivels]
    extra = [(e, (0.0, 0.0)) for e in axes]
    tmin, tmax = robot.tension_bounds
    for i in taut:
        if tmin[i] > 0.0 or np.isfinite(tmax[i]):
            if i in swivels:
                d, lf = plane[i]
                q2 = (geo[i].rho2 - const(swivels[i].radius) * d + geo[i].h * lf) ** 2
            else:
                q2 = dot(span[i], span[i])
            extra.append((t[i] ** 2 * q2, (max(float(tmin[i]), 0.0) ** 2, float(tmax[i]) ** 2)))
    system = compile_system(nv, forces + moments + circles + pulley_eqs, extra)
    J = [[force(i)[k] for i in taut] for k in range(3)] + [[arms[i][k] for i in taut] for k in range(3)]
    rhs = [const(-fl[k]) for k in range(3)] + [-x for x in load0]
    statics = LinearFilter(compile_tape([e for row in J for e in row] + rhs, [(-np.inf, np.inf)] * (6 * m + 6)), m)

    lo, hi = np.empty(nv), np.empty(nv)
    np_ = len(free_pos)
    na = np_ + 2 * len(free_ang)
    lo[:np_], hi[:np_] = pos_lo[free_pos], pos_hi[free_pos]
    lo[np_:na], hi[np_:na] = -cos_sin_bound, cos_sin_bound
    half = half_turn_restricted(robot.orientation, free_ang)
    if half is not None:
        lo[np_ + 2 * free_ang.index(half[0]) + half[1]] = 0.0
    corner = np.maximum(np.abs(pos_lo), np.abs(pos_hi))
    for j, i in enumerate(pulleys):
        # ρ ≤ ‖p − D‖ + ‖r_i‖ over the position box bounds d and l_f
        far = float(np.linalg.norm(corner + np.abs(a[i]))) + float(np.linalg.norm(r[i]))
        lo[na + 2 * j : na + 2 * j + 2], hi[na + 2 * j : na + 2 * j + 2] = 0.0, far * (1.0 + 1e-12)
    lo[nv - m :], hi[nv - m :] = 0.0, np.inf
    primary = np.arange(nv) < na
    names = tuple(f"{x}_{i + 1}" for i in pulleys for x in ("d", "l_f"))
    return system, statics, lo, hi, primary, free_pos, free_ang, names


def pulley_igp_tensions(robot: Robot, taut: tuple[int, ...], b: np.ndarray, t: np.ndarray) -> np.ndarray:
    """The tensions ``τ = t Q`` (pulley) or ``t ρ`` (fixed exit) of the taut cables at the
    anchors ``b``, from the scaled tensions ``t`` of :func:`pulley_igp_problem`."""
    out = np.empty(len(taut))
    for j, i in enumerate(taut):
        pulley = robot.cables[i].swivel
        if pulley is None:
            out[j] = t[j] * float(np.linalg.norm(robot.exits[i] - b[i]))
        else:
            d, lf, h, _ = _plane(robot, i, b[i])
            out[j] = t[j] * (float(np.sum((b[i] - robot.exits[i]) ** 2)) - pulley.radius * d + h * lf)
    return out
