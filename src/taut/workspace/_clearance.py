"""Certified interference-free boxes: the capsule pairs of the collision model (Lieskovský
2020, §3.4) proven apart, or one pair proven in contact, for every position of a box.

The distance of two capsules does not change when both move by the platform's translation,
so their end points are taken relative to the platform's reference point ``p``: a cable runs
from ``a_i − p`` (an interval over the box) to ``R b_i`` (fixed at a fixed orientation), a
capsule of the platform from ``R a_c`` to ``R b_c``; a shared end is cut back as the point
test cuts it (:mod:`taut.collision`), along the enclosed cable direction.

* **Apart** (every pose of the box): along the unit direction ``ν`` joining the closest
  points of the two segments at the box's centre, every point of one segment lies beyond
  ``min ν·(its ends)`` and every point of the other before ``max ν·(its ends)``; when that gap
  exceeds ``ρ_i + ρ_j`` (by more than the point test's round-off band) the pair is clear — a
  fixed separating direction, as for the wrench sets.
* **In contact** (every pose): the points at the centre's closest-point parameters stay
  closer than ``ρ_i + ρ_j``; or, in the plane, the two segments cross, the four orientation
  predicates keeping strict opposite signs.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2, §3.4, §3.5.
   (docs/references.bib: lieskovsky2020)
.. [2] M. Gouttefarde, D. Daney, J.-P. Merlet, "Interval-analysis-based determination of the
   wrench-feasible workspace of parallel cable-driven robots", IEEE Transactions on Robotics
   27(1), 2011, §IV (box verdicts by interval evaluation). (docs/references.bib: gouttefarde2011)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from taut.collision import capsule_model
from taut.geometry import segment_distance
from taut.interval import Interval
from taut.model import Robot

__all__ = ["Clearance", "clearance_spec", "clearance_verdicts"]

#: Round-off band around contact: the point test reports a distance within 16 ulps of the
#: pair's scale from ``ρ_i + ρ_j`` as contact; a certificate keeps four times that away.
BAND_ULPS = 64.0
_EPS = float(np.finfo(float).eps)
#: The smallest cut at a shared end, as a fraction of the shorter cable (the point test's).
SHARED_END_MIN = 1e-6


@dataclass(frozen=True)
class Clearance:
    """What a worker needs of the capsule model: picklable arrays."""

    exits: np.ndarray  # (n, d)
    anchors: np.ndarray  # (n, d), platform frame
    ends: np.ndarray  # (c, 2, d): the platform's capsules, platform frame
    rho: np.ndarray  # (P,) ρ_i + ρ_j per pair
    pairs: np.ndarray  # (P, 2) capsule indices, cables first
    shared: np.ndarray  # (P, 2) shared exit, shared anchor
    cuts: np.ndarray  # (P,)


def clearance_spec(robot: Robot) -> Clearance:
    """The capsule pairs of ``robot`` (:func:`taut.collision.capsule_model`), in its dimension.

    Parameters
    ----------
    robot : Robot
        Without jointed bodies (the platform's capsules move with the platform).

    Returns
    -------
    Clearance
    """
    model = capsule_model(robot)
    d = robot.dimension
    return Clearance(
        exits=np.asarray(robot.exits, float),
        anchors=np.asarray(robot.anchors, float),
        ends=np.asarray(model.local[..., :d], float),
        rho=model.radii[model.pairs[:, 0]] + model.radii[model.pairs[:, 1]],
        pairs=np.asarray(model.pairs),
        shared=np.asarray(model.shared),
        cuts=np.asarray(model.cut, float),
    )


def _dot(nu: np.ndarray, x: Interval) -> Interval:
    """``ν·x`` for float directions ``(B, d)`` and interval points ``(B, d)``."""
    return (Interval(nu) * x).sum_last()


def _cross2(a: Interval, b: Interval, c: Interval) -> Interval:
    """The orientation ``(b − a) × (c − a)`` of planar interval points ``(B, 2)``."""
    u, v = b - a, c - a
    return u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]


def _segments(cs: Clearance, p: Interval, R: Interval) -> tuple[list[Interval], np.ndarray, np.ndarray]:
    """The end points ``[e1, e2, f1, f2]`` ``(B, P, d)`` of both members of every pair,
    relative to ``p``, with shared ends cut back; ``ok`` ``(B, P)`` False where a cut is not
    proven shorter than its cable (the pair decides nothing); the point test's scale
    ``(B, P)`` (the pair's largest absolute coordinate, or ``ρ_i + ρ_j``), rounded up."""
    B, d = p.shape
    rb = (R[:, None, :, :] * cs.anchors[None, :, None, :]).sum_last()  # (B, n, d)
    a = Interval(cs.exits[None]) - p[:, None, :]
    caps = [(R[:, None, :, :] * cs.ends[None, :, k, None, :]).sum_last() for k in (0, 1)]  # (B, c, d)
    first = Interval(np.concatenate([a.lo, caps[0].lo], 1), np.concatenate([a.hi, caps[0].hi], 1))
    second = Interval(np.concatenate([rb.lo, caps[1].lo], 1), np.concatenate([rb.hi, caps[1].hi], 1))
    i, j = cs.pairs[:, 0], cs.pairs[:, 1]
    ends = [first[:, i], second[:, i], first[:, j], second[:, j]]
    ok = np.ones((B, len(i)), dtype=bool)
    cut = np.flatnonzero(cs.shared.any(axis=1))
    if cut.size:
        v = a - rb  # anchor to exit, (B, n, d)
        length = v[..., 0].sqr()
        for k in range(1, d):
            length = length + v[..., k].sqr()
        L = length.sqrt()  # (B, n)
        ci, cj = i[cut], j[cut]
        short = Interval(np.minimum(L.lo[:, ci], L.lo[:, cj]), np.minimum(L.hi[:, ci], L.hi[:, cj])) * SHARED_END_MIN
        c = Interval(np.maximum(cs.cuts[cut], short.lo), np.maximum(cs.cuts[cut], short.hi))  # (B, K)
        ok[:, cut] = (L.lo[:, ci] > c.hi) & (L.lo[:, cj] > c.hi)
        u = v / Interval(np.where(L.lo > 0, L.lo, 1.0), np.where(L.lo > 0, L.hi, 1.0))[..., None]
        # a shared exit moves towards the anchor (−u), a shared anchor towards the exit (+u)
        for end, sign in ((0, -1.0), (1, 1.0)):
            rows = cut[cs.shared[cut, end]]
            if not rows.size:
                continue
            step = (c[:, np.searchsorted(cut, rows)] * sign)[..., None]
            for x, cable in ((ends[end], i[rows]), (ends[2 + end], j[rows])):
                moved = x[:, rows] + u[:, cable] * step
                x.lo[:, rows], x.hi[:, rows] = moved.lo, moved.hi
    reach = np.max([np.maximum(np.abs(x.lo), np.abs(x.hi)).max(axis=2) for x in ends], axis=0)
    reach = reach + np.maximum(np.abs(p.lo), np.abs(p.hi)).max(axis=1)[:, None]
    scale = np.maximum(np.maximum(reach, np.abs(cs.exits).max(initial=0.0)), cs.rho[None]) * (1 + 1e-12)
    return ends, ok, scale


def clearance_verdicts(cs: Clearance, p: Interval, R: Interval, centre: np.ndarray, R_centre: np.ndarray) -> np.ndarray:
    """Verdicts of boxes of positions ``p`` ``(B, d)`` at the rotations ``R`` ``(B, d, d)``:
    1 every pair apart at every pose, −1 a pair in contact at every pose, 0 undecided.

    Parameters
    ----------
    cs : Clearance
    p : Interval, shape (B, d)
        The boxes of positions.
    R : Interval, shape (B, d, d)
        Enclosures of the rotations (an orientation box, or a fixed one).
    centre, R_centre : ndarray, shapes (B, d) and (B, d, d)
        A position and a rotation within each box, where the directions are chosen.

    Returns
    -------
    ndarray of int8, shape (B,)
    """
    B, d = p.shape
    P = cs.pairs.shape[0]
    if P == 0:
        return np.ones(B, dtype=np.int8)
    flat = (B * P, d)

    def flatten(x: Interval) -> Interval:
        return Interval(x.lo.reshape(flat), x.hi.reshape(flat))

    ends, ok, scale = _segments(cs, p, R)
    e1, e2, f1, f2 = (flatten(x) for x in ends)
    c1, c2, d1, d2 = (x.mid.reshape(flat) for x in _segments(cs, Interval(centre), Interval(R_centre))[0])
    dist, s, t = segment_distance(c1, c2, d1, d2, parameters=True)
    nu = ((c1 + s[:, None] * (c2 - c1)) - (d1 + t[:, None] * (d2 - d1))) / np.where(dist > 0, dist, 1.0)[:, None]
    band = (BAND_ULPS * _EPS * scale).reshape(-1)
    rho = np.broadcast_to(cs.rho, (B, P)).reshape(-1)
    ok = ok.reshape(-1)
    # apart: min over one segment minus max over the other, along ν (|ν| = 1 to round-off)
    near = Interval(np.minimum(_dot(nu, e1).lo, _dot(nu, e2).lo))
    far = Interval(np.maximum(_dot(nu, f1).hi, _dot(nu, f2).hi))
    apart = ok & (dist > 0) & ((near - far).lo * (1 - 1e-12) - rho > band)
    # in contact: the points at the centre's closest-point parameters stay within ρ_i + ρ_j
    S, T = Interval(s[:, None]), Interval(t[:, None])
    diff = (e1 + S * (e2 - e1)) - (f1 + T * (f2 - f1))
    norm = diff[:, 0].sqr()
    for k in range(1, d):
        norm = norm + diff[:, k].sqr()
    contact = ok & (norm.sqrt().hi < rho - band)
    if d == 2:
        # or the segments cross: each one's ends strictly on both sides of the other
        def sides(a: Interval, b: Interval, x: Interval, y: Interval) -> np.ndarray:
            ox, oy = _cross2(a, b, x), _cross2(a, b, y)
            return ((ox.lo > 0) & (oy.hi < 0)) | ((ox.hi < 0) & (oy.lo > 0))

        contact |= ok & sides(e1, e2, f1, f2) & sides(f1, f2, e1, e2)
    out = np.zeros(B, dtype=np.int8)
    out[apart.reshape(B, P).all(axis=1)] = 1
    out[contact.reshape(B, P).any(axis=1)] = -1
    return out
