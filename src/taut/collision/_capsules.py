"""Capsule collision model of a robot (§2.3.2, §3.1.2 and §3.4 of
Lieskovský 2020).

Every collidable element is a *capsule*: a segment swept by a sphere of radius ``ρ``
(Fig. 2.1).  The model of a robot is

* one capsule per cable, from its exit point ``a_i`` to its anchor ``b_i``, radius
  ``cables[i].radius`` (§3.1.2: a taut cable is a single capsule); a cable routed through via
  points (``cables[].via``) is a chain of segments, one capsule each: the cable's own from
  its last via point to its anchor, then the earlier ones after every cable's (segments of
  one cable, which meet at its via points, are not checked against each other);
* the capsules of the platform (``platform.shape.capsules``, body 0) and of each extra
  body (``platform.bodies[k].capsules``), in that order — e.g. the two rectangles and the
  joint column of the adjustable platform (Fig. 3.3).

Capsule ``c`` has the 0-based index ``c`` (cables first), so that the 1-based numbers shown
to users follow the columns of ``D`` in Eq. 3.4.1.  The pairs checked are those of §3.4:

* cable–cable, every pair (``D_I``, Eq. 3.4.2);
* cable–body capsule (``D_II``, ``D_III``, Eqs. 3.4.3–3.4.4), except the capsules of the
  cable's own body that contain its anchor (the zeros of ``D_II``: a cable cannot hit the
  platform segment it is attached to without hitting the others first), and likewise for a
  segment's via points, and the capsules of a body that both ends of a segment are on;
* body–body pairs are not checked: the joint limits keep the bodies apart (§3.1.2).

Cables that share an end point (all cables of a point-mass platform at their anchor,
cables leaving one exit point, segments through one via point) always touch there; such a pair is compared with the shared
end cut back by ``c = (ρ_i + ρ_j) / sin(SHARED_END_ANGLE)`` (at least ``SHARED_END_MIN`` of
the shorter cable): the two interfere iff their capsules meet farther than ``c`` from the
common point — at an angle of about one degree or less, or by crossing elsewhere.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2, §3.1.2, §3.4, Eqs.
   3.4.1–3.4.4, Figs. 2.1 and 3.3. (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from taut._results import Result
from taut.errors import TautError
from taut.kinematics import anchors_at, body_frames, cable_paths, via_points_at
from taut.model import Robot

__all__ = ["CapsuleModel", "capsule_model", "capsule_segments"]

#: Cables sharing an end point interfere iff their angle there is below about this [rad].
SHARED_END_ANGLE = math.radians(1.0)
#: Smallest cut at a shared end, as a fraction of the shorter cable (cables of radius 0).
SHARED_END_MIN = 1e-6
#: Anchors closer than this [m] to a capsule's segment are "on" it; end points closer than
#: this coincide.
ON_TOL = 1e-9


@dataclass(frozen=True)
class CapsuleModel(Result):
    """The capsules of a robot and the pairs to check (:func:`capsule_model`).

    Capsule ``c`` has the 0-based index ``c``: the cables first, then the body capsules.

    Attributes
    ----------
    names : tuple of str
        Capsule names (``"cable 1"`` … then the body capsules' names).
    radii : ndarray, shape (C,)
        Capsule radii ``ρ`` [m].
    body : ndarray of int, shape (C,)
        The body of each body capsule (0 the platform), ``-1`` for cables.
    local : ndarray, shape (K, 2, 3)
        End points of the body capsules in their body frames [m].
    n_cables : int
        The number of cable capsules, the rows of ``D``: one per cable, then one per earlier
        segment of the routed cables (``cables[].via``).
    pairs : ndarray of int, shape (P, 2)
        The pairs checked, capsule indices ``i < j`` (``i`` always a cable).
    shared : ndarray of bool, shape (P, 2)
        A common exit point / anchor of a cable–cable pair.
    cut : ndarray, shape (P,)
        The cut-back length ``c`` [m] at a shared end.
    flip : ndarray of bool, shape (P,)
        Compare capsule ``j`` of the pair turned round (its ``B`` end is ``i``'s ``A`` or its
        ``A`` end ``i``'s ``B``: two routed cables through one via point).

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2, §3.4.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.collision import capsule_model
    >>> model = capsule_model(example("adjustable-8cable"))
    >>> model.n_capsules, model.names[8], len(model.pairs)
    (17, 'segment 9 (B1-B2)', 84)
    """

    names: tuple[str, ...]
    radii: np.ndarray  #: ``(C,)``
    body: np.ndarray  #: ``(C,)`` body index of body capsules, ``-1`` for cables
    local: np.ndarray  #: ``(K, 2, 3)`` end points of the body capsules in their body frames
    n_cables: int
    pairs: np.ndarray
    shared: np.ndarray
    cut: np.ndarray
    flip: np.ndarray

    @property
    def n_capsules(self) -> int:
        """The number of capsules ``C``."""
        return len(self.names)


def _point_on_segment(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> bool:
    v = b - a
    vv = float(v @ v)
    t = 0.0 if vv == 0 else min(1.0, max(0.0, float((p - a) @ v) / vv))
    return float(np.linalg.norm(a + t * v - p)) <= ON_TOL


def capsule_model(robot: Robot) -> CapsuleModel:
    """The capsule model of a robot: one capsule per cable (and per earlier segment of a cable
    routed through via points), those of the bodies, and the pairs to check (cable–cable and
    cable–body, §3.4).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    CapsuleModel

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.1.2, §3.4.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    The planar robot has four cable capsules and no body capsule: six cable pairs.

    >>> from taut.model import example
    >>> from taut.collision import capsule_model
    >>> model = capsule_model(example("planar-4cable"))
    >>> model.n_capsules, model.pairs.tolist()
    (4, [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]])
    """
    n = robot.n_cables
    caps = robot.body_capsules
    pad = np.zeros(3 - robot.dimension)
    owner, ends = _cable_capsules(robot)
    nc = len(owner)
    counts = np.bincount(owner[n:], minlength=n)
    rank = np.arange(nc - n) - np.searchsorted(owner[n:], owner[n:])  # the segment's place on its cable
    names = [f"cable {i + 1}" for i in range(n)]
    names += [f"cable {i + 1} segment {k + 1} of {counts[i] + 1}" for i, k in zip(owner[n:], rank)]
    names += [c.name or f"body {k} capsule" for k, c in caps]
    radii = np.array([robot.cables[i].radius for i in owner] + [c.radius for _, c in caps], float)
    body = np.array([-1] * nc + [k for k, _ in caps], int)
    local = np.array([[np.r_[c.a, pad], np.r_[c.b, pad]] for _, c in caps], float).reshape(-1, 2, 3)
    # every pair of capsules of different cables in the order of a double loop over i < j
    # (vectorised: 2 million pairs for 2000 cables), then the cable–body pairs
    ii, jj = np.triu_indices(nc, k=1)
    keep = owner[ii] != owner[jj]
    ii, jj = ii[keep], jj[keep]

    def same(e: int, f: int) -> np.ndarray:
        """Whether end ``e`` of capsule ``i`` and end ``f`` of capsule ``j`` are one point."""
        bi, pi = ends[e]
        bj, pj = ends[f]
        return (bi[ii] == bj[jj]) & (np.linalg.norm(pi[ii] - pj[jj], axis=1) <= ON_TOL)

    aa, bb, ab, ba = same(0, 0), same(1, 1), same(0, 1), same(1, 0)
    # a segment that ends where another starts (an eyelet two cables run through) is compared
    # with the other turned round, so that the shared ends are both ``A`` or both ``B``
    flip = (ab | ba) & ~(aa | bb)
    shared = np.stack([np.where(flip, ab, aa), np.where(flip, ba, bb)], axis=1)
    # a cable capsule is not checked against a capsule of a body one of its ends is on and
    # lies on, nor against those of a body both its ends are on (it moves with that body)
    body_pairs = [
        (c, nc + k)
        for c in range(nc)
        for k, (bk, _) in enumerate(caps)
        if not (ends[0][0][c] == ends[1][0][c] == bk)
        and not any(ends[e][0][c] == bk and _point_on_segment(ends[e][1][c], local[k, 0], local[k, 1]) for e in (0, 1))
    ]
    m = len(body_pairs)
    return CapsuleModel(
        tuple(names),
        radii,
        body,
        local,
        nc,
        np.concatenate([np.stack([ii, jj], axis=1), np.array(body_pairs, int).reshape(-1, 2)]),
        np.concatenate([shared, np.zeros((m, 2), bool)]),
        np.concatenate([(radii[ii] + radii[jj]) / math.sin(SHARED_END_ANGLE), np.zeros(m)]),
        np.concatenate([flip, np.zeros(m, bool)]),
    )


def _cable_capsules(robot: Robot) -> tuple[np.ndarray, tuple[tuple[np.ndarray, np.ndarray], ...]]:
    """The cable of each cable capsule (``(n + V,)``: one per cable, from the start of its
    last straight segment to its anchor, then one per earlier segment of the routed cables, in
    the order of ``Robot.via_points``) and the two ends of each as ``(body, point)``: the body
    (−1 the fixed frame) and the point in its frame ``(n + V, 3)``."""
    n, d = robot.n_cables, robot.dimension
    via_cables, via_bodies, via_points = robot.via_points
    V = len(via_cables)

    def lift(points: np.ndarray) -> np.ndarray:
        return np.concatenate([points, np.zeros((len(points), 3 - d))], axis=1)

    exits, anchors, vias = lift(robot.exits), lift(robot.anchors), lift(via_points)
    first, last = _chain_ends(via_cables)
    # the main capsule starts at the cable's last via point, or at its exit point
    start_body, start = np.full(n, -1), exits.copy()
    start_body[via_cables[last]], start[via_cables[last]] = via_bodies[last], vias[last]
    # segment k of a routed cable runs from its exit point or via point k − 1 to via point k
    rest = np.flatnonzero(~first)
    seg_body, seg_start = np.full(V, -1), exits[via_cables]
    seg_body[rest], seg_start[rest] = via_bodies[rest - 1], vias[rest - 1]
    owner = np.concatenate([np.arange(n), via_cables])
    a = (np.concatenate([start_body, seg_body]), np.vstack([start, seg_start]))
    b = (np.concatenate([robot.cable_bodies, via_bodies]), np.vstack([anchors, vias]))
    return owner, (a, b)


def _chain_ends(via_cables: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Which via points are the first and which the last of their cable's."""
    first, last = np.ones(len(via_cables), bool), np.ones(len(via_cables), bool)
    first[1:] = last[:-1] = via_cables[1:] != via_cables[:-1]
    return first, last


def checked_model(robot: Robot, model: object) -> CapsuleModel:
    """``model`` if it is a :class:`CapsuleModel` of a robot with ``robot``'s cables and
    capsules, else a :class:`~taut.errors.TautError`."""
    if not isinstance(model, CapsuleModel):
        raise TautError(f"model must be a CapsuleModel (capsule_model(robot)), got {type(model).__name__}")
    cables = robot.n_cables + len(robot.via_points[0])
    if model.n_cables != cables or model.n_capsules != cables + len(robot.body_capsules):
        raise TautError(
            f"{robot.name}: the capsule model has {model.n_cables} cable capsules and {model.n_capsules} capsules, "
            f"the robot {cables} and {cables + len(robot.body_capsules)}"
        )
    return model


def capsule_segments(
    robot: Robot, poses: np.ndarray, *, model: CapsuleModel | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """The end points of every capsule at checked poses.

    Cable capsules run from the exit point (``A``; the tangent point of a swivelling pulley)
    to the anchor (``B``).

    Parameters
    ----------
    robot : Robot
    poses : ndarray, shape (N, pose_size)
        Poses already checked by :func:`taut.kinematics.as_poses`.
    model : CapsuleModel, optional
        ``robot``'s capsule model; default :func:`capsule_model`.

    Returns
    -------
    A, B : ndarray, shape (N, C, 3)
        The end points [m] (planar robots get ``z = 0``).

    Raises
    ------
    PoseError
        ``poses`` is not an ``(N, pose_size)`` array.
    TautError
        A model of another robot.

    Examples
    --------
    >>> import numpy as np
    >>> from taut.model import example
    >>> from taut.collision import capsule_segments
    >>> A, B = capsule_segments(example("planar-4cable"), np.zeros((1, 3)))
    >>> A[0, 0], B[0, 0]
    (array([-1., -1.,  0.]), array([-0.1 , -0.05,  0.  ]))
    """
    model = capsule_model(robot) if model is None else checked_model(robot, model)
    b = anchors_at(robot, poses)  # refuses what is not an (N, pose_size) array
    N, n, nc, d = poses.shape[0], robot.n_cables, model.n_cables, robot.dimension
    A = np.zeros((N, model.n_capsules, 3))
    B = np.zeros((N, model.n_capsules, 3))
    vias = via_points_at(robot, poses)
    moving = robot.swivel_cables or robot.routed_cables
    A[:, :n, :d] = cable_paths(robot, b, via=vias if robot.routed_cables else None)[1] if moving else robot.exits
    B[:, :n, :d] = b
    if nc > n:
        first, _ = _chain_ends(robot.via_points[0])
        rest = np.flatnonzero(~first)
        A[:, n:nc, :d] = robot.exits[robot.via_points[0]]
        A[:, n + rest, :d] = vias[:, rest - 1]
        B[:, n:nc, :d] = vias
    if model.n_capsules > nc:
        pos, rot = body_frames(robot, poses)
        k = model.body[nc:]
        loc = model.local[..., :d]
        A[:, nc:, :d] = pos[:, k] + np.einsum("nkij,kj->nki", rot[:, k], loc[:, 0])
        B[:, nc:, :d] = pos[:, k] + np.einsum("nkij,kj->nki", rot[:, k], loc[:, 1])
    return A, B
