"""The geometrico-static equations of one taut-cable subset (Berti (2015)
§2.3.1–2.3.6, initial domain §3.1.1, filters §3.1.3).

Parameterisation (§2.3.5–2.3.6, "reference points"): the unknowns are the fixed-frame
positions ``q_1, q_2, q_3`` of three non-collinear platform points, the normal
``n = (q_2 − q_1) × (q_3 − q_1)`` of their plane (when a cable anchor lies off it), and
the scaled tensions ``t_i = τ_i/ρ_i`` of the ``m`` taut cables — ``12 + m`` unknowns
(``9 + m`` without the normal).  The reference points are
the three platform points with the smallest secondary-point weights, taut anchors preferred
(their length constraints are plain spheres, Eq. 2.26): :func:`reference_choice`
(§3.1.1, "Cable numbering").
Every other platform point is a *secondary point* (Eqs. 2.21–2.23)

    s = q_1 + β_2 (q_2 − q_1) + β_3 (q_3 − q_1) + β_4 n,

with constants ``β`` from the body-frame geometry (Eq. 2.22), entered in the affine form
``(1 − β_2 − β_3) q_1 + β_2 q_2 + β_3 q_3 + β_4 n`` of Eqs. 2.23–2.24, where each
unknown occurs once (the last term is dropped when ``β_4 = 0`` exactly, i.e. for points
on the reference plane).  The thesis writes the cross product into every secondary point,
which makes their lengths quartic; with ``n`` an unknown every equation is quadratic, so
the slope enclosures of :mod:`taut.interval._slope` need one node instead of two, and HC4
contracts ``n`` itself (CoGiRo, Table 4.4: 4.72 M boxes → 3.52 M).  Equations (all
quadratic, no trigonometry):

* 3 rigidity relations ``‖q_i − q_j‖² = d_ij²`` (Eq. 2.19/2.28);
* ``m`` cable lengths ``‖b_i − a_i‖² = ρ_i²`` (Eqs. 2.20, 2.26, 2.27);
* 3 normal relations ``n = (q_2 − q_1) × (q_3 − q_1)``;
* 6 equilibrium equations (Eq. 2.3): forces ``Σ t_i (a_i − b_i) + f = 0`` and moments about
  the exit point ``a_p`` of the first taut cable,
  ``Σ t_i (b_i − a_p) × (a_i − a_p) + (g − a_p) × f + m_ext = 0`` (using
  ``(b − a_p) × (a_i − b) = (b − a_p) × (a_i − a_p)``, which keeps one occurrence of ``b``).

Redundant constraints for the filter (§3.1.3): ``‖n‖² = ‖q_2 − q_1‖²‖q_3 − q_1‖² −
((q_2 − q_1)·(q_3 − q_1))²``, a constant, and ``n ⊥ q_2 − q_1, q_3 − q_1``; the moment
equations about every other taut exit point (up to :data:`OTHER_POLES_UP_TO` taut
cables), the slack-cable inequalities
``‖b_k − a_k‖² ≤ ρ_k²`` (Eq. 3.7), and the sphere bounds
``(ρ_j − d_qj)² ≤ ‖q − a_j‖² ≤ (ρ_j + d_qj)²`` of Eq. 3.6 on each reference point ``q``
(the lower one for taut cables ``j``; on secondary points they cost more than they
prune).  The initial box (§3.1.1, Eqs. 3.1–3.2) bounds each reference point by the
spheres around the taut exit points, ``‖q − a_j‖ ≤ ρ_j + d_jq``, and each component of
``n`` by ``‖n‖``; tensions start in
``[0, ∞)`` (§3.1.1: no upper bound is needed, HC4 and the bisection rule of §3.1.4 bound
them).

Six taut cables (§3.1.3, last paragraph): the tensions are not unknowns — the 12 (or 9)
equations of rigidity, lengths and normal fix the pose, the statics is square, and its
interval solution only discards boxes where a tension must be negative; a solution's
tensions are then solved for.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, §2.3.1–2.3.6 (Eqs. 2.21–2.26), §3.1.1, §3.1.3.
   (docs/references.bib: berti2015)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from fractions import Fraction
from itertools import combinations

import numpy as np
import numpy.typing as npt
from numba import njit

from taut._checks import as_array, as_index
from taut.dgp._undecided import REFERENCE_UNKNOWNS, scaled
from taut.errors import CableSetError, SingularConfigurationError, UnsupportedRobotError
from taut.geometry import angles_from_matrix
from taut.interval import Expr, LinearFilter, System, compile_system, compile_tape, const, evaluate_point, variables
from taut.kinematics import refuse_routed, refuse_swivels
from taut.model import Robot

#: Three body points whose triangle has a smaller area ratio than this are collinear.
COLLINEAR = 1e-9

#: The moments about the other taut exit points are redundant constraints up to this many
#: taut cables.  With five, their 12 constraints of 5 terms each prune 1–3 % of the boxes and
#: cost 25 % of the time (five CoGiRo and MARIONET-VR sub-problems: 14.0 → 10.6 s); with
#: three or four they halve the boxes (seven sub-problems of Tables 4.3–4.6: 4.7 → 3.2 s).
OTHER_POLES_UP_TO = 4


def refuse_unmodelled(robot: Robot, analysis: str) -> None:
    """Refuse what the geometrico-static equations do not model: cables that wrap around
    obstacles or around a planar winch's exit pulley (their lengths and directions depend on
    the wrapping, :mod:`taut.wrapping`), swivelling pulleys off a spatial rigid platform,
    jointed platforms (their joint forces are not balanced) and cables routed through via
    points.

    Raises
    ------
    UnsupportedRobotError
        One of these, named with the reason.
    """
    if robot.obstacles:
        raise UnsupportedRobotError(
            f"{robot.name}: {analysis} models straight cables, and this robot's cables wrap around "
            f"{len(robot.obstacles)} obstacle(s) (taut trajectory and taut atlas model the wrapping)"
        )
    wound = [i + 1 for i, c in enumerate(robot.cables) if c.pulley is not None]
    if wound:
        raise UnsupportedRobotError(
            f"{robot.name}: {analysis} models straight cables from fixed exits, and cable(s) "
            f"{', '.join(map(str, wound))} wrap around a winch's exit pulley (taut trajectory models the wrapping)"
        )
    if robot.swivel_cables and (robot.dimension != 3 or robot.is_point_mass):
        raise UnsupportedRobotError(
            f"{robot.name}: {analysis} models swivelling pulleys on spatial rigid platforms only"
        )
    if robot.n_joints:
        raise UnsupportedRobotError(
            f"{robot.name}: {analysis} handles platforms without joints (a jointed platform's joint forces are not balanced)"
        )
    refuse_routed(robot, analysis)


def load(robot: Robot) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The constant load on the platform of the geometrico-static model (Eq. 2.3): the
    platform's ``wrench`` plus its weight.

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    f : ndarray, shape (3,)
        Force [N], fixed frame (shape (2,) for a planar platform).
    m_ext : ndarray, shape (3,)
        Moment [N m], fixed frame (shape (1,), ``m_z``, for a planar platform).
    g : ndarray, shape (3,)
        Body-frame point [m] where the force acts (``wrench_point``; shape (2,) planar).

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §2.1, Eq. 2.3. (docs/references.bib: berti2015)

    Examples
    --------
    >>> from taut.dgp import load
    >>> from taut.model import example
    >>> f, m, g = load(example("suspended-3cable"))
    >>> f.tolist(), m.tolist(), g.tolist()
    ([0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [0.0, 0.0, -0.577])
    """
    plat = robot.platform
    d = robot.dimension
    w = np.zeros(robot.wrench_dim)
    if plat.wrench is not None:
        w += np.asarray(plat.wrench, float)
    w[:d] += robot.weight
    gp = np.zeros(d) if plat.wrench_point is None else np.asarray(plat.wrench_point, float)
    return w[:d], w[d:], gp


def _cross(u: Sequence[Expr], v: Sequence[Expr]) -> list[Expr]:
    return [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]


class StaticsFilter(LinearFilter):
    """The tension filter of §3.1.3 (Eqs. 3.9–3.12): over a box, the equilibrium
    ``J(X) t = −w(X)`` is an interval linear system in the tensions alone; its
    preconditioned interval-Gauss enclosure (generalised inverse of Eq. 3.12) bounds
    ``t`` however wide the tension domain is, and proves boxes without equilibrium empty.
    ``tape``: 6·m entries of J (row-major), then the 6 entries of the right-hand side."""


@dataclass(frozen=True)
class Subproblem:
    """The system of one taut subset, its search box and what maps a solution back."""

    taut: tuple[int, ...]  #: 0-based taut cables
    system: System
    lo: np.ndarray
    hi: np.ndarray
    primary: np.ndarray  #: the reference points (bisected first, §3.1.4; the normal is not)
    body_refs: np.ndarray  #: (3, 3) body-frame reference points
    statics: StaticsFilter
    pose_unknowns: int = 9  #: the reference points, then the normal when it is an unknown

    def pose(self, x: np.ndarray, convention: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(position p, angles, R)`` of the platform frame from the unknowns ``x``."""
        p, R = self.frame(x)
        return p, angles_from_matrix(R, convention), R

    def unknowns(self, p: npt.ArrayLike, R: npt.ArrayLike, t: npt.ArrayLike = ()) -> np.ndarray:
        """The unknowns ``x`` of the platform frame ``(p, R)`` and the scaled tensions
        ``t = τ/ρ`` of the taut cables (none for six taut cables): :meth:`frame` inverted."""
        q = np.asarray(p, float) + self.body_refs @ np.asarray(R, float).T
        normal = [np.cross(q[1] - q[0], q[2] - q[0])] if self.pose_unknowns == 12 else []
        return np.concatenate([q.ravel(), *normal, np.asarray(t, float)])

    def frame(self, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``(position p, rotation R)`` of the platform frame from the unknowns ``x``."""
        return frame_from_points(np.ascontiguousarray(x[:9]).reshape(3, 3), self.body_refs)

    @property
    def tension_unknowns(self) -> bool:
        """False for six taut cables: the unknowns are the pose's alone and the tensions
        follow from the (square) statics (§3.1.3)."""
        return self.system.n > self.pose_unknowns

    @property
    def geometry(self) -> int:
        """How many leading equations involve the pose alone — the 3 rigidity relations, the
        ``m`` lengths and the 3 normal relations, a ``(6 − m)``-dimensional manifold of poses
        that branch-and-prune contracts boxes onto (its ``tube``; the normal, not bisected,
        is solved for) for ``3 ≤ m ≤ 5``.  0 otherwise: six taut cables make the geometry
        square, and on the manifolds of dimension ≥ 4 of one or two cables the
        contraction reshapes boxes without emptying them (CoGiRo's cables 3 and 7: 929
        boxes without, 142 155 with it)."""
        return 3 + len(self.taut) + (self.pose_unknowns - 9) if 3 <= len(self.taut) <= 5 else 0

    @property
    def unknown_names(self) -> tuple[str, ...]:
        """Names of the pose unknowns (the reference points, the normal)."""
        return REFERENCE_UNKNOWNS[: self.pose_unknowns]

    def tension_enclosure(
        self, t_lo: np.ndarray, t_hi: np.ndarray, lengths: np.ndarray, lo: np.ndarray, hi: np.ndarray
    ) -> tuple[tuple[float, ...], tuple[float, ...]]:
        """Bounds of the tensions ``τ = t ρ`` of the scaled tensions in ``[t_lo, t_hi]`` over
        the box ``[lo, hi]``, rounded outwards."""
        return scaled(t_lo, t_hi, np.asarray(lengths, float)[list(self.taut)])

    def tensions(self, x: np.ndarray, lengths: np.ndarray, n: int) -> np.ndarray:
        """Tensions of all ``n`` cables (0 for slack ones) at the unknowns ``x``."""
        idx = list(self.taut)
        tau = np.zeros(n)
        if self.tension_unknowns:
            tau[idx] = x[self.pose_unknowns :] * lengths[idx]
        else:
            v = evaluate_point(self.statics.tape, np.asarray(x, float))
            m = len(idx)
            tau[idx] = np.linalg.solve(v[: 6 * m].reshape(6, m), v[6 * m :]) * lengths[idx]
        return tau


@njit(cache=True)
def frame_from_points(q: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Platform frame from the reference points ``q`` (fixed frame) and ``b`` (body frame):
    ``R`` maps the body triad ``(b₂−b₁, b₃−b₁, their cross product)`` onto the fixed one,
    projected on the nearest rotation (it is orthogonal at a solution).  Compiled: the
    tracking update calls it once per step."""
    e1, e2 = q[1] - q[0], q[2] - q[0]
    f1, f2 = b[1] - b[0], b[2] - b[0]
    E = np.empty((3, 3))
    Eb = np.empty((3, 3))
    E[:, 0], E[:, 1], E[:, 2] = e1, e2, np.cross(e1, e2)
    Eb[:, 0], Eb[:, 1], Eb[:, 2] = f1, f2, np.cross(f1, f2)
    u, _, vt = np.linalg.svd(E @ np.linalg.inv(Eb))
    R = u @ vt
    return q[0] - R @ b[0], R


#: Cost of a reference point that is not a taut anchor, in units of mean secondary-point
#: weight: its domain is not cut to a sphere (Eq. 2.26), so it must buy a clearly better
#: conditioning (the weights of §3.1.1's index Φ, Eq. 3.5, are empirical too).
NON_TAUT_REFERENCE = 0.5


def reference_choice(robot: Robot, taut: tuple[int, ...], gp: np.ndarray) -> tuple[list[int | str], np.ndarray]:
    """Reference points (§3.1.1, "Cable numbering"): the three non-collinear platform points
    — anchors or the load point G — whose secondary points have the smallest mean
    ``|weight|`` (the affine weights and ``β₄`` of Eqs. 2.23–2.24: the term ``I_α`` that
    Eq. 3.5 weighs most), plus :data:`NON_TAUT_REFERENCE` per reference point that is not a
    taut anchor.  Two reference points a few millimetres apart (paired anchors, as on
    MARIONET-VR and the teaching prototype) would multiply every secondary point's interval
    by hundreds.

    Parameters
    ----------
    robot : Robot
    taut : tuple of int
        The taut cables (0-based).
    gp : ndarray, shape (3,)
        Body-frame load point ``G`` (:func:`load`).

    Returns
    -------
    labels : list of int or str
        The three reference points: a cable index (its anchor) or ``"G"``.
    points : ndarray, shape (3, 3)
        Their body-frame coordinates [m].

    Raises
    ------
    SingularConfigurationError
        Every three platform points are collinear.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §3.1.1, Eq. 3.5. (docs/references.bib: berti2015)

    Examples
    --------
    >>> from taut.dgp import load, reference_choice
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> reference_choice(robot, (0, 1, 2), load(robot)[2])[0]
    [0, 1, 2]
    """
    r = robot.anchors
    points = [(i, r[i]) for i in taut] + [("G", gp)] + [(k, r[k]) for k in range(robot.n_cables) if k not in taut]
    scale = max(1e-12, max(float(np.linalg.norm(c[1] - points[0][1])) for c in points))
    best, best_cost = None, np.inf
    for triple in combinations(points, 3):
        ref = np.array([c[1] for c in triple])
        area = np.linalg.norm(np.cross(ref[1] - ref[0], ref[2] - ref[0]))
        if area <= COLLINEAR * scale**2:
            continue
        E = np.column_stack([ref[1] - ref[0], ref[2] - ref[0], np.cross(ref[1] - ref[0], ref[2] - ref[0])])
        labels = [c[0] for c in triple]
        beta = np.linalg.solve(E, np.array([pt - ref[0] for lab, pt in points if lab not in labels]).T).T
        weights = np.column_stack([1.0 - beta[:, 0] - beta[:, 1], beta])
        cost = float(np.mean(np.abs(weights))) + NON_TAUT_REFERENCE * sum(lab not in taut for lab in labels)
        if cost < best_cost - 1e-12:
            best, best_cost = triple, cost
    if best is None:
        raise SingularConfigurationError(
            "the platform anchors are collinear or coincide: the platform's pose is not determined "
            "by its cables (three non-collinear anchors are needed)"
        )
    return [c[0] for c in best], np.array([c[1] for c in best])


def rational_constant(x: Fraction) -> Expr:
    """The constant ``x`` (exact rational) as the tightest float interval holding it; the
    rational rides along for :mod:`taut.interval._precise`."""
    f = float(x)  # correctly rounded
    if Fraction(f) == x:
        return const(f)
    return const(float(np.nextafter(f, -np.inf)), float(np.nextafter(f, np.inf)), exact=x)


def _exact(v: npt.ArrayLike) -> list[Fraction]:
    return [Fraction(float(c)) for c in np.ravel(v)]


def exact_cross(u: Sequence[Fraction], w: Sequence[Fraction]) -> list[Fraction]:
    return [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]


def _exact_load(robot: Robot) -> tuple[list[Fraction], list[Fraction]]:
    """``(f, m_ext)`` of :func:`load` in exact rational arithmetic (of the float weight, as
    :func:`load` has it)."""
    plat = robot.platform
    w = _exact(plat.wrench) if plat.wrench is not None else [Fraction(0)] * 6
    w = [w[k] + Fraction(float(robot.weight[k])) if k < 3 else w[k] for k in range(6)]
    return w[:3], w[3:]


def secondary_coordinates(refs: np.ndarray, body: np.ndarray) -> list[Fraction]:
    """Exact ``β`` of Eq. 2.22: ``body − r₁ = β₂(r₂ − r₁) + β₃(r₃ − r₁) + β₄(r₂ − r₁)×(r₃ − r₁)``,
    by Cramer's rule on rationals (a zero ``β`` — coplanar points — is exactly zero)."""
    r0, r1, r2, pt = (_exact(x) for x in (refs[0], refs[1], refs[2], body))
    cols = [[r1[k] - r0[k] for k in range(3)], [r2[k] - r0[k] for k in range(3)]]
    cols.append(exact_cross(cols[0], cols[1]))
    rhs = [pt[k] - r0[k] for k in range(3)]

    def det(c: list[list[Fraction]]) -> Fraction:
        return sum((c[0][k] * exact_cross(c[1], c[2])[k] for k in range(3)), Fraction(0))

    d = det(cols)
    return [det(cols[:j] + [rhs] + cols[j + 1 :]) / d for j in range(3)]


def build_subproblem(robot: Robot, lengths: npt.ArrayLike, taut: tuple[int, ...], *, normal: bool = True) -> Subproblem:
    """The square system of one taut subset (§2.3, module docstring), its initial box and
    the map back to poses.

    Every constant derived from the robot's data (the ``β`` of secondary points, squared
    distances between reference points, exit-point differences, the load) is computed in
    exact rational arithmetic and entered as the float interval enclosing it, so the
    system holds the exact one of the data (docs/architecture.md §5: outward rounding
    throughout).

    Parameters
    ----------
    robot : Robot
        Without swivelling pulleys (:func:`taut.dgp.pulley_subproblem` formulates those).
    lengths : array_like, shape (n,)
        Cable lengths [m].
    taut : tuple of int
        The taut cables (0-based), ``1 ≤ m ≤ 6``.
    normal : bool, optional
        Make the plane normal of the reference points an unknown when some cable anchor lies
        off their plane (tracking leaves it out: Newton steps on a smaller system).

    Returns
    -------
    Subproblem
        The system (``system``), the initial box (``lo``, ``hi``), the statics filter and
        the maps between unknowns and poses (``pose``, ``unknowns``, ``tensions``).

    Raises
    ------
    CableSetError
        Taut cables that are not 1 to 6 distinct cables of the robot.
    TautError
        Lengths that are not ``n`` finite numbers.
    UnsupportedRobotError
        A cable through a swivelling pulley.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, §2.3.1–2.3.6, §3.1.1, §3.1.3. (docs/references.bib: berti2015)

    Examples
    --------
    Three taut cables whose anchors are coplanar: 9 reference-point coordinates (no normal)
    and 3 scaled tensions.

    >>> from taut.dgp import build_subproblem
    >>> from taut.model import example
    >>> robot = example("suspended-3cable")
    >>> sp = build_subproblem(robot, robot.reference.lengths, (0, 1, 2))
    >>> sp.system.n, sp.pose_unknowns
    (12, 9)
    """
    refuse_swivels(robot, "build_subproblem (taut.dgp.pulley_subproblem formulates pulleys)")
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
    _, _, gp = load(robot)
    f, mext = _exact_load(robot)
    labels, refs = reference_choice(robot, taut, gp)
    betas = {lab: secondary_coordinates(refs, body) for lab, body in [*enumerate(r), ("G", gp)] if lab not in labels}
    # off the plane, an anchor's length would be quartic (the load point enters linearly)
    normal = normal and any(betas[k][2] != 0 for k in range(n) if k in betas)
    pose = 12 if normal else 9
    # six taut cables: the statics is square and only checks the sign of its solution
    unknowns = pose if m == 6 else pose + m
    v = variables(unknowns)
    q = [v[0:3], v[3:6], v[6:9]]
    t = dict(zip(taut, v[pose:]))
    e1 = [q[1][k] - q[0][k] for k in range(3)]
    e2 = [q[2][k] - q[0][k] for k in range(3)]
    n12 = v[9:12] if normal else _cross(e1, e2)

    def point(label: int | str) -> list[Expr]:
        """A secondary point (Eqs. 2.23–2.24) as ``c₁ q₁ + c₂ q₂ + c₃ q₃`` with affine weights
        ``c₁ = 1 − β₂ − β₃``, ``c₂ = β₂``, ``c₃ = β₃`` — each unknown occurs once, so its
        interval evaluation is exact — plus ``β₄ n`` off the reference plane (``n`` the normal
        unknown, or the cross product ``(q₂ − q₁)×(q₃ − q₁)``)."""
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

    def dist2(p: Sequence[Expr], c: np.ndarray) -> Expr:
        return sum(((p[k] - float(c[k])) ** 2 for k in range(3)), const(0.0))

    eqs: list[Expr] = []
    for i, j in ((0, 1), (0, 2), (1, 2)):
        d2 = sum(((x - y) ** 2 for x, y in zip(_exact(refs[i]), _exact(refs[j]))), Fraction(0))
        eqs.append(sum(((q[i][k] - q[j][k]) ** 2 for k in range(3)), const(0.0)) - rational_constant(d2))
    for i in taut:
        eqs.append(dist2(b[i], a[i]) - const(float(lengths[i])) ** 2)
    if normal:
        eqs += [nk - ck for nk, ck in zip(n12, _cross(e1, e2))]
    if m < 6:
        for k in range(3):
            eqs.append(sum((t[i] * (float(a[i][k]) - b[i][k]) for i in taut), const(0.0)) + rational_constant(f[k]))

    def moment_arm(i: int, pole: np.ndarray, k: int) -> Expr:
        """``((b_i − pole) × (a_i − pole))_k``."""
        k1, k2 = (k + 1) % 3, (k + 2) % 3
        c = [x - y for x, y in zip(_exact(a[i]), _exact(pole))]
        return (b[i][k1] - float(pole[k1])) * rational_constant(c[k2]) - (
            b[i][k2] - float(pole[k2])
        ) * rational_constant(c[k1])

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

    extra = []
    if normal:
        # redundant: n has the (constant) length of e₁ × e₂ and is orthogonal to e₁, e₂
        d01, d02, d12 = (
            sum(((x - y) ** 2 for x, y in zip(_exact(refs[i]), _exact(refs[j]))), Fraction(0))
            for i, j in ((0, 1), (0, 2), (1, 2))
        )
        dot = (d01 + d02 - d12) / 2
        area2 = d01 * d02 - dot * dot  # ‖e₁ × e₂‖² = ‖e₁‖²‖e₂‖² − (e₁·e₂)²
        extra.append((sum((nk * nk for nk in n12), const(0.0)) - rational_constant(area2), (0.0, 0.0)))
        extra += [(sum((nk * ek for nk, ek in zip(n12, e)), const(0.0)), (0.0, 0.0)) for e in (e1, e2)]
    if m < 6:
        eqs += moments(a[taut[0]])
        if m <= OTHER_POLES_UP_TO:
            extra += [(e, (0.0, 0.0)) for j in taut[1:] for e in moments(a[j])]
    for k in range(n):
        if k not in taut:
            extra.append((dist2(b[k], a[k]) - const(float(lengths[k])) ** 2, (-np.inf, 0.0)))
    widen = 1.0 + 4.0 * np.finfo(float).eps  # covers the rounding of ρ ± d below
    for s, (lab, body) in enumerate(zip(labels, refs)):
        for j in range(n):
            if j == lab:
                continue
            # Eq. 3.6: ‖q − a_j‖ ≤ ρ_j + d_qj for every cable (‖b_j − a_j‖ ≤ ρ_j, taut or
            # slack), and ≥ ρ_j − d_qj when cable j is taut; on the reference points the
            # sphere refinements of §3.1.1 then hold in every box, not only the first
            d = float(np.linalg.norm(body - r[j]))
            upper = float(np.nextafter(((lengths[j] + d) * widen) ** 2, np.inf))
            near = (lengths[j] - d) / widen
            lower = float(np.nextafter(near**2, -np.inf)) if j in taut and near > 0.0 else -np.inf
            extra.append((dist2(q[s], a[j]), (lower, upper)))
    system = compile_system(unknowns, eqs, extra)
    pole = a[taut[0]]
    J = [[float(a[i][k]) - b[i][k] for i in taut] for k in range(3)] + [
        [moment_arm(i, pole, k) for i in taut] for k in range(3)
    ]
    rhs = [-rational_constant(f[k]) for k in range(3)] + [-load_moment(pole, k) for k in range(3)]
    statics_tape = compile_tape([e for row in J for e in row] + rhs, [(-np.inf, np.inf)] * (6 * m + 6))

    lo = np.full(unknowns, -np.inf)
    hi = np.full(unknowns, np.inf)
    for s, body in enumerate(refs):
        for j in taut:
            # radius rounded up by a few ulps, the box edges outwards: the sphere is inside
            rad = (lengths[j] + float(np.linalg.norm(body - r[j]))) * (1.0 + 4.0 * np.finfo(float).eps)
            lo[3 * s : 3 * s + 3] = np.maximum(lo[3 * s : 3 * s + 3], np.nextafter(a[j] - rad, -np.inf))
            hi[3 * s : 3 * s + 3] = np.minimum(hi[3 * s : 3 * s + 3], np.nextafter(a[j] + rad, np.inf))
    if normal:
        rad = float(np.nextafter(np.sqrt(float(area2)) * (1.0 + 4.0 * np.finfo(float).eps), np.inf))
        lo[9:12], hi[9:12] = -rad, rad
    lo[pose:], hi[pose:] = 0.0, np.inf
    primary = np.arange(unknowns) < 9
    return Subproblem(
        tuple(taut), system, lo, hi, primary, refs, StaticsFilter(statics_tape, m, sign_only=m == 6), pose
    )
