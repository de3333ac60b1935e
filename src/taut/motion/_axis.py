"""Orientation turned about one axis per segment, as CASPR's spherical joints move it.

Between waypoints with rotations ``R_s`` and ``R_e`` the platform turns about the one axis
``k`` by the angle ``θ ∈ [0, π]`` of ``R_sᵀ R_e = Exp(θ k)`` (the short way), the segment's
time law timing the angle turned, ``ψ(t) = σ(t) θ`` with ``σ`` from 0 to 1:

    ``R(t) = R_s Exp(φ(t))``,  ``φ(t) = σ(t) θ k``,
    ``ω = R_s φ̇``,  ``α = R_s φ̈``  (fixed frame; the axis does not move).

This is CASPR's ``SphericalEulerXYZ`` / ``SphericalFixedXYZ`` joint trajectory [1]_: the
quaternion of ``R_sᵀ R_e`` gives the axis and angle (``AxisAngle.FromQuaternion``), the
linear, cubic, quintic or parabolic-blend spline times the angle from 0 to ``θ`` with zero
velocity (and acceleration) at both ends (``Quaternion.LinearInterpolation`` …
``ParabolicBlend``), and the angles are read back from ``R_s`` times the interpolated
quaternion's matrix.  A :class:`~taut.motion._trajectory.Motion` keeps ``φ(t)`` as the
polynomials of its angle columns and :class:`AxisTurns` turns it into the pose's angles in
the robot's convention, with rates ``q̇ = E(q)⁻¹ ω`` and ``q̈ = E(q)⁻¹ (α − Ė(q, q̇) q̇)``
(:mod:`taut.geometry._rates`).

Angles.  CASPR reads the angles back in their principal range (the middle angle in
``[−π/2, π/2]``), so they jump by 2π where an outer angle passes ±π; taut continues them
from the segment's start instead: the same triple family (``(a, b, c)`` or
``(a + π, π − b, c + π)`` in the ``xyz`` conventions, ``(φ, θ, σ)`` or ``(φ + π, −θ, σ)`` in
``tilt-torsion``) and no 2π jump, which give CASPR's angles wherever CASPR's are continuous.
The continuation is followed on a grid of ``ψ`` whose steps are a quarter of the distance
``d(ψ)`` to the gimbal lock (``|cos b|``, ``|sin θ|``): the angles' rates are at most about
``2/d`` per unit of ``ψ``, so a step changes them by less than π and the nearest 2π shift of
the principal angles is the continued one.  ``d(ψ)`` is known in closed form (the entry of
``R`` that fixes the middle angle is ``A cos ψ + B sin ψ + C`` along the segment), so a
segment that comes within :data:`GIMBAL_TOL` of the gimbal lock, where the angles' rates are
unbounded, is refused.

References
----------
.. [1] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
.. [2] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §3.6 (analytical Jacobian), §4.2. (docs/references.bib: siciliano2009)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from taut.errors import TrajectoryError
from taut.geometry import angles_from_matrix, rate_matrix, rate_matrix_derivative, rotation_matrix

__all__ = ["GIMBAL_TOL", "AxisTurns", "axis_turns", "other_triple"]

#: Closest approach to the gimbal lock (``|cos b|``, ``|sin θ|``) a turning segment may make
#: (the angles' rates reach about ``|ω| / GIMBAL_TOL``): read from a rotation matrix, the
#: distance is known only to about 1e-8 near the lock.
GIMBAL_TOL = 1e-6

#: Per convention: the entry ``(i, j)`` of ``R`` that is ``±sin b`` (``cos θ``): the middle
#: angle's distance to the gimbal lock is ``√(1 − R_ij²)``.
_MIDDLE = {"xyz-moving": (0, 2), "xyz-fixed": (2, 0), "tilt-torsion": (2, 2)}

#: Most grid points of one segment (the grid is logarithmic near the gimbal lock: tens).
_MAX_GRID = 100_000

_TWO_PI = 2 * math.pi


def other_triple(angles: np.ndarray, convention: str) -> np.ndarray:
    """The other angle triple of the same rotations ``(..., 3)``: ``(a + π, π − b, c + π)``
    in the ``xyz`` conventions, ``(φ + π, −θ, σ)`` in ``tilt-torsion``."""
    a, b, c = np.moveaxis(np.asarray(angles, dtype=float), -1, 0)
    if convention == "tilt-torsion":
        return np.stack([a + math.pi, -b, c], axis=-1)
    return np.stack([a + math.pi, math.pi - b, c + math.pi], axis=-1)


def _is_other(angles: np.ndarray, convention: str) -> bool:
    """Whether ``angles`` is of the family :func:`~taut.geometry._rotation.angles_from_matrix`
    does not return (``cos b < 0``; ``sin θ < 0``)."""
    b = float(angles[1])
    return (math.sin(b) if convention == "tilt-torsion" else math.cos(b)) < 0


def _nearest(angles: np.ndarray, reference: np.ndarray) -> np.ndarray:
    """``angles`` shifted by multiples of 2π to the nearest of ``reference``."""
    return angles + _TWO_PI * np.round((reference - angles) / _TWO_PI)


def _exp(phi: np.ndarray) -> np.ndarray:
    """Rotation matrices ``(N, 3, 3)`` of rotation vectors ``(N, 3)`` (Rodrigues)."""
    from scipy.spatial.transform import Rotation

    return np.asarray(Rotation.from_rotvec(phi).as_matrix()).reshape(-1, 3, 3)


@dataclass(frozen=True)
class AxisTurns:
    """The turns of a motion's ``S`` segments (read-only arrays): each segment's rotation
    ``starts`` ``(S, 3, 3)`` and unit ``axes`` ``(S, 3)``, whether its angles are the ``other``
    triple family ``(S,)``, and the grid of angles turned ``grids[s]`` ``(G,)`` with the
    continued angles there ``lifts[s]`` ``(G, 3)``."""

    starts: np.ndarray
    axes: np.ndarray
    other: np.ndarray
    grids: tuple[np.ndarray, ...]
    lifts: tuple[np.ndarray, ...]

    def __post_init__(self) -> None:
        for name in ("starts", "axes", "other"):
            getattr(self, name).setflags(write=False)
        for a in self.grids + self.lifts:
            a.setflags(write=False)

    def evaluate(
        self, convention: str, segment: np.ndarray, phi: np.ndarray, phid: np.ndarray, phidd: np.ndarray
    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """Angles, their rates and accelerations ``(N, 3)`` and the angular velocity and
        acceleration ``(N, 3)`` in the fixed frame of samples in segments ``segment`` ``(N,)``
        with rotation vectors ``phi`` turned since the segment's start and their derivatives."""
        Rs = self.starts[segment]
        R = Rs @ _exp(phi)
        q = angles_from_matrix(R, convention)
        flip = self.other[segment]
        if flip.any():
            q[flip] = other_triple(q[flip], convention)
        psi = np.einsum("ni,ni->n", phi, self.axes[segment])
        reference = np.empty_like(q)
        for s in np.unique(segment):
            rows = segment == s
            j = np.clip(np.searchsorted(self.grids[s], psi[rows], side="right") - 1, 0, len(self.grids[s]) - 1)
            reference[rows] = self.lifts[s][j]
        q = _nearest(q, reference)
        w = np.einsum("nij,nj->ni", Rs, phid)
        a = np.einsum("nij,nj->ni", Rs, phidd)
        E = rate_matrix(q, convention)
        qd = np.linalg.solve(E, w[..., None])[..., 0]
        Ed = rate_matrix_derivative(q, qd, convention)
        qdd = np.linalg.solve(E, (a - np.einsum("nij,nj->ni", Ed, qd))[..., None])[..., 0]
        return q, qd, qdd, w, a


def _distance(Rs: np.ndarray, axis: np.ndarray, convention: str) -> tuple[float, float, float]:
    """``(A, B, C)`` with the middle angle's entry of ``R_s Exp(ψ k)`` = ``A cos ψ + B sin ψ + C``."""
    i, j = _MIDDLE[convention]
    r = Rs[i]
    e = np.zeros(3)
    e[j] = 1.0
    C = float(r @ axis) * axis[j]
    return float(r[j] - C), float(r @ np.cross(axis, e)), C


def _gimbal_distance(abc: tuple[float, float, float], psi: np.ndarray | float) -> np.ndarray:
    A, B, C = abc
    m = A * np.cos(psi) + B * np.sin(psi) + C
    return np.sqrt(np.maximum(0.0, 1.0 - m * m))


def _closest_approach(abc: tuple[float, float, float], theta: float) -> float:
    """The least distance to the gimbal lock for ``ψ`` in ``[0, θ]``: at an end or where
    ``−A sin ψ + B cos ψ = 0``."""
    A, B, _ = abc
    first = math.atan2(B, A)
    candidates = [0.0, theta] + [p for p in (first + n * math.pi for n in range(-2, 3)) if 0.0 < p < theta]
    return float(np.min(_gimbal_distance(abc, np.array(candidates))))


def axis_turns(waypoints: np.ndarray, columns: slice, convention: str) -> tuple[np.ndarray, np.ndarray, AxisTurns]:
    """Waypoints with the angles continued along the turns, the rotation vector ``θ k`` of
    each segment ``(S, 3)`` and the :class:`AxisTurns` of the segments.

    The first waypoint keeps its angles; each later one gets the triple of its rotation that
    continues the turn that reaches it (its own, when the turn arrives there; else its own
    shifted by multiples of 2π or its other triple).  Raises
    :class:`~taut.errors.TrajectoryError` when a turn comes within :data:`GIMBAL_TOL` of the
    gimbal lock."""
    from scipy.spatial.transform import Rotation

    W = np.array(waypoints, dtype=float)
    S = len(W) - 1
    starts, axes, other = np.empty((S, 3, 3)), np.empty((S, 3)), np.zeros(S, dtype=bool)
    rotvecs = np.empty((S, 3))
    grids: list[np.ndarray] = []
    lifts: list[np.ndarray] = []
    for s in range(S):
        qs = W[s, columns]
        Rs = rotation_matrix(qs, convention)
        Re = rotation_matrix(W[s + 1, columns], convention)
        rv = np.asarray(Rotation.from_matrix(Rs.T @ Re).as_rotvec(), dtype=float)
        theta = float(np.linalg.norm(rv))
        axis = rv / theta if theta > 0 else np.array([0.0, 0.0, 1.0])
        abc = _distance(Rs, axis, convention)
        closest = _closest_approach(abc, theta)
        if closest < GIMBAL_TOL:
            raise TrajectoryError(
                f"segment {s + 1} turns through the gimbal lock of the {convention} angles (distance {closest:.2g}), "
                "where their rates are unbounded: add a waypoint to turn around it"
            )
        grid = [0.0]
        while grid[-1] < theta:
            if len(grid) > _MAX_GRID:
                raise TrajectoryError(f"segment {s + 1}: its turn runs too close to the gimbal lock to follow")
            grid.append(min(theta, grid[-1] + 0.25 * float(_gimbal_distance(abc, grid[-1]))))
        psi = np.array(grid)
        flip = _is_other(qs, convention)
        canon = angles_from_matrix(Rs @ _exp(psi[:, None] * axis), convention)
        if flip:
            canon = other_triple(canon, convention)
        lift = np.unwrap(canon, axis=0)
        lift += _TWO_PI * np.round((qs - lift[0]) / _TWO_PI)
        # the waypoint's own triple (or its other one) nearest the turn's end, so that a
        # waypoint the turn reaches keeps the angles given
        end = W[s + 1, columns]
        if _is_other(end, convention) != flip:
            end = other_triple(end, convention)
        W[s + 1, columns] = _nearest(end, lift[-1])
        starts[s], axes[s], other[s], rotvecs[s] = Rs, axis, flip, rv
        grids.append(psi)
        lifts.append(lift)
    return W, rotvecs, AxisTurns(starts, axes, other, tuple(grids), tuple(lifts))
