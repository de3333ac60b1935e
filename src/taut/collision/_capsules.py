"""Capsule collision model of a robot (§2.3.2, §3.1.2 and §3.4 of
Lieskovský 2020).

Every collidable element is a *capsule*: a segment swept by a sphere of radius ``ρ``
(Fig. 2.1).  The model of a robot is

* one capsule per cable, from its exit point ``a_i`` to its anchor ``b_i``, radius
  ``cables[i].radius`` (§3.1.2: a taut cable is a single capsule);
* the capsules of the platform (``platform.shape.capsules``, body 0) and of each extra
  body (``platform.bodies[k].capsules``), in that order — e.g. the two rectangles and the
  joint column of the adjustable platform (Fig. 3.3).

Capsule ``c`` has the 0-based index ``c`` (cables first), so that the 1-based numbers shown
to users follow the columns of ``D`` in Eq. 3.4.1.  The pairs checked are those of §3.4:

* cable–cable, every pair (``D_I``, Eq. 3.4.2);
* cable–body capsule (``D_II``, ``D_III``, Eqs. 3.4.3–3.4.4), except the capsules of the
  cable's own body that contain its anchor (the zeros of ``D_II``: a cable cannot hit the
  platform segment it is attached to without hitting the others first);
* body–body pairs are not checked: the joint limits keep the bodies apart (§3.1.2).

Cables that share an end point (all cables of a point-mass platform at their anchor,
cables leaving one exit point) always touch there; such a pair is compared with the shared
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
from taut.kinematics import anchors_at, body_frames, cable_paths, refuse_routed
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
    pairs : ndarray of int, shape (P, 2)
        The pairs checked, capsule indices ``i < j`` (``i`` always a cable).
    shared : ndarray of bool, shape (P, 2)
        A common exit point / anchor of a cable–cable pair.
    cut : ndarray, shape (P,)
        The cut-back length ``c`` [m] at a shared end.

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
    """The capsule model of a robot: one capsule per cable, those of the bodies, and the pairs
    to check (cable–cable and cable–body, §3.4).

    Parameters
    ----------
    robot : Robot

    Returns
    -------
    CapsuleModel

    Raises
    ------
    UnsupportedRobotError
        Cables routed through via points (a capsule per cable runs from its exit point to its
        anchor).

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
    refuse_routed(robot, "the interference check")
    n = robot.n_cables
    caps = robot.body_capsules
    pad = np.zeros(3 - robot.dimension)
    names = [f"cable {i + 1}" for i in range(n)] + [c.name or f"body {k} capsule" for k, c in caps]
    radii = np.array([c.radius for c in robot.cables] + [c.radius for _, c in caps], float)
    body = np.array([-1] * n + [k for k, _ in caps], int)
    local = np.array([[np.r_[c.a, pad], np.r_[c.b, pad]] for _, c in caps], float).reshape(-1, 2, 3)
    anchors = np.concatenate([robot.anchors, np.zeros((n, 3 - robot.dimension))], axis=1)
    exits = robot.exits
    # every cable pair in the order of a double loop over i < j (vectorised: 2 million pairs
    # for 2000 cables), then the cable–body pairs
    ii, jj = np.triu_indices(n, k=1)
    bodies = np.asarray(robot.cable_bodies)
    same_exit = np.linalg.norm(exits[ii] - exits[jj], axis=1) <= ON_TOL
    same_anchor = (bodies[ii] == bodies[jj]) & (np.linalg.norm(anchors[ii] - anchors[jj], axis=1) <= ON_TOL)
    body_pairs = [
        (i, n + c)
        for i in range(n)
        for c, (k, _) in enumerate(caps)
        if not (k == robot.cable_bodies[i] and _point_on_segment(anchors[i], local[c, 0], local[c, 1]))
    ]
    m = len(body_pairs)
    return CapsuleModel(
        tuple(names),
        radii,
        body,
        local,
        n,
        np.concatenate([np.stack([ii, jj], axis=1), np.array(body_pairs, int).reshape(-1, 2)]),
        np.concatenate([np.stack([same_exit, same_anchor], axis=1), np.zeros((m, 2), bool)]),
        np.concatenate([(radii[ii] + radii[jj]) / math.sin(SHARED_END_ANGLE), np.zeros(m)]),
    )


def checked_model(robot: Robot, model: object) -> CapsuleModel:
    """``model`` if it is a :class:`CapsuleModel` of a robot with ``robot``'s cables and
    capsules, else a :class:`~taut.errors.TautError`."""
    if not isinstance(model, CapsuleModel):
        raise TautError(f"model must be a CapsuleModel (capsule_model(robot)), got {type(model).__name__}")
    if model.n_cables != robot.n_cables or model.n_capsules != robot.n_cables + len(robot.body_capsules):
        raise TautError(
            f"{robot.name}: the capsule model has {model.n_cables} cables and {model.n_capsules} capsules, "
            f"the robot {robot.n_cables} and {robot.n_cables + len(robot.body_capsules)}"
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
    N, n, d = poses.shape[0], robot.n_cables, robot.dimension
    A = np.zeros((N, model.n_capsules, 3))
    B = np.zeros((N, model.n_capsules, 3))
    A[:, :n, :d] = cable_paths(robot, b)[1] if robot.swivel_cables else robot.exits
    B[:, :n, :d] = b
    if model.n_capsules > n:
        pos, rot = body_frames(robot, poses)
        k = model.body[n:]
        loc = model.local[..., :d]
        A[:, n:, :d] = pos[:, k] + np.einsum("nkij,kj->nki", rot[:, k], loc[:, 0])
        B[:, n:, :d] = pos[:, k] + np.einsum("nkij,kj->nki", rot[:, k], loc[:, 1])
    return A, B
