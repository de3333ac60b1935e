"""Self-collision by capsule proximity: the matrices ``D`` and ``E`` of §3.4 of
Lieskovský (2020) and the colliding pairs at each pose.

For each pair of capsules ``(i, j)`` of :func:`taut.collision.capsule_model` the
proximity ``δ_ij`` is the segment–segment distance of §3.5
(:mod:`taut.geometry._segments`), and the clearance is ``ε_ij = δ_ij − (ρ_i + ρ_j)``
(§2.3.2).  The pose is interference free iff every ``ε_ij > 0``; a pair with ``ε_ij ≤ 0``
collides.  Touching capsules (cables of radius 0 that cross) have ``ε_ij = 0`` only up to
round-off, which depends on the order of the operations: a proximity within ``TOUCH_ULPS``
(16) units in the last place of the pair's scale ``s`` (its largest end-point coordinate
or ``ρ_i + ρ_j``, whichever is larger) of ``ρ_i + ρ_j`` is reported as ``ρ_i + ρ_j``, so
``ε_ij = 0`` and the pair collides — ``|ε_ij| ≤ 16 · 2.2e-16 · s``, 3.6e-14 m for a
10 m robot, is no distance a model resolves.

``D`` (Eq. 3.4.1) has one row per cable and one column per capsule (cables first, then the
body capsules); ``E`` holds the ``ε_ij`` in the same layout (the source prints it
transposed).  Pairs that are not checked are ``NaN`` in both (the source writes 0
in ``D`` and 1 in ``E``).  The distances of all poses and pairs are computed in one Numba
kernel.

References
----------
.. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2, §3.4 (Eq. 3.4.1), §3.5.
   (docs/references.bib: lieskovsky2020)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from numba import njit

from taut._results import Result
from taut.collision._capsules import SHARED_END_MIN, CapsuleModel, capsule_model, capsule_segments, checked_model
from taut.geometry import segment_distance_scalar
from taut.kinematics import as_poses
from taut.model import Robot

__all__ = ["ProximityResult", "proximity"]

#: Machine epsilon of float64.
EPS = float(np.finfo(float).eps)
#: A distance within this many units in the last place of the pair's scale (its largest
#: coordinate, or ``ρ_i + ρ_j``) of ``ρ_i + ρ_j`` is reported as exactly ``ρ_i + ρ_j``:
#: touching, ``ε = 0``, colliding.  The segment distance is accurate to about 4 of them
#: (:mod:`taut.geometry._segments`), so exact contacts are decided alike whatever the
#: order, direction or mirror image of the segments.
TOUCH_ULPS = 16.0


@njit(cache=True)
def _cut(P: np.ndarray, Q: np.ndarray, c: float) -> np.ndarray:
    """``P`` moved towards ``Q`` by ``c`` (at most to ``Q``)."""
    v = Q - P
    L = np.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    if L == 0.0:
        return P.copy()
    return P + v * (min(c, L) / L)


@njit(cache=True)
def _proximity_kernel(
    A: np.ndarray,
    B: np.ndarray,
    pairs: np.ndarray,
    shared: np.ndarray,
    cut: np.ndarray,
    flip: np.ndarray,
    rho: np.ndarray,
    dist: np.ndarray,
) -> None:
    N = A.shape[0]
    for k in range(N):
        for p in range(pairs.shape[0]):
            i, j = pairs[p, 0], pairs[p, 1]
            ai, bi, aj, bj = A[k, i], B[k, i], A[k, j], B[k, j]
            if flip[p]:
                aj, bj = bj, aj
            if shared[p, 0] or shared[p, 1]:
                li = np.sqrt(np.sum((bi - ai) ** 2))
                lj = np.sqrt(np.sum((bj - aj) ** 2))
                c = max(cut[p], SHARED_END_MIN * min(li, lj))
                if shared[p, 0]:
                    ai, aj = _cut(ai, bi, c), _cut(aj, bj, c)
                if shared[p, 1]:
                    bi, bj = _cut(bi, ai, c), _cut(bj, aj, c)
            d = segment_distance_scalar(ai, bi, aj, bj)[0]
            scale = rho[p]
            for c3 in range(3):
                scale = max(scale, abs(ai[c3]), abs(bi[c3]), abs(aj[c3]), abs(bj[c3]))
            dist[k, p] = rho[p] if abs(d - rho[p]) <= TOUCH_ULPS * EPS * scale else d


@dataclass(frozen=True)
class ProximityResult(Result):
    """Proximities of the capsule pairs of ``model`` at ``N`` poses (:func:`proximity`).

    Attributes
    ----------
    model : CapsuleModel
    distances : ndarray, shape (N, P)
        Proximities ``δ`` of ``model.pairs`` [m] (segment–segment distances).
    clearances : ndarray, shape (N, P)
        ``ε = δ − (ρ_i + ρ_j)`` [m]: a pair collides where ``ε ≤ 0``.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §2.3.2, §3.4.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    >>> from taut.model import example
    >>> from taut.collision import proximity
    >>> res = proximity(example("planar-4cable"), [0.0, 0.0, 0.0])
    >>> res.interference_free, res.collisions(0)
    (array([ True]), [])
    """

    model: CapsuleModel
    distances: np.ndarray  #: ``(N, P)`` proximities ``δ`` of ``model.pairs``
    clearances: np.ndarray  #: ``(N, P)`` ``ε = δ − (ρ_i + ρ_j)``

    @property
    def colliding(self) -> np.ndarray:
        """``(N, P)`` bool: ``ε ≤ 0`` (touching within round-off is ``ε = 0``: module docstring)."""
        return self.clearances <= 0.0

    @property
    def interference_free(self) -> np.ndarray:
        """``(N,)`` bool: every checked ``ε > 0`` (§3.4)."""
        return np.asarray(~self.colliding.any(axis=1))

    @property
    def min_clearance(self) -> np.ndarray:
        """``(N,)`` smallest ``ε`` over the checked pairs (``inf`` when none is checked)."""
        if self.clearances.shape[1] == 0:
            return np.full(self.clearances.shape[0], np.inf)
        return self.clearances.min(axis=1)

    def collisions(self, k: int) -> list[tuple[int, int]]:
        """The colliding pairs at pose ``k``.

        Parameters
        ----------
        k : int
            A 0-based pose index.

        Returns
        -------
        list of tuple of int
            0-based capsule indices ``(i, j)``.
        """
        return [(int(self.model.pairs[p, 0]), int(self.model.pairs[p, 1])) for p in np.flatnonzero(self.colliding[k])]

    def _matrix(self, values: np.ndarray) -> np.ndarray:
        N = values.shape[0]
        out = np.full((N, self.model.n_cables, self.model.n_capsules), np.nan)
        out[:, self.model.pairs[:, 0], self.model.pairs[:, 1]] = values
        return out

    @property
    def D(self) -> np.ndarray:
        """Proximity matrix ``D`` (Eq. 3.4.1), ``(N, n, C)``, ``NaN`` where not checked."""
        return self._matrix(self.distances)

    @property
    def E(self) -> np.ndarray:
        """Clearance matrix ``E`` (§3.4), ``(N, n, C)``, ``NaN`` where not checked."""
        return self._matrix(self.clearances)


def proximity(robot: Robot, poses: npt.ArrayLike, *, model: CapsuleModel | None = None) -> ProximityResult:
    """Proximities and clearances of every checked capsule pair at each pose.

    Parameters
    ----------
    robot : Robot
    poses : array_like, shape (N, pose_size) or (pose_size,)
    model : CapsuleModel, optional
        ``robot``'s capsule model; default :func:`capsule_model`.

    Returns
    -------
    ProximityResult
        Always with the batch axis (``N = 1`` for one pose).

    Raises
    ------
    PoseError
        Poses that :func:`~taut.kinematics.as_poses` refuses.
    TautError
        A model of another robot.

    References
    ----------
    .. [1] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, §3.4, Eq. 3.4.1.
       (docs/references.bib: lieskovsky2020)

    Examples
    --------
    At the centre of the planar robot cables 1 and 2 (indices 0 and 1) are 0.2 m apart, the
    distance of their anchors:

    >>> from taut.model import example
    >>> from taut.collision import proximity
    >>> proximity(example("planar-4cable"), [0.0, 0.0, 0.0]).distances.round(3)
    array([[0.2  , 0.224, 0.1  , 0.1  , 0.224, 0.2  ]])
    """
    arr, _ = as_poses(robot, poses)
    model = capsule_model(robot) if model is None else checked_model(robot, model)
    A, B = capsule_segments(robot, arr, model=model)
    dist = np.empty((arr.shape[0], len(model.pairs)))
    rho = model.radii[model.pairs[:, 0]] + model.radii[model.pairs[:, 1]]
    _proximity_kernel(A, B, model.pairs, model.shared, model.cut, model.flip, rho, dist)
    return ProximityResult(model, dist, dist - rho[None, :])
