"""Certified workspaces (Gouttefarde, Daney & Merlet 2011): a region of platform positions
covered by boxes proven inside the workspace of a condition, boxes proven outside it, and
undecided boxes no wider than ``eps`` along the boundary.

A grid says nothing between its points; a box here is decided for **every** position in
it.  Over a box of positions (at a fixed orientation, or for every orientation of an
orientation box), the structure matrices and their derivatives are enclosed in
outward-rounded interval arithmetic (:class:`taut.interval.Interval`: ``v_i = a_i − R b_i −
p``, ``u_i = v_i / ‖v_i‖`` and the moments ``R b_i × u_i``), the external wrench likewise,
and three tests run in turn:

* **tensions proven** (inside): tensions within the bounds exist for every pose and every
  required wrench, by a Brouwer fixed point around the tensions of the box's centre with
  their first-order change taken out;
* **one separating hyperplane** (outside): the facet of the available wrench set that the
  required set crosses farthest at the centre stays crossed over the whole box
  (:func:`taut.interval.separating_directions` gives it);
* **the facet test** of Gouttefarde, Daney & Merlet (2011) over interval minors
  (:func:`taut.interval.zonotope_verdicts`) on what is left, for planar robots and point
  masses (:data:`FACET_ROWS`), and alone for wrench closure.

A box none of them decides is cut across each side at least half as wide as its widest
(and wider than ``eps``), breadth first, until it is no wider than ``eps``; what is left is
the undecided boundary layer.  This is set inversion (SIVIA, Jaulin et al. 2001), not the
zero-finding branch-and-prune of :func:`taut.interval.branch_and_prune`: a box is kept for
its verdict, not contracted towards solutions.

* The volumes bound the workspace's: ``inner ≤ true ≤ inner + undecided`` (within the
  region).
* With an orientation box the inner boxes belong to the *total orientation* workspace (the
  condition holds at every orientation of the box); an outer box fails at the box's centre
  orientation, so none of its positions belongs to that workspace either.
* The boxes of one level are split into chunks of :data:`CHUNK_BOXES` and mapped over an
  executor of :mod:`taut.parallel`; each box is decided alone, so the boxes are the same
  whatever the executor.

Conditions: ``wrench-feasible`` (box, polytope or single-wrench sets), ``static``,
``wrench-closure`` and ``interference-free`` (the capsule pairs of the collision model,
:mod:`taut.workspace._clearance`: in 3-D, cables of radius 0 that always meet — coplanar
crossing pairs — leave their boxes undecided, since no interval proves a distance of exactly
0).  Ellipsoidal wrench sets and conditions of one's own are refused.  Robots: point masses and rigid platforms, planar and
spatial, whose cables leave from fixed exit points; jointed platforms, swivelling pulleys
and obstacles are refused.

References
----------
.. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011, §III–V. (docs/references.bib: gouttefarde2011)
.. [2] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §2.1.4. (docs/references.bib: rushton2022)
.. [3] L. Jaulin, M. Kieffer, O. Didrit, É. Walter, "Applied Interval Analysis", Springer, 2001,
   §3.4.1 (SIVIA). (docs/references.bib: jaulin2001)
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from taut._results import Result, jsonable
from taut.errors import ArgumentError, GridSizeError, UnsupportedRobotError
from taut.interval import MAX_BOXES, OUTSIDE_RTOL, Interval, separating_directions, zonotope_verdicts
from taut.model import Robot
from taut.parallel import Executor, as_executor
from taut.statics import BoxWrenchSet, PolytopeWrenchSet, SingleWrench
from taut.workspace._clearance import Clearance, clearance_spec, clearance_verdicts
from taut.workspace._conditions import (
    InterferenceFree,
    StaticEquilibrium,
    WorkspaceCondition,
    WrenchClosure,
    WrenchFeasible,
    make_condition,
)
from taut.workspace._grid import default_bounds

__all__ = ["CHUNK_BOXES", "DEFAULT_EPS", "CertifiedWorkspace", "certified"]

#: Default smallest box width [m] (1 cm).
DEFAULT_EPS = 0.01
#: Default widest piece of an orientation box [rad].
ORIENTATION_STEP = 0.05
#: Most pieces of an orientation box.
MAX_PIECES = 4096
#: Boxes per task handed to the executor.
CHUNK_BOXES = 4096
#: The facet test (interval minors of ``m − 1`` columns) runs on what the tension and
#: separation tests leave only up to this many wrench components: beyond, its minors are too
#: wide to decide and too many to afford (spatial platforms, ``m = 6``: 5 × 5 minors of 56
#: column sets decided 77 of 83,183 boxes at 90 % of the time).  Wrench closure uses it always.
FACET_ROWS = 3
#: Margins (fractions of each tension range) and closed forms tried in turn for the tensions at
#: a box's centre: Pott's (one pseudo-inverse) well inside, then the improved one.
CENTRE_MARGINS = ((0.25, "closed-form"),) + tuple((f, "improved-closed-form") for f in (0.05, 0.01, 0.002))


@dataclass(frozen=True)
class CertifiedWorkspace(Result):
    """Boxes of positions proven inside, proven outside, and undecided (:func:`certified`).

    Boxes are arrays ``(K, d, 2)``: ``[lo, hi]`` of each position coordinate.

    Attributes
    ----------
    robot_name : str
    condition : str
        The condition's registry name.
    axis_names : tuple of str
        The position coordinates' names.
    region : ndarray, shape (d, 2)
    orientation : ndarray, shape (k,)
        The fixed orientation (the centre of ``orientation_box`` when one is given; empty
        for a point mass).
    orientation_box : ndarray, shape (k, 2), or None
        Inner boxes hold for every orientation of it.
    eps : float
        Undecided boxes are no wider than this [m] (unless the budget ran out).
    inner, outer, undecided : ndarray, shape (K, d, 2)
    complete : bool
        False when the box budget ran out: the boxes not yet decided are in ``undecided``,
        some of them wider than ``eps``.
    evaluated : int
        Boxes evaluated.
    elapsed_s : float

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.workspace import certified
    >>> res = certified(example("planar-4cable"), "static", eps=0.05)
    >>> res.complete, res.inner_volume <= res.inner_volume + res.undecided_volume
    (True, True)
    >>> sorted(res.as_dict()["boxes"])
    ['inner', 'outer', 'undecided']
    """

    robot_name: str
    condition: str
    axis_names: tuple[str, ...]
    region: np.ndarray
    orientation: np.ndarray
    orientation_box: np.ndarray | None
    eps: float
    inner: np.ndarray
    outer: np.ndarray
    undecided: np.ndarray
    complete: bool
    evaluated: int
    elapsed_s: float

    @staticmethod
    def _volume(boxes: np.ndarray) -> float:
        return float(np.prod(boxes[:, :, 1] - boxes[:, :, 0], axis=1).sum()) if len(boxes) else 0.0

    @property
    def inner_volume(self) -> float:
        """Volume (area in 2-D) of the inner boxes: a lower bound of the workspace's within the region."""
        return self._volume(self.inner)

    @property
    def outer_volume(self) -> float:
        """Volume of the outer boxes."""
        return self._volume(self.outer)

    @property
    def undecided_volume(self) -> float:
        """Volume of the undecided boxes: ``inner + undecided`` bounds the workspace's from above."""
        return self._volume(self.undecided)

    @property
    def region_volume(self) -> float:
        """Volume of the region."""
        return float(np.prod(self.region[:, 1] - self.region[:, 0]))

    def as_dict(self, *, boxes: bool = False) -> dict[str, Any]:
        """The result in JSON types: volumes, box counts and, with ``boxes``, the boxes.

        Parameters
        ----------
        boxes : bool, default False
            Include the arrays of boxes (``inner_boxes``, ``outer_boxes``, ``undecided_boxes``).

        Returns
        -------
        dict
        """
        d = {
            "robot": self.robot_name,
            "condition": self.condition,
            "axis_names": list(self.axis_names),
            "region": self.region,
            "orientation": self.orientation,
            "orientation_box": self.orientation_box,
            "eps": self.eps,
            "inner_volume": self.inner_volume,
            "undecided_volume": self.undecided_volume,
            "outer_volume": self.outer_volume,
            "region_volume": self.region_volume,
            "boxes": {"inner": len(self.inner), "outer": len(self.outer), "undecided": len(self.undecided)},
            "evaluated": self.evaluated,
            "complete": self.complete,
            "elapsed_s": self.elapsed_s,
        }
        if boxes:
            d.update(inner_boxes=self.inner, outer_boxes=self.outer, undecided_boxes=self.undecided)
        return jsonable(d)


@dataclass(frozen=True)
class _Spec:
    """What a worker needs to decide boxes: picklable, no robot methods called twice."""

    exits: np.ndarray  # (n, d)
    anchors: np.ndarray  # (n, d) in the platform frame; zeros for a point mass
    point_mass: bool
    convention: str
    orientation: np.ndarray  # fixed orientation (centre of the box)
    orientation_box: np.ndarray | None
    orientation_step: float
    tension_bounds: tuple[np.ndarray, np.ndarray]
    closure: bool
    around_external: bool
    force: np.ndarray  # the external force (weights and constant wrench), fixed frame
    moment: np.ndarray  # the external wrench's constant moment
    wrench_point: np.ndarray  # where the force acts, platform frame
    centre: np.ndarray
    radius: np.ndarray
    vertices: np.ndarray | None
    clearance: Clearance | None  # the capsule pairs of ``interference-free``


def _rotations(spec: _Spec, angles: Interval, *, derivatives: bool) -> tuple[Interval, list[Interval]]:
    """Enclosures of the rotation matrices ``(B, d, d)`` of boxes of angles ``(B, k)``, and
    with ``derivatives`` of their derivatives in each angle (the product rule over the
    elementary factors)."""
    B = angles.shape[0]
    if spec.exits.shape[1] == 2:
        c, s = angles[:, 0].cos(), angles[:, 0].sin()
        R = Interval(
            np.stack([np.stack([c.lo, -s.hi], -1), np.stack([s.lo, c.lo], -1)], -2),
            np.stack([np.stack([c.hi, -s.lo], -1), np.stack([s.hi, c.hi], -1)], -2),
        )
        dR = Interval(
            np.stack([np.stack([-s.hi, -c.hi], -1), np.stack([c.lo, -s.hi], -1)], -2),
            np.stack([np.stack([-s.lo, -c.lo], -1), np.stack([c.hi, -s.lo], -1)], -2),
        )
        return R, [dR] if derivatives else []

    def axis(k: int, t: Interval, derivative: bool) -> Interval:
        # R_x = [[1, 0, 0], [0, c, −s], [0, s, c]] and its cyclic shifts R_y, R_z;
        # dR_x/dt = [[0, 0, 0], [0, −s, −c], [0, c, −s]]
        c, s = t.cos(), t.sin()
        lo, hi = np.zeros((B, 3, 3)), np.zeros((B, 3, 3))
        i, j = (k + 1) % 3, (k + 2) % 3
        if derivative:
            lo[:, i, i], hi[:, i, i] = -s.hi, -s.lo
            lo[:, j, j], hi[:, j, j] = -s.hi, -s.lo
            lo[:, i, j], hi[:, i, j] = -c.hi, -c.lo
            lo[:, j, i], hi[:, j, i] = c.lo, c.hi
        else:
            lo[:, k, k] = hi[:, k, k] = 1.0
            lo[:, i, i], hi[:, i, i] = c.lo, c.hi
            lo[:, j, j], hi[:, j, j] = c.lo, c.hi
            lo[:, i, j], hi[:, i, j] = -s.hi, -s.lo
            lo[:, j, i], hi[:, j, i] = s.lo, s.hi
        return Interval(lo, hi)

    a, b, c = angles[:, 0], angles[:, 1], angles[:, 2]
    # each factor: its axis, its angle and that angle's coefficients on (a, b, c)
    if spec.convention == "xyz-fixed":
        plan = [(2, c, (0, 0, 1)), (1, b, (0, 1, 0)), (0, a, (1, 0, 0))]
    elif spec.convention == "xyz-moving":
        plan = [(0, a, (1, 0, 0)), (1, b, (0, 1, 0)), (2, c, (0, 0, 1))]
    else:  # tilt-torsion
        plan = [(2, a, (1, 0, 0)), (1, b, (0, 1, 0)), (2, c - a, (-1, 0, 1))]
    factors = [axis(k, t, False) for k, t, _ in plan]
    slopes = [axis(k, t, True) for k, t, _ in plan]

    def product(parts: list[Interval]) -> Interval:
        out = parts[0]
        for F in parts[1:]:
            out = _matmul(out, F)
        return out

    def derivative(var: int) -> Interval:
        terms = [
            product([slopes[g] if g == f else factors[g] for g in range(3)]) * float(coef[var])
            for f, (_, _, coef) in enumerate(plan)
            if coef[var] != 0
        ]
        total = terms[0]
        for term in terms[1:]:
            total = total + term
        return total

    return product(factors), [derivative(var) for var in range(3)] if derivatives else []


def _matmul(A: Interval, Bm: Interval) -> Interval:
    """``A @ B`` of stacks of interval matrices ``(B, p, q) @ (B, q, r)``."""
    out = A[:, :, 0:1] * Bm[:, 0:1, :]
    for k in range(1, A.shape[2]):
        out = out + A[:, :, k : k + 1] * Bm[:, k : k + 1, :]
    return out


def _rotate(R: Interval, x: np.ndarray) -> Interval:
    """``R x_i`` for the rows of ``x`` ``(n, d)``: ``(B, n, d)``."""
    out = R[:, None, :, 0] * x[None, :, 0:1]
    for k in range(1, x.shape[1]):
        out = out + R[:, None, :, k] * x[None, :, k : k + 1]
    return out


def _cross(a: Interval, b: Interval) -> Interval:
    """Cross products along the last axis (a scalar ``(…, 1)`` in 2-D)."""
    if a.shape[-1] == 2:
        return a[..., 0:1] * b[..., 1:2] - a[..., 1:2] * b[..., 0:1]
    parts = [a[..., i] * b[..., j] - a[..., j] * b[..., i] for i, j in ((1, 2), (2, 0), (0, 1))]
    return Interval(np.stack([p.lo for p in parts], -1), np.stack([p.hi for p in parts], -1))


def _enclosures(
    spec: _Spec, lo: np.ndarray, hi: np.ndarray, angles: Interval, *, by_angles: bool = False, derivatives: bool = True
) -> tuple[Interval, Interval, Interval]:
    """The structure matrices ``(B, m, n)``, their derivatives ``(B, m, n, q)`` and the
    external wrenches ``(B, m)`` over boxes of positions ``[lo, hi]`` ``(B, d)`` at the
    orientations ``angles`` ``(B, k)``.  The derivatives are in the position (``q = d``), and
    with ``by_angles`` in the angles too (``q = d + k``): since ``v = a − R b − p``,
    ``∂u/∂p = −(I − u uᵀ)/L``, ``∂u/∂θ = (∂u/∂p)(∂R/∂θ) b`` and the moments' derivatives
    ``∂(R b × u) = ∂(R b) × u + R b × ∂u``.  Without ``derivatives``, ``q = 0``."""
    B, d = lo.shape
    p = Interval(lo, hi)[:, None, :]
    if spec.point_mass:
        rb = Interval(np.zeros((B, 1, d)))
        drb: list[Interval] = []
    else:
        # one orientation for every box (a fixed one): its rotation once
        same = not by_angles and bool(np.all(angles.lo == angles.lo[:1]) and np.all(angles.hi == angles.hi[:1]))
        R, dR = _rotations(spec, angles[:1] if same else angles, derivatives=by_angles)
        if same:
            R = Interval(np.broadcast_to(R.lo, (B, *R.shape[1:])), np.broadcast_to(R.hi, (B, *R.shape[1:])))
        rb = _rotate(R, spec.anchors)
        drb = [_rotate(D, spec.anchors) for D in dR]
    v = Interval(spec.exits[None]) - rb - p  # (B, n, d)
    length = v[..., 0].sqr()
    for k in range(1, d):
        length = length + v[..., k].sqr()
    L = length.sqrt()
    u = v / L[..., None]
    slopes_u: list[Interval] = []
    du_angles: list[Interval] = []
    if derivatives:
        # du[..., k, l] = ∂u_k/∂p_l = (u_k u_l − δ_kl) / L
        du = (u[..., :, None] * u[..., None, :] - np.eye(d)) / L[..., None, None]  # (B, n, d, d)
        du_angles = [(du * g[..., None, :]).sum_last() for g in drb]  # each (B, n, d)
        slopes_u = [du[..., :, l] for l in range(d)] + du_angles
    force = Interval(np.broadcast_to(spec.force, (B, d)))
    if spec.point_mass:
        columns, slopes, wrench = u, slopes_u, force
    else:
        columns = _join(u, _cross(rb, u))
        slopes = [_join(g, _cross(rb, g)) for g in slopes_u[:d]]
        slopes += [_join(g, _cross(rb, g) + _cross(dr, u)) for g, dr in zip(du_angles, drb)]
        arm = _rotate(R, spec.wrench_point[None])[:, 0, :]
        moment = _cross(arm, force) + spec.moment
        wrench = _join(force, moment)
    G = (
        Interval(np.stack([g.lo for g in slopes], -1), np.stack([g.hi for g in slopes], -1))
        if slopes
        else Interval(np.zeros(columns.shape + (0,)))
    )
    return (
        Interval(np.swapaxes(columns.lo, 1, 2), np.swapaxes(columns.hi, 1, 2)),
        Interval(np.swapaxes(G.lo, 1, 2), np.swapaxes(G.hi, 1, 2)),
        wrench,
    )


def _join(a: Interval, b: Interval) -> Interval:
    """``[a, b]`` along the last axis."""
    return Interval(np.concatenate([a.lo, b.lo], -1), np.concatenate([a.hi, b.hi], -1))


def _pieces(box: np.ndarray, step: float) -> list[tuple[np.ndarray, np.ndarray]]:
    """The orientation box cut evenly into pieces no wider than ``step`` along each angle."""
    counts = np.maximum(1, np.ceil((box[:, 1] - box[:, 0]) / step).astype(int))
    edges = [np.linspace(lo, hi, k + 1) for (lo, hi), k in zip(box, counts)]
    out = []
    for index in np.ndindex(*counts):
        out.append((np.array([e[i] for e, i in zip(edges, index)]), np.array([e[i + 1] for e, i in zip(edges, index)])))
    return out


def _decide(task: tuple[_Spec, np.ndarray, np.ndarray]) -> np.ndarray:
    """Verdicts (1 inside, −1 outside, 0 undecided) of boxes of positions ``(B, d)``."""
    spec, lo, hi = task
    B = len(lo)
    centre = np.ascontiguousarray(np.broadcast_to(spec.orientation, (B, spec.orientation.size)))
    if spec.orientation_box is None:
        return _verdicts(spec, lo, hi, centre, centre)
    # inner for every piece of the orientation box: the enclosures widen with the angles'
    # range, so the box is cut into pieces no wider than ``orientation_step``
    whole = np.ones(B, dtype=bool)
    for a_lo, a_hi in _pieces(spec.orientation_box, spec.orientation_step):
        verdict = _verdicts(spec, lo, hi, np.tile(a_lo, (B, 1)), np.tile(a_hi, (B, 1)))
        whole &= verdict == 1
        if not whole.any():
            break
    # outside at the centre orientation is outside the total orientation workspace
    at_centre = _verdicts(spec, lo, hi, centre, centre)
    return np.where(at_centre == -1, np.int8(-1), np.where(whole, np.int8(1), np.int8(0)))


def _verdicts(spec: _Spec, lo: np.ndarray, hi: np.ndarray, a_lo: np.ndarray, a_hi: np.ndarray) -> np.ndarray:
    """Verdicts of boxes of positions ``[lo, hi]`` for every orientation of ``[a_lo, a_hi]``;
    the mean-value form runs over the positions, and over the angles when they span a box."""
    if spec.clearance is not None:
        return _clearances(spec, spec.clearance, lo, hi, a_lo, a_hi)
    by_angles = bool(np.any(a_hi > a_lo))
    W, G, wrench = _enclosures(spec, lo, hi, Interval(a_lo, a_hi), by_angles=by_angles)
    mid = 0.5 * (lo + hi)
    a_mid = 0.5 * (a_lo + a_hi)
    Wc, _, _ = _enclosures(spec, mid, mid, Interval(a_mid), derivatives=False)
    if by_angles:
        lo, hi, mid = np.hstack([lo, a_lo]), np.hstack([hi, a_hi]), np.hstack([mid, a_mid])
    bad = ~(np.isfinite(W.lo) & np.isfinite(W.hi)).all(axis=(1, 2)) | ~(np.isfinite(G.lo) & np.isfinite(G.hi)).all(
        axis=(1, 2, 3)
    )
    Wlo, Whi = np.where(bad[:, None, None], -1.0, W.lo), np.where(bad[:, None, None], 1.0, W.hi)
    # the half-widths, rounded up, hold the box around its rounded midpoint
    half = np.maximum(hi - mid, mid - lo) * (1 + 1e-15)
    mean_value = (
        np.where(bad[:, None, None], -1.0, Wc.lo),
        np.where(bad[:, None, None], 1.0, Wc.hi),
        np.where(bad[:, None, None, None], 0.0, G.lo),
        np.where(bad[:, None, None, None], 0.0, G.hi),
        half,
    )
    out = np.zeros(len(lo), dtype=np.int8)
    todo = ~bad
    if not spec.closure and todo.any():
        # tensions proven first: cheap, and sharp where the facets of nearly dependent cables
        # blur the facet test (spatial robots with symmetric cable pairs); the entries'
        # centred form is met with their natural enclosure
        spread = Interval(-half, half)[:, None, None, :]
        centred = Wc + (G * spread).sum_last()
        tight = Interval(np.maximum(W.lo, centred.lo), np.minimum(W.hi, centred.hi))
        args = (spec, tight[todo], Wc[todo], G[todo], half[todo], wrench[todo])
        outside, beyond = _separated(*args)
        out[np.flatnonzero(todo)[outside]] = -1
        # a box whose centre fails cannot be inside
        feasible = np.flatnonzero(todo)[~beyond]
        args = (spec, tight[feasible], Wc[feasible], G[feasible], half[feasible], wrench[feasible])
        out[feasible[_tensions_proven(*args)]] = 1
        todo &= out == 0
        if W.shape[1] > FACET_ROWS:
            todo[:] = False
    if todo.any():
        mean_value = tuple(a[todo] for a in mean_value)
        if spec.closure:
            out[todo] = zonotope_verdicts(
                Wlo[todo], Whi[todo], tension_bounds=spec.tension_bounds, closure=True, mean_value=mean_value
            )
        else:
            o_lo = wrench.lo if spec.around_external else np.zeros_like(wrench.lo)
            o_hi = wrench.hi if spec.around_external else np.zeros_like(wrench.hi)
            out[todo] = zonotope_verdicts(
                Wlo[todo],
                Whi[todo],
                tension_bounds=spec.tension_bounds,
                wrench_lo=o_lo[todo],
                wrench_hi=o_hi[todo],
                centre=spec.centre,
                radius=spec.radius,
                vertices=spec.vertices,
                mean_value=mean_value,
            )
    # a box where a cable may have no direction (an exit point in it) decides nothing
    out[bad] = 0
    return out


def _clearances(
    spec: _Spec, clearance: Clearance, lo: np.ndarray, hi: np.ndarray, a_lo: np.ndarray, a_hi: np.ndarray
) -> np.ndarray:
    """Interference-free verdicts (:mod:`taut.workspace._clearance`) of boxes of positions for
    every orientation of ``[a_lo, a_hi]``."""
    B, d = lo.shape
    mid = 0.5 * (lo + hi)
    if spec.point_mass:
        R = R_mid = Interval(np.broadcast_to(np.eye(d), (B, d, d)))
    else:
        R, _ = _rotations(spec, Interval(a_lo, a_hi), derivatives=False)
        R_mid, _ = _rotations(spec, Interval(0.5 * (a_lo + a_hi)), derivatives=False)
    return clearance_verdicts(clearance, Interval(lo, hi), R, mid, R_mid.mid)


def _separated(
    spec: _Spec, W: Interval, W_centre: Interval, G: Interval, half: np.ndarray, wrench: Interval
) -> tuple[np.ndarray, np.ndarray]:
    """Boxes ``(B,)`` proven outside, and those whose centre is outside: one direction ``c`` along which a required wrench lies
    beyond the available wrench set of every pose of the box.

    ``c`` is the facet normal the required set crosses farthest at the box's centre
    (:func:`taut.interval.separating_directions`); it separates at a pose when
    ``max_x c·(−(o + x)) > Σ_i max(c·w_i τ_min,i, c·w_i τ_max,i)``, which the box proves with
    ``c·w_i`` enclosed by its centred form (the derivative enclosures ``G``, ``c`` being a
    point) met with its natural enclosure — the outside test of Gouttefarde, Daney & Merlet
    (2011, §IV) along one fixed hyperplane, so that no interval minor is needed."""
    B, m, n = W.shape
    tmin, tmax = spec.tension_bounds
    o = wrench if spec.around_external else Interval(np.zeros((B, m)))
    direction, gap = separating_directions(
        W_centre.mid,
        tension_bounds=(tmin, tmax),
        wrench=o.mid,
        centre=spec.centre,
        radius=spec.radius,
        vertices=spec.vertices,
    )
    c = Interval(direction)[:, :, None]  # (B, m, 1)
    natural = _sum_rows(c * W)
    spread = Interval(-half, half)[:, None, :]
    centred = _sum_rows(c * W_centre) + (_sum_rows(c[..., None] * G) * spread).sum_last()
    along = Interval(np.maximum(natural.lo, centred.lo), np.minimum(natural.hi, centred.hi))  # (B, n)
    # the support over the box, rounded up: each term's largest value at its upper end
    top = along.hi
    terms = np.where(top > 0, (Interval(top) * tmax).hi, (Interval(top) * tmin).hi)
    support = Interval(terms).sum_last().hi
    need = -(Interval(direction) * o).sum_last()
    if spec.vertices is not None:
        need = need + Interval(np.max((-(Interval(direction)[:, None, :] * spec.vertices)).sum_last().lo, axis=1))
    else:
        need = need + (-(Interval(direction) * spec.centre) + Interval(np.abs(direction)) * spec.radius).sum_last()
    scale = np.abs(terms).sum(axis=1) + np.abs(need.lo)
    return (gap > 0) & np.isfinite(support) & (need.lo - support > OUTSIDE_RTOL * scale), gap > 0


def _tensions_proven(
    spec: _Spec, W: Interval, W_centre: Interval, G: Interval, half: np.ndarray, wrench: Interval
) -> np.ndarray:
    """Boxes ``(B,)`` where tensions within the bounds are proven for every pose of the box and
    every required wrench: a fixed point of the tensions around those of the box's centre.

    At the centre, ``τ_c`` balances the middle of the required wrenches (the closed-form
    method, near the middle of the ranges) and ``R = D W_cᵀ (W_c D W_cᵀ)⁻¹`` is a right
    inverse of the centre's matrix that moves each cable in proportion to its margin ``D``.
    For a pose ``p`` and a required wrench ``r``, ``τ = τ_c + R y`` balances ``r`` iff
    ``y = g + (I − W(p) R) y`` with ``g = −r − W(p) τ_c``.  Over the box, ``[g]`` is enclosed
    by the centred form of ``W(p) τ_c`` (the derivative enclosures ``G``) and ``[I − W R]`` by
    the matrix enclosure; a vector ``u ≥ |[g]| + |[I − W R]| u`` makes the map send
    ``[−u, u]`` into itself, so that by Brouwer's theorem a solution ``y`` lies there for every
    pose and wrench (the Krawczyk test of Gouttefarde, Daney & Merlet 2011, §IV, with the
    free tensions moved too), and ``τ ∈ τ_c + R [g] + R [I − W R] [−u, u]`` within the
    bounds proves the box inside."""
    from taut.statics import solve_tensions

    B, m, n = W.shape
    tmin, tmax = spec.tension_bounds
    if spec.vertices is not None:
        x = Interval(spec.vertices.min(axis=0), spec.vertices.max(axis=0))
    else:
        x = Interval(spec.centre - spec.radius, spec.centre + spec.radius)
    o = wrench if spec.around_external else Interval(np.zeros((B, m)))
    required = o + x  # the cables give −required
    W0 = W_centre.mid
    # τ_c well inside the bounds: the closed form within bounds shrunk by a margin, the widest
    # that is feasible (a cable left at its bound could not be proven within it)
    span = np.where(np.isfinite(tmax), tmax - tmin, 10.0 * (tmin + 1.0))
    ok = np.zeros(B, dtype=bool)
    tc = np.broadcast_to(tmin, (B, n)).copy()
    for shrink, method in CENTRE_MARGINS:
        if ok.all():
            break
        bounds = (tmin + shrink * span, tmax - shrink * span)
        res = solve_tensions(W0[~ok], required.mid[~ok], tension_bounds=bounds, method=method)
        found = np.flatnonzero(~ok)[np.asarray(res.feasible, bool)]
        tc[found] = np.asarray(res.tensions)[np.asarray(res.feasible, bool)]
        ok[found] = True
    weight = np.maximum(np.minimum(tc - tmin, tmax - tc), 1e-12)
    A = W0 * weight[:, None, :]
    S = A @ np.swapaxes(W0, 1, 2)
    ev = np.linalg.eigvalsh(S)  # S is symmetric: its condition from its eigenvalues
    ok &= ev[:, 0] > 1e-12 * ev[:, -1]
    R = np.swapaxes(A, 1, 2) @ np.linalg.inv(np.where(ok[:, None, None], S, np.eye(m)))  # (B, n, m)
    # the first-order change of the tensions is taken out exactly: with T = −R ∂(W τ_c)/∂q at
    # the centre, τ = τ_c + T Δq + R y leaves only a second-order remainder to y
    spread = Interval(-half, half)  # (B, q)
    Gs = Interval(np.swapaxes(G.lo, 2, 3), np.swapaxes(G.hi, 2, 3))  # (B, m, q, n)
    T = -R @ (Gs.mid @ tc[:, None, :, None])[..., 0]  # (B, n, q)
    moved = Interval(tc) + _apply(T, spread)  # τ_c + T Δq over the box
    # h(q) = W(q) (τ_c + T Δq): ∂h/∂q_k = ∂W/∂q_k (τ_c + T Δq) + W T_k, in the centred form
    dh = (Gs * moved[:, None, None, :]).sum_last() + _matmul(W, Interval(T))  # (B, m, q)
    centre = _apply_interval(W_centre, Interval(tc))
    h_box = centre + (dh * spread[:, None, :]).sum_last()
    g = -required - h_box
    IM = Interval(np.eye(m)) - _matmul(W, Interval(R))
    a = np.maximum(np.abs(g.lo), np.abs(g.hi))
    D = np.maximum(np.abs(IM.lo), np.abs(IM.hi))
    u = a.copy()
    for _ in range(40):
        u = a + np.einsum("bij,bj->bi", D, u)
    u = u * 1.01 + 1e-12
    bound = (Interval(a) + _apply_interval(Interval(D), Interval(u))).hi
    ok &= np.all(np.isfinite(u), axis=1) & np.all(bound < u, axis=1)
    u = np.where(ok[:, None], u, 0.0)
    # τ ∈ τ_c + T [Δq] + R [g] + R [I − W R] [−u, u], with R [g] in the centred form again
    Rg = _apply(R, -required) - _apply(R, centre) - (_matmul(Interval(R), dh) * spread[:, None, :]).sum_last()
    tau = moved + Rg + _apply_interval(_matmul(Interval(R), IM), Interval(-u, u))
    return ok & np.all(tau.lo >= tmin, axis=1) & np.all(tau.hi <= tmax, axis=1)


def _sum_rows(x: Interval) -> Interval:
    """Sums over the second axis (the wrench components of ``(B, m, …)``)."""
    return Interval(np.moveaxis(x.lo, 1, -1), np.moveaxis(x.hi, 1, -1)).sum_last()


def _apply(C: np.ndarray, r: Interval) -> Interval:
    """``C [r]`` for float matrices ``(B, m, m)`` and interval vectors ``(B, m)``."""
    return _apply_interval(Interval(C), r)


def _apply_interval(A: Interval, r: Interval) -> Interval:
    """``[A] [r]`` for interval matrices ``(B, p, q)`` and interval vectors ``(B, q)``."""
    out = A[:, :, 0] * r[:, 0:1]
    for j in range(1, A.shape[2]):
        out = out + A[:, :, j] * r[:, j : j + 1]
    return out


def _spec(
    robot: Robot, condition: WorkspaceCondition, orientation: np.ndarray, box: np.ndarray | None, step: float
) -> _Spec:
    d, m = robot.dimension, robot.wrench_dim
    why = None
    if robot.n_joints:
        why = "its platform has jointed bodies"
    elif robot.swivel_cables:
        why = "its cables leave through swivelling pulleys, whose exit points move"
    elif robot.obstacles:
        why = "it has obstacles its cables may wrap around"
    elif robot.routed_cables:
        why = "its cables run through via points"
    elif robot.n_cables < m:
        why = f"it has {robot.n_cables} cables for {m} wrench components: its workspace has no interior to certify"
    if why is not None:
        raise UnsupportedRobotError(f"{robot.name}: certified workspaces take robots with fixed exit points; {why}")
    closure = isinstance(condition, WrenchClosure)
    centre, radius, vertices = np.zeros(m), np.zeros(m), None
    around = True
    if isinstance(condition, WrenchFeasible):
        ws = condition.required_set(robot)
        around = condition.around_external
        if isinstance(ws, BoxWrenchSet):
            centre, radius = 0.5 * (ws.lower + ws.upper), 0.5 * (ws.upper - ws.lower)
        elif isinstance(ws, SingleWrench):
            centre = np.asarray(ws.wrench, float)
        elif isinstance(ws, PolytopeWrenchSet):
            vertices = np.asarray(ws.vertices, float)
        else:
            raise ArgumentError(
                f"a certified workspace takes a box, polytope or single-wrench set; a {type(ws).__name__} cannot be certified"
            )
    elif not isinstance(condition, (StaticEquilibrium, WrenchClosure, InterferenceFree)):
        raise ArgumentError(
            f"the {condition.name!r} condition cannot be certified; certified conditions: "
            "wrench-feasible, static, wrench-closure, interference-free"
        )
    plat = robot.platform
    force = robot.weight + robot.body_weights.sum(axis=0)
    moment = np.zeros(m - d)
    if plat.wrench is not None:
        force = force + np.asarray(plat.wrench[:d], float)
        moment = np.asarray(plat.wrench[d:], float)
    point = np.zeros(d) if plat.wrench_point is None else np.asarray(plat.wrench_point, float)
    tmin, tmax = robot.tension_bounds
    return _Spec(
        exits=np.asarray(robot.exits, float),
        anchors=np.asarray(robot.anchors, float),
        point_mass=robot.is_point_mass,
        convention=robot.orientation,
        orientation=orientation,
        orientation_box=box,
        orientation_step=step,
        tension_bounds=(np.asarray(tmin, float), np.asarray(tmax, float)),
        closure=closure,
        around_external=around,
        force=np.asarray(force, float),
        moment=moment,
        wrench_point=point,
        centre=centre,
        radius=radius,
        vertices=vertices,
        clearance=clearance_spec(robot) if isinstance(condition, InterferenceFree) else None,
    )


def _as_box(value: npt.ArrayLike, rows: int, what: str) -> np.ndarray:
    try:
        box = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentError(f"{what} must be numbers, shape ({rows}, 2)") from None
    if box.shape != (rows, 2) or not np.all(np.isfinite(box)):
        raise ArgumentError(
            f"{what} must be finite numbers of shape ({rows}, 2) ([lo, hi] per coordinate), got shape {box.shape}"
        )
    if np.any(box[:, 0] > box[:, 1]):
        raise ArgumentError(f"{what} is inverted: a lower end above its upper end in {box.tolist()}")
    return box


def _split(lo: np.ndarray, hi: np.ndarray, eps: float) -> tuple[np.ndarray, np.ndarray]:
    """Each box cut across every side at least half as wide as its widest and wider than
    ``eps`` (near-cubes into ``2^d`` children at once: the halves a one-side cut would leave
    undecided are not evaluated on the way); the children of a box follow one another."""
    width = hi - lo
    cut = (width >= 0.5 * width.max(axis=1, keepdims=True)) & (width > eps)
    cut[np.arange(len(lo)), np.argmax(width, axis=1)] = True
    mid = 0.5 * (lo + hi)
    parts_lo, parts_hi = [lo], [hi]
    for axis in range(lo.shape[1]):
        new_lo, new_hi = [], []
        for a, b in zip(parts_lo, parts_hi):
            upper_lo, lower_hi = a.copy(), b.copy()
            upper_lo[:, axis] = np.where(cut[:, axis], mid[:, axis], a[:, axis])
            lower_hi[:, axis] = np.where(cut[:, axis], mid[:, axis], b[:, axis])
            new_lo += [a, upper_lo]
            new_hi += [lower_hi, b]
        parts_lo, parts_hi = new_lo, new_hi
    k = len(parts_lo)
    los, his = np.stack(parts_lo, 1), np.stack(parts_hi, 1)  # (B, 2^d, d)
    # a side not cut gives two copies of one box: keep the lower one
    d = lo.shape[1]
    upper = np.array([[(j >> (d - 1 - a)) & 1 for a in range(d)] for j in range(k)], dtype=bool)  # (2^d, d)
    keep = ~np.any(upper[None, :, :] & ~cut[:, None, :], axis=2)
    return los[keep], his[keep]


def certified(
    robot: Robot,
    condition: str | WorkspaceCondition = "wrench-feasible",
    region: npt.ArrayLike | None = None,
    *,
    orientation: npt.ArrayLike | None = None,
    orientation_box: npt.ArrayLike | None = None,
    orientation_step: float = ORIENTATION_STEP,
    eps: float = DEFAULT_EPS,
    max_boxes: int = MAX_BOXES,
    executor: Executor | str | None = None,
    progress: Callable[[int, int | None], None] | None = None,
    **options: Any,
) -> CertifiedWorkspace:
    """The workspace of a condition over a region of positions, certified by interval analysis:
    boxes proven inside, proven outside, and an undecided boundary layer of boxes no wider
    than ``eps``.

    Parameters
    ----------
    robot : Robot
        A point mass or a rigid platform, planar or spatial, with fixed exit points.
    condition : str or WorkspaceCondition, default "wrench-feasible"
        ``wrench-feasible`` (box, polytope or single-wrench sets), ``static``,
        ``wrench-closure`` or ``interference-free``, by name or instance.
    region : array_like, shape (d, 2), optional
        ``[lo, hi]`` of each position coordinate (default: the box of the exit points,
        :func:`~taut.workspace.default_bounds`).
    orientation : array_like, optional
        The fixed orientation of a rigid platform (θ, or three angles in the robot's
        convention; default zeros).
    orientation_box : array_like, shape (k, 2), optional
        Instead: ``[lo, hi]`` of each angle; inner boxes then hold for every orientation of it
        (the total orientation workspace), outer boxes fail at its centre.
    orientation_step : float, default 0.05
        The orientation box is cut into pieces no wider than this [rad]; a box of positions
        is inner when it is inner for every piece (the enclosures widen with the angles'
        range: spatial platforms may need 0.005).
    eps : float, default 0.01
        Boxes no wider than this [m] are not cut further.
    max_boxes : int, default 2000000
        Budget of boxes evaluated (:data:`taut.interval.MAX_BOXES`, as the interval solvers');
        beyond it the boxes left are reported undecided and the result is incomplete.
    executor : Executor, optional
        Where the chunks of boxes are decided (:func:`taut.parallel.get_executor`; default
        serial).
    progress : callable, optional
        ``progress(done, 1000)``: the permille of the region's volume decided so far.
    **options
        Passed to the condition's class when ``condition`` is a name (e.g. ``wrench_set``).

    Returns
    -------
    CertifiedWorkspace

    Raises
    ------
    UnsupportedRobotError
        Jointed platforms, swivelling pulleys, obstacles, fewer cables than wrench components.
    ArgumentError
        An empty, inverted or non-finite region or orientation box, ``eps ≤ 0``, a bad
        budget, or a condition or wrench set that cannot be certified.
    GridSizeError
        A region so much larger than ``eps`` that even its boundary layer exceeds the budget
        by orders of magnitude (more than 1e12 boxes of width ``eps``).

    References
    ----------
    .. [1] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of
       the wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on
       Robotics 27(1), 2011, §III–V. (docs/references.bib: gouttefarde2011)

    Examples
    --------
    The static workspace of the planar 4-cable robot at θ = 0, to 5 cm: the true area lies
    between the inner area and the inner plus undecided area.

    >>> from taut.model import example
    >>> res = certified(example("planar-4cable"), "static", eps=0.05)
    >>> lo, hi = res.inner_volume, res.inner_volume + res.undecided_volume
    >>> bool(0 < lo < hi <= res.region_volume)
    True
    """
    t0 = time.perf_counter()
    if (
        isinstance(eps, bool)
        or not isinstance(eps, (int, float, np.floating, np.integer))
        or not np.isfinite(eps)
        or eps <= 0
    ):
        raise ArgumentError(f"eps must be a positive number of metres, got {eps!r}")
    if (
        isinstance(orientation_step, bool)
        or not isinstance(orientation_step, (int, float, np.floating, np.integer))
        or not np.isfinite(orientation_step)
        or orientation_step <= 0
    ):
        raise ArgumentError(f"orientation_step must be a positive number of radians, got {orientation_step!r}")
    if isinstance(max_boxes, bool) or not isinstance(max_boxes, (int, np.integer)) or max_boxes < 1:
        raise ArgumentError(f"max_boxes must be a positive integer, got {max_boxes!r}")
    if progress is not None and not callable(progress):
        raise ArgumentError(f"progress must be a callable progress(done, total), got {progress!r}")
    cond = make_condition(condition, **options)
    d = robot.dimension
    k = 0 if robot.is_point_mass else (1 if d == 2 else 3)
    reg = default_bounds(robot) if region is None else _as_box(region, d, "region")
    if np.any(reg[:, 1] <= reg[:, 0]):
        raise ArgumentError(f"region is empty: every coordinate needs lo < hi, got {reg.tolist()}")
    box = None
    if orientation_box is not None:
        if k == 0:
            raise ArgumentError(f"{robot.name}: a point mass has no orientation box")
        if orientation is not None:
            raise ArgumentError("give orientation or orientation_box, not both")
        box = _as_box(orientation_box, k, "orientation_box")
        fixed = 0.5 * (box[:, 0] + box[:, 1])
    else:
        fixed = np.zeros(k) if orientation is None else np.array(orientation, dtype=float).reshape(-1)
        if fixed.shape != (k,) or not np.all(np.isfinite(fixed)):
            raise ArgumentError(f"{robot.name}: the orientation takes {k} finite angles, got {orientation!r}")
    widths = reg[:, 1] - reg[:, 0]
    if float(np.prod(np.maximum(widths / eps, 1.0))) > 1e12:
        raise GridSizeError(
            f"eps = {eps:g} m cuts the region {reg.tolist()} into more than 1e12 boxes; raise eps or shrink the region"
        )
    if box is not None and float(np.prod(np.ceil((box[:, 1] - box[:, 0]) / orientation_step))) > MAX_PIECES:
        raise ArgumentError(
            f"the orientation box {box.tolist()} cut into pieces of {orientation_step:g} rad makes more than "
            f"{MAX_PIECES} pieces; raise orientation_step or shrink the box"
        )
    spec = _spec(robot, cond, fixed, box, float(orientation_step))
    ex = as_executor(executor)
    total = float(np.prod(widths))
    inner: list[np.ndarray] = []
    outer: list[np.ndarray] = []
    undecided: list[np.ndarray] = []
    decided_volume = 0.0
    lo, hi = reg[None, :, 0].copy(), reg[None, :, 1].copy()
    evaluated = 0
    complete = True
    if progress is not None:
        progress(0, 1000)
    while len(lo):
        if evaluated + len(lo) > max_boxes:
            complete = False
            undecided.append(np.stack([lo, hi], -1))
            break
        tasks = [(spec, lo[i : i + CHUNK_BOXES], hi[i : i + CHUNK_BOXES]) for i in range(0, len(lo), CHUNK_BOXES)]
        verdict = np.concatenate(ex.map(_decide, tasks))
        evaluated += len(lo)
        small = (hi - lo).max(axis=1) <= eps
        keep = (verdict == 0) & ~small
        for mask, bucket in ((verdict == 1, inner), (verdict == -1, outer), ((verdict == 0) & small, undecided)):
            if mask.any():
                bucket.append(np.stack([lo[mask], hi[mask]], -1))
                decided_volume += float(np.prod(hi[mask] - lo[mask], axis=1).sum())
        if progress is not None:
            progress(min(1000, int(1000 * decided_volume / total)), 1000)
        lo, hi = _split(lo[keep], hi[keep], eps)

    def stacked(parts: list[np.ndarray]) -> np.ndarray:
        return np.concatenate(parts) if parts else np.zeros((0, d, 2))

    return CertifiedWorkspace(
        robot_name=robot.name,
        condition=cond.name,
        axis_names=tuple(robot.pose_names[:d]),
        region=reg,
        orientation=fixed,
        orientation_box=box,
        eps=float(eps),
        inner=stacked(inner),
        outer=stacked(outer),
        undecided=stacked(undecided),
        complete=complete,
        evaluated=evaluated,
        elapsed_s=time.perf_counter() - t0,
    )
