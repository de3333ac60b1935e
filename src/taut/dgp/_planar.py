"""The geometrico-static problems of a planar rigid platform (pose ``x, y, θ``): the planar
analogue of the reference-point formulation of :mod:`taut.dgp._formulation` (Berti (2015)
§2.3.5–2.3.6, §3.1.1, §3.1.3), with the same solve loop, certificates and filters.

Direct problem, one taut subset of ``m ≤ 3`` cables.  The unknowns are the fixed-frame
positions ``q_1, q_2`` of two distinct platform points and the scaled tensions
``t_i = τ_i/ρ_i`` — ``4 + m`` unknowns (4 for three taut cables, whose geometry is square:
the tensions then follow from the square statics, as for six cables in space).  Every other
platform point is a secondary point

    s = q_1 + β_2 (q_2 − q_1) + β_3 J (q_2 − q_1),   J the rotation by 90°,

with exact rational ``β`` from the body-frame geometry (``R J = J R`` in the plane, so the
body-frame relation holds in the fixed frame), entered in the affine form
``s_x = (1 − β_2) x_1 + β_3 y_1 + β_2 x_2 − β_3 y_2``,
``s_y = −β_3 x_1 + (1 − β_2) y_1 + β_3 x_2 + β_2 y_2`` where each unknown occurs once.
Equations, all quadratic:

* the rigidity ``‖q_2 − q_1‖² = d²``;
* ``m`` cable lengths ``‖b_i − a_i‖² = ρ_i²``;
* 3 equilibrium equations: forces ``Σ t_i (a_i − b_i) + f = 0`` and the moment about the exit
  point ``a_p`` of the first taut cable, ``Σ t_i (b_i − a_p) × (a_i − a_p) + (g − a_p) × f
  + m_z = 0`` with the scalar cross product ``u × v = u_x v_y − u_y v_x``.

Redundant constraints: the moments about the other taut exit points, the slack-cable
inequalities ``‖b_k − a_k‖² ≤ ρ_k²`` (Eq. 3.7) and the circle bounds of Eq. 3.6 on the
reference points.  The initial box bounds each reference point by the circles
``‖q − a_j‖ ≤ ρ_j + d_jq`` around the taut exit points (Eqs. 3.1–3.2); tensions start in
``[0, ∞)``.  One taut cable is solved in closed form (:func:`single_cable_equilibria`): the
cable is parallel to the load and the load point lies on its line, below its anchor
(stable) or above it; a load point on the anchor leaves the angle free, a continuum.

Inverse problem (:func:`inverse_system`): with ``m`` taut cables (``1 ≤ m ≤ 3``) assign ``m``
of ``x, y, θ``; the unknowns are the free position coordinates, ``(cos θ, sin θ)`` when
``θ`` is free, and the scaled tensions ``t_i = τ_i/l_i``, as in :mod:`taut.dgp._inverse`.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §2.3.3, §2.3.5–2.3.6, §3.1.1, §3.1.3, §4.1.2. (docs/references.bib: berti2015)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from itertools import combinations
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_index
from taut.dgp._formulation import (
    COLLINEAR,
    NON_TAUT_REFERENCE,
    StaticsFilter,
    load,
    rational_constant,
)
from taut.dgp._single_cable import TWO_PI, _arcs
from taut.dgp._undecided import PLANAR_REFERENCE_UNKNOWNS, scaled
from taut.errors import CableSetError, SingularConfigurationError
from taut.geometry import angles_from_matrix, planar_rotation, rotation_matrix
from taut.interval import (
    ZERO,
    Expr,
    LinearFilter,
    System,
    certified_step,
    compile_system,
    compile_tape,
    const,
    evaluate_point,
    variables,
)
from taut.model import Robot

#: Most taut cables of a planar equilibrium: three fix the pose.
MAX_TAUT = 3


def cross(u: Sequence, v: Sequence) -> Any:
    """The scalar cross product ``u × v = u_x v_y − u_y v_x`` of floats, rationals or
    expressions."""
    return u[0] * v[1] - u[1] * v[0]


def rotation(robot: Robot, angles: npt.ArrayLike) -> np.ndarray:
    """The platform's rotation matrix for its orientation ``angles``: ``R(θ)`` (2 × 2) of a
    planar platform, the robot's convention (3 × 3) of a spatial one."""
    if robot.dimension == 2:
        return planar_rotation(float(np.ravel(angles)[0]))
    return rotation_matrix(angles, robot.orientation)


def orientation(R: np.ndarray, convention: str) -> np.ndarray:
    """The angles of the rotation ``R``: ``(θ,)`` of a 2 × 2 one, the convention's three of a
    3 × 3 one."""
    if R.shape == (2, 2):
        return np.array([math.atan2(R[1, 0], R[0, 0])])
    return angles_from_matrix(R, convention)


def _exact(v: npt.ArrayLike) -> list[Fraction]:
    return [Fraction(float(c)) for c in np.ravel(v)]


def _exact_load(robot: Robot) -> tuple[list[Fraction], Fraction]:
    """``(f, m_z)`` of :func:`~taut.dgp._formulation.load` in exact rational arithmetic."""
    w = _exact(robot.platform.wrench) if robot.platform.wrench is not None else [Fraction(0)] * 3
    return [w[k] + Fraction(float(robot.weight[k])) for k in range(2)], w[2]


def reference_choice(robot: Robot, taut: tuple[int, ...], gp: np.ndarray) -> tuple[list[int | str], np.ndarray]:
    """The two reference points — anchors or the load point ``G`` — whose secondary points have
    the smallest mean ``|weight|`` (``1 − β_2, β_2, β_3``), plus
    :data:`~taut.dgp._formulation.NON_TAUT_REFERENCE` per reference point that is not a taut
    anchor (§3.1.1, "Cable numbering", in the plane).

    Raises
    ------
    SingularConfigurationError
        Every platform point coincides: nothing fixes the platform's angle.
    """
    r = robot.anchors
    points = [(i, r[i]) for i in taut] + [("G", gp)] + [(k, r[k]) for k in range(robot.n_cables) if k not in taut]
    scale = max(1e-12, max(float(np.linalg.norm(c[1] - points[0][1])) for c in points))
    best, best_cost = None, np.inf
    for pair in combinations(points, 2):
        e = pair[1][1] - pair[0][1]
        length2 = float(e @ e)
        if length2 <= (COLLINEAR * scale) ** 2:
            continue
        labels = [c[0] for c in pair]
        d = np.array([pt - pair[0][1] for lab, pt in points if lab not in labels]).reshape(-1, 2)
        b2, b3 = d @ e / length2, (e[0] * d[:, 1] - e[1] * d[:, 0]) / length2
        weights = np.abs(np.concatenate([1.0 - b2, b2, b3]))
        cost = (float(np.mean(weights)) if weights.size else 0.0) + NON_TAUT_REFERENCE * sum(
            lab not in taut for lab in labels
        )
        if cost < best_cost - 1e-12:
            best, best_cost = pair, cost
    if best is None:
        raise SingularConfigurationError(
            "the platform anchors and load point coincide: nothing fixes the planar platform's angle "
            "(two distinct platform points are needed)"
        )
    return [c[0] for c in best], np.array([c[1] for c in best])


def secondary_coordinates(refs: np.ndarray, body: np.ndarray) -> tuple[Fraction, Fraction]:
    """Exact ``(β_2, β_3)`` of ``body − r_1 = β_2 (r_2 − r_1) + β_3 J (r_2 − r_1)``."""
    r1, r2, pt = (_exact(x) for x in (refs[0], refs[1], body))
    e = [r2[k] - r1[k] for k in range(2)]
    d = [pt[k] - r1[k] for k in range(2)]
    length2 = e[0] * e[0] + e[1] * e[1]
    return (d[0] * e[0] + d[1] * e[1]) / length2, cross(e, d) / length2


@dataclass(frozen=True)
class PlanarSubproblem:
    """The system of one taut subset of a planar platform, its search box and what maps a
    solution back: the interface of :class:`~taut.dgp._formulation.Subproblem` that the solve
    loop, the undecided boxes and tracking use."""

    taut: tuple[int, ...]  #: 0-based taut cables
    system: System
    lo: np.ndarray
    hi: np.ndarray
    primary: np.ndarray  #: the reference points (bisected first)
    body_refs: np.ndarray  #: (2, 2) body-frame reference points
    statics: StaticsFilter
    pose_unknowns: int = 4  #: the two reference points

    def pose(self, x: np.ndarray, convention: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(position p, (θ,), R)`` of the platform frame from the unknowns ``x``."""
        p, R = self.frame(x)
        return p, orientation(R, convention), R

    def unknowns(self, p: npt.ArrayLike, R: npt.ArrayLike, t: npt.ArrayLike = ()) -> np.ndarray:
        """The unknowns ``x`` of the platform frame ``(p, R)`` and the scaled tensions ``t``
        (none for three taut cables): :meth:`frame` inverted."""
        q = np.asarray(p, float) + self.body_refs @ np.asarray(R, float).T
        return np.concatenate([q.ravel(), np.asarray(t, float)])

    def frame(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(position p, rotation R)``: ``R`` turns the body-frame ``r_2 − r_1`` onto
        ``q_2 − q_1`` (of the same length at a solution)."""
        q = np.asarray(x[:4], float).reshape(2, 2)
        e, f = q[1] - q[0], self.body_refs[1] - self.body_refs[0]
        R = planar_rotation(math.atan2(cross(f, e), float(f @ e)))
        return q[0] - R @ self.body_refs[0], R

    @property
    def unknown_names(self) -> tuple[str, ...]:
        """Names of the pose unknowns (the two reference points)."""
        return PLANAR_REFERENCE_UNKNOWNS

    def tension_enclosure(
        self, t_lo: np.ndarray, t_hi: np.ndarray, lengths: np.ndarray, lo: np.ndarray, hi: np.ndarray
    ) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """Bounds of the tensions ``τ = t ρ`` of the scaled tensions in ``[t_lo, t_hi]``,
        rounded outwards (the box ``[lo, hi]`` does not enter: the lengths are constants)."""
        return scaled(t_lo, t_hi, np.asarray(lengths, float)[list(self.taut)])

    @property
    def tension_unknowns(self) -> bool:
        """False for three taut cables: the tensions follow from the square statics."""
        return self.system.n > self.pose_unknowns

    @property
    def geometry(self) -> int:
        """How many leading equations involve the pose alone and leave a curve of poses
        (two taut cables: the rigidity and two lengths) that branch-and-prune contracts
        boxes onto; 0 otherwise (one cable: closed form; three: the geometry is square)."""
        return 1 + len(self.taut) if len(self.taut) == 2 else 0

    def tensions(self, x: np.ndarray, lengths: np.ndarray, n: int) -> np.ndarray:
        """Tensions of all ``n`` cables (0 for slack ones) at the unknowns ``x``."""
        idx = list(self.taut)
        tau = np.zeros(n)
        if self.tension_unknowns:
            tau[idx] = x[self.pose_unknowns :] * lengths[idx]
        else:
            v = evaluate_point(self.statics.tape, np.asarray(x, float))
            m = len(idx)
            tau[idx] = np.linalg.solve(v[: 3 * m].reshape(3, m), v[4 * m : 4 * m + 3]) * lengths[idx]
        return tau


def build_subproblem(robot: Robot, lengths: npt.ArrayLike, taut: tuple[int, ...]) -> PlanarSubproblem:
    """The square system of one taut subset of a planar platform (module docstring), its
    initial box and the map back to poses; constants derived from the robot's data in exact
    rational arithmetic, entered as the float intervals enclosing them.

    Raises
    ------
    CableSetError
        Taut cables that are not 1 to 3 distinct cables of the robot.
    SingularConfigurationError
        Every platform point coincides.
    """
    n = robot.n_cables
    lengths = as_array(lengths, "cable lengths", shape=(n,))
    try:
        taut = tuple(as_index(i, "taut cables", n, error=CableSetError) for i in taut)
    except TypeError:
        raise CableSetError(f"taut cables: expected cable indices 0..{n - 1}, got {taut!r}") from None
    if not 1 <= len(taut) <= MAX_TAUT or len(set(taut)) != len(taut):
        raise CableSetError(f"taut cables of a planar platform: expected 1 to 3 distinct cables, got {list(taut)}")
    m = len(taut)
    a, r = robot.exits, robot.anchors
    _, _, gp = load(robot)
    f, mz = _exact_load(robot)
    labels, refs = reference_choice(robot, taut, gp)
    betas = {lab: secondary_coordinates(refs, body) for lab, body in [*enumerate(r), ("G", gp)] if lab not in labels}
    # three taut cables: the geometry is square and the statics only checks its sign
    unknowns = 4 if m == 3 else 4 + m
    v = variables(unknowns)
    q = [v[0:2], v[2:4]]
    t = dict(zip(taut, v[4:]))

    def point(label: int | str) -> list[Expr]:
        if label in labels:
            return q[labels.index(label)]
        b2, b3 = betas[label]
        # (x1, y1, x2, y2) weights of each coordinate: each unknown once
        rows = ((1 - b2, b3, b2, -b3), (-b3, 1 - b2, b3, b2))
        out = []
        for w in rows:
            terms = [u if c == 1 else rational_constant(c) * u for c, u in zip(w, v[:4]) if c != 0]
            out.append(sum(terms[1:], terms[0]) if terms else const(0.0))
        return out

    b = {i: point(i) for i in range(n)}
    g = point("G")

    def dist2(p: Sequence[Expr], c: np.ndarray) -> Expr:
        return (p[0] - float(c[0])) ** 2 + (p[1] - float(c[1])) ** 2

    d2 = sum(((x - y) ** 2 for x, y in zip(_exact(refs[0]), _exact(refs[1]))), Fraction(0))
    eqs: list[Expr] = [(q[1][0] - q[0][0]) ** 2 + (q[1][1] - q[0][1]) ** 2 - rational_constant(d2)]
    for i in taut:
        eqs.append(dist2(b[i], a[i]) - const(float(lengths[i])) ** 2)
    if m < 3:
        for k in range(2):
            eqs.append(sum((t[i] * (float(a[i][k]) - b[i][k]) for i in taut), const(0.0)) + rational_constant(f[k]))

    def moment_arm(i: int, pole: np.ndarray) -> Expr:
        """``(b_i − pole) × (a_i − pole)``."""
        c = [x - y for x, y in zip(_exact(a[i]), _exact(pole))]
        return (b[i][0] - float(pole[0])) * rational_constant(c[1]) - (b[i][1] - float(pole[1])) * rational_constant(
            c[0]
        )

    def load_moment(pole: np.ndarray) -> Expr:
        return (
            (g[0] - float(pole[0])) * rational_constant(f[1]) - (g[1] - float(pole[1])) * rational_constant(f[0])
        ) + rational_constant(mz)

    def moment(pole: np.ndarray) -> Expr:
        acc = load_moment(pole)
        for i in taut:
            acc = acc + t[i] * moment_arm(i, pole)
        return acc

    extra: list[tuple[Expr, tuple[float, float]]] = []
    if m < 3:
        eqs.append(moment(a[taut[0]]))
        extra += [(moment(a[j]), (0.0, 0.0)) for j in taut[1:]]
    for k in range(n):
        if k not in taut:
            extra.append((dist2(b[k], a[k]) - const(float(lengths[k])) ** 2, (-np.inf, 0.0)))
    widen = 1.0 + 4.0 * np.finfo(float).eps  # covers the rounding of ρ ± d below
    for s, (lab, body) in enumerate(zip(labels, refs)):
        for j in range(n):
            if j == lab:
                continue
            # Eq. 3.6 in the plane: ‖q − a_j‖ ≤ ρ_j + d_qj for every cable, ≥ ρ_j − d_qj for a taut one
            d = float(np.linalg.norm(body - r[j]))
            upper = float(np.nextafter(((lengths[j] + d) * widen) ** 2, np.inf))
            near = (lengths[j] - d) / widen
            lower = float(np.nextafter(near**2, -np.inf)) if j in taut and near > 0.0 else -np.inf
            extra.append((dist2(q[s], a[j]), (lower, upper)))
    system = compile_system(unknowns, eqs, extra)
    # the tension filter's rows: the forces, then the moments about two poles — the filter's
    # generalised inverse (Eq. 3.12) pairs force rows with as many moment rows
    poles = (a[taut[0]], a[taut[-1]] if m > 1 else np.zeros(2))
    J = [[float(a[i][k]) - b[i][k] for i in taut] for k in range(2)]
    J += [[moment_arm(i, pole) for i in taut] for pole in poles]
    rhs = [-rational_constant(f[0]), -rational_constant(f[1]), *(-load_moment(pole) for pole in poles)]
    statics_tape = compile_tape([e for row in J for e in row] + rhs, [(-np.inf, np.inf)] * (4 * m + 4))

    lo = np.full(unknowns, -np.inf)
    hi = np.full(unknowns, np.inf)
    for s, body in enumerate(refs):
        for j in taut:
            # radius rounded up by a few ulps, the box edges outwards: the circle is inside
            rad = (lengths[j] + float(np.linalg.norm(body - r[j]))) * (1.0 + 4.0 * np.finfo(float).eps)
            lo[2 * s : 2 * s + 2] = np.maximum(lo[2 * s : 2 * s + 2], np.nextafter(a[j] - rad, -np.inf))
            hi[2 * s : 2 * s + 2] = np.minimum(hi[2 * s : 2 * s + 2], np.nextafter(a[j] + rad, np.inf))
    lo[4:], hi[4:] = 0.0, np.inf
    primary = np.arange(unknowns) < 4
    return PlanarSubproblem(
        tuple(taut), system, lo, hi, primary, refs, StaticsFilter(statics_tape, m, sign_only=m == 3)
    )


def single_cable_equilibria(robot: Robot, lengths: np.ndarray, i: int) -> list[dict]:
    """Equilibria of a planar platform with cable ``i`` alone taut: dicts with ``R``, ``p``,
    ``tensions``, ``stable`` and ``continuum`` (Berti 2015, §2.3.3, in the plane).

    The cable hangs along the load, ``b_i = a_i + ρ_i f̂``, and the load point ``G`` lies on
    that line below ``b_i`` (stable) or above it (unstable): two points, each an equilibrium
    when every slack cable reaches its anchor.  With ``G`` on the anchor every angle balances;
    the arcs of angles where all slack cables fit are each reported at their middle angle,
    with ``continuum`` the arc (neutral: not stable).
    """
    f, mz, gp = load(robot)
    F = float(np.linalg.norm(f))
    if F == 0.0 or np.any(mz != 0.0):
        return []
    fh = f / F
    a, r = robot.exits, robot.anchors
    bi = a[i] + lengths[i] * fh
    v = gp - r[i]
    tau = np.zeros(robot.n_cables)
    tau[i] = F
    others = [k for k in range(robot.n_cables) if k != i]
    out = []
    if float(np.linalg.norm(v)) == 0.0:
        conds = []
        for k in others:
            c, w = bi - a[k], r[k] - r[i]
            # ‖c + R(ϑ) w‖² − ρ_k² = A + B cos ϑ + C sin ϑ
            conds.append((float(c @ c + w @ w - lengths[k] ** 2), float(2.0 * c @ w), float(2.0 * cross(w, c))))
        for lo, hi in _arcs(conds):
            R = planar_rotation(0.5 * (lo + hi))
            out.append({"R": R, "p": bi - R @ r[i], "tensions": tau, "stable": False, "continuum": (lo, hi)})
        return out
    for side in (1.0, -1.0):  # G below B_i (along the load) or above it
        theta = math.atan2(side * fh[1], side * fh[0]) - math.atan2(v[1], v[0])
        theta = math.remainder(theta, TWO_PI)
        R = planar_rotation(theta)
        p = bi - R @ r[i]
        reach = np.linalg.norm(p + r[others] @ R.T - a[others], axis=1)
        if np.all(reach <= lengths[others]):
            out.append({"R": R, "p": p, "tensions": tau, "stable": side > 0, "continuum": None})
    return out


#: Of :func:`inverse_system`: the system, the tension filter, the box, the bisected
#: variables, the free position coordinates (0, 1) and the free angle (``[0]`` or ``[]``).
InverseSystem = tuple[System, LinearFilter, np.ndarray, np.ndarray, np.ndarray, list[int], list[int]]


def inverse_system(
    robot: Robot,
    taut: tuple[int, ...],
    fixed: dict[int, float],
    pos_lo: np.ndarray,
    pos_hi: np.ndarray,
    angle: tuple[Expr, Expr] | None,
    cos_sin_bound: float,
) -> InverseSystem:
    """The inverse geometrico-static problem of a planar platform (module docstring): the
    unknowns, equations and box of :func:`taut.dgp.solve_igp` for ``m`` taut cables and the
    ``m`` assigned pose coordinates ``fixed`` (pose index 0–2 → value).

    The equations are the forces, the moment about the first taut anchor ``b_0`` —
    ``(R u_i) × (a_i − p) − u_i × r_i`` with ``u_i = r_i − r_0`` (a planar rotation keeps the
    cross product, so the arm is linear in ``R``) — and ``c² + s² = 1`` when ``θ`` is free;
    the moments about the other taut anchors and exit points (each free of one tension) and
    the tension bounds are redundant constraints.  ``angle`` is the enclosure of
    ``(cos θ, sin θ)`` of an assigned ``θ``; ``cos_sin_bound`` bounds those unknowns.
    """
    a, r = robot.exits, robot.anchors
    f, mz, gp = load(robot)
    m = len(taut)
    free_pos = [k for k in range(2) if k not in fixed]
    free_ang = [0] if 2 not in fixed else []
    nv = len(free_pos) + 2 * len(free_ang) + m
    v = iter(variables(nv))
    p = [next(v) if k in free_pos else const(fixed[k]) for k in range(2)]
    c, s = (next(v), next(v)) if free_ang else angle  # type: ignore[misc]
    t = {i: next(v) for i in taut}
    fl, ml = [float(x) for x in f], float(mz[0])

    def rotated(vec: np.ndarray) -> list[Expr]:
        return [c * float(vec[0]) - s * float(vec[1]), s * float(vec[0]) + c * float(vec[1])]

    ap = {i: [float(a[i][k]) - p[k] for k in range(2)] for i in taut}  # a_i − p
    Rr = {i: rotated(r[i]) for i in taut}
    span = {i: [ap[i][k] - Rr[i][k] for k in range(2)] for i in taut}  # a_i − b_i
    g = [p[k] + x for k, x in enumerate(rotated(gp))]

    def anchor_arm(i: int, j: int) -> Expr:
        """(b_i − b_j) × (a_i − b_i) = (R u) × (a_i − p) − u × r_i, u = r_i − r_j."""
        u = r[i] - r[j]
        return cross(rotated(u), ap[i]) - float(cross(u, r[i]))

    def anchor_load(j: int) -> Expr:
        return cross(rotated(gp - r[j]), fl) + ml

    def exit_arm(i: int, pole: np.ndarray) -> Expr:
        """(b_i − pole) × (a_i − pole) = (a_i − pole) × (a_i − b_i)."""
        return cross([float(x) for x in a[i] - pole], span[i])

    def exit_load(pole: np.ndarray) -> Expr:
        return cross([g[k] - float(pole[k]) for k in range(2)], fl) + ml

    j0 = taut[0]
    forces = [sum((t[i] * span[i][k] for i in taut), const(fl[k])) for k in range(2)]
    arms = {i: anchor_arm(i, j0) if i != j0 else ZERO for i in taut}
    moment = sum((t[i] * arms[i] for i in taut), anchor_load(j0))
    circles = [c**2 + s**2 - 1.0] if free_ang else []
    extra = [(sum((t[i] * anchor_arm(i, j) for i in taut if i != j), anchor_load(j)), (0.0, 0.0)) for j in taut[1:]]
    extra += [(sum((t[i] * exit_arm(i, a[j]) for i in taut if i != j), exit_load(a[j])), (0.0, 0.0)) for j in taut]
    tmin, tmax = robot.tension_bounds
    for i in taut:
        if tmin[i] > 0.0 or np.isfinite(tmax[i]):
            size2 = span[i][0] * span[i][0] + span[i][1] * span[i][1]
            extra.append((t[i] ** 2 * size2, (max(float(tmin[i]), 0.0) ** 2, float(tmax[i]) ** 2)))
    system = compile_system(nv, [*forces, moment, *circles], extra)
    # forces, then the moments about b_0 and a_0: as many moment rows as force rows (Eq. 3.12)
    J = [[span[i][k] for i in taut] for k in range(2)]
    J += [[arms[i] for i in taut], [exit_arm(i, a[j0]) if i != j0 else ZERO for i in taut]]
    rhs = [const(-fl[0]), const(-fl[1]), -anchor_load(j0), -exit_load(a[j0])]
    statics = LinearFilter(compile_tape([e for row in J for e in row] + rhs, [(-np.inf, np.inf)] * (4 * m + 4)), m)
    lo, hi = np.empty(nv), np.empty(nv)
    k = len(free_pos)
    lo[:k], hi[:k] = pos_lo[free_pos], pos_hi[free_pos]
    lo[k : nv - m], hi[k : nv - m] = -cos_sin_bound, cos_sin_bound
    lo[nv - m :], hi[nv - m :] = 0.0, np.inf
    return system, statics, lo, hi, np.arange(nv) < nv - m, free_pos, free_ang


#: Of :meth:`Tracker.update`, as :data:`taut.dgp._tracking.Update`: status, p, R, angles,
#: tensions, spans, smallest eigenvalue of the reduced Hessian, box width.
Update = tuple[int, np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray, float, float]


class Tracker:
    """The tracking update of :mod:`taut.dgp._tracking` on one taut subset of a planar
    platform: the sub-problem compiled once, its length constants patched per update, then
    Newton and the Krawczyk test around the step (:func:`~taut.interval.certified_step`)."""

    def __init__(self, robot: Robot, taut: tuple[int, ...], margin: float, floor: float) -> None:
        # placeholder lengths, patched per update: distinct, so that the tape's hash-consing
        # cannot merge two cables' ρ (or a ρ with another constant) into one node
        marks = 1.0 + np.sqrt(2.0) / 7.0 + np.arange(robot.n_cables)
        self.robot, self.taut, self.margin, self.floor = robot, taut, margin, floor
        self.sub = build_subproblem(robot, marks, taut)
        tape = self.sub.system.tape
        nodes = []
        for j, i in enumerate(taut):  # length equations follow the rigidity relation
            sq = tape.b[tape.end[1 + j] - 1]  # dist² − ρ²: SUB(dist², SQR(CONST ρ))
            k = tape.a[sq]
            if not (tape.clo[k] == marks[i] and tape.parents(k) == 1):
                raise AssertionError("a length constant is shared: it cannot be patched per update")
            nodes.append(k)
        self.nodes = np.array(nodes, np.int64)
        self.gp = load(robot)[2]

    def update(self, lengths: np.ndarray, p0: np.ndarray, R0: np.ndarray, tau0: np.ndarray) -> Update:
        """From the equilibrium ``(p0, R0, tau0)`` to ``lengths``."""
        sub, idx = self.sub, list(self.taut)
        system = sub.system
        system.tape.clo[self.nodes] = lengths[idx]
        system.tape.chi[self.nodes] = lengths[idx]
        x0 = sub.unknowns(p0, R0, tau0[idx] / lengths[idx] if sub.tension_unknowns else ())
        status, x, lo, hi = certified_step(
            *system.tape.arrays[:7],
            system.n_equations,
            *system.jacobian.arrays[:7],
            system.rows,
            system.cols,
            x0,
            self.margin,
            self.floor,
            1e-13,
            30,
            10,
        )
        width = float(np.max(hi - lo))
        n = self.robot.n_cables
        if status != 1:
            return status, p0, R0, np.zeros(1), np.zeros(n), np.zeros(n), 0.0, width
        p, ang, R = sub.pose(x, "")
        tau = sub.tensions(x, lengths, n)
        a, r = self.robot.exits, self.robot.anchors
        b = p + r @ R.T
        spans = np.linalg.norm(b - a, axis=1)
        Hr = planar_reduced_hessian(a[idx], b[idx], p + R @ self.gp, tau[idx], lengths[idx])
        eig = float(np.linalg.eigvalsh(0.5 * (Hr + Hr.T))[0]) if Hr.size else np.inf
        return status, p, R, ang, tau, spans, eig, width


def planar_reduced_hessian(a: np.ndarray, b: np.ndarray, g: np.ndarray, tau: np.ndarray, rho: np.ndarray) -> np.ndarray:
    """The reduced Hessian of a planar equilibrium (:func:`taut.dgp.reduced_hessian` on the
    planar twists ``(v_x, v_y, ω)``, velocities at ``G``): with ``u_i = b_i − g``,
    ``H = Σ τ_i/ρ_i [[I, J u_i], [(J u_i)ᵀ, −u_i·(g − a_i)]]``, restricted to the null space
    of ``Jᵀ`` (rows ``[(b_i − a_i)ᵀ, u_i × (b_i − a_i)]/ρ_i``)."""
    H = np.zeros((3, 3))
    Jt = np.zeros((tau.size, 3))
    for i in range(tau.size):
        w = tau[i] / rho[i]
        u, d = b[i] - g, b[i] - a[i]
        H[:2, :2] += w * np.eye(2)
        H[:2, 2] += w * np.array([-u[1], u[0]])
        H[2, :2] += w * np.array([-u[1], u[0]])
        H[2, 2] -= w * float(u @ (g - a[i]))
        Jt[i, :2], Jt[i, 2] = d / rho[i], cross(u, d) / rho[i]
    if tau.size == 0:
        return H
    _, s, vt = np.linalg.svd(Jt)
    top = max(1.0, s[0]) if s.size else 1.0
    N = vt[int(np.sum(s > 1e-10 * top)) :].T
    return N.T @ H @ N
