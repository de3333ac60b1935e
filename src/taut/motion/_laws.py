"""Time laws of one segment of a trajectory, as polynomial pieces in the segment's local time.

A segment from ``q₀`` to ``q₁`` lasting ``T`` is one or more pieces ``q(τ) = Σ_j c_j τ^j``
(``j ≤ 5``, ``τ`` from the start of the piece), all coordinates at once:

- ``linear``: ``q₀ + (q₁ − q₀) τ/T`` (CASPR's ``linear_spline_trajectory``): constant
  velocity, the velocity jumps at the waypoints (the acceleration there is an impulse that no
  sample shows);
- ``cubic``: the cubic with the given positions and velocities at both ends;
- ``quintic``: the quintic with the given positions, velocities and accelerations at both ends;
- ``trapezoidal`` (linear segment with parabolic blends, CASPR's ``parabolic_blend_trajectory``):
  constant acceleration ``a = Δ / (t_b (T − t_b))`` for a blend time ``t_b``, cruise at
  ``v = a t_b``, constant deceleration; it starts and ends at rest.  ``t_b = T/2`` is the
  triangular profile.

With zero end velocities (and accelerations) every law is ``q₀ + s(τ)(q₁ − q₀)`` with one
scalar ``s`` rising from 0 to 1: the time law is applied to all coordinates together and the
segment is a straight line in pose coordinates.  :func:`minimum_duration` gives the shortest
``T`` of such a segment within velocity and acceleration limits of ``s``.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §4.2.1 (cubic and quintic polynomials, trapezoidal velocity
   profile), §4.2.2 (linear segments with parabolic blends). (docs/references.bib: siciliano2009)
.. [2] D. Lau, J. Eden, Y. Tan, D. Oetomo, "CASPR: A comprehensive cable-robot analysis and
   simulation platform for the research of cable-driven parallel robots", IEEE/RSJ
   International Conference on Intelligent Robots and Systems (IROS), 2016.
   (docs/references.bib: lau2016)
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "DEGREE",
    "LAWS",
    "cubic_piece",
    "linear_piece",
    "minimum_duration",
    "quintic_piece",
    "trapezoidal_pieces",
]

#: The time laws, by name.
LAWS = ("linear", "cubic", "quintic", "trapezoidal")

#: Highest degree of a piece: every piece has ``DEGREE + 1`` coefficients.
DEGREE = 5


def _padded(*coefficients: np.ndarray) -> np.ndarray:
    c = np.zeros((DEGREE + 1,) + np.shape(coefficients[0]))
    for j, value in enumerate(coefficients):
        c[j] = value
    return c


def linear_piece(q0: np.ndarray, q1: np.ndarray, T: float) -> np.ndarray:
    """Coefficients ``(6, dof)`` of the constant-velocity move from ``q0`` to ``q1`` in ``T``."""
    return _padded(q0, (q1 - q0) / T)


def cubic_piece(q0: np.ndarray, v0: np.ndarray, q1: np.ndarray, v1: np.ndarray, T: float) -> np.ndarray:
    """Coefficients ``(6, dof)`` of the cubic with position and velocity ``q0, v0`` at
    ``τ = 0`` and ``q1, v1`` at ``τ = T`` (Siciliano et al. 2009, §4.2.1)."""
    d = q1 - q0
    return _padded(q0, v0, (3 * d - (2 * v0 + v1) * T) / T**2, (-2 * d + (v0 + v1) * T) / T**3)


def quintic_piece(
    q0: np.ndarray, v0: np.ndarray, a0: np.ndarray, q1: np.ndarray, v1: np.ndarray, a1: np.ndarray, T: float
) -> np.ndarray:
    """Coefficients ``(6, dof)`` of the quintic with position, velocity and acceleration
    ``q0, v0, a0`` at ``τ = 0`` and ``q1, v1, a1`` at ``τ = T`` (Siciliano et al. 2009, §4.2.1)."""
    d = q1 - q0
    return _padded(
        q0,
        v0,
        a0 / 2,
        (20 * d - (8 * v1 + 12 * v0) * T - (3 * a0 - a1) * T**2) / (2 * T**3),
        (-30 * d + (14 * v1 + 16 * v0) * T + (3 * a0 - 2 * a1) * T**2) / (2 * T**4),
        (12 * d - 6 * (v1 + v0) * T + (a1 - a0) * T**2) / (2 * T**5),
    )


def trapezoidal_pieces(q0: np.ndarray, q1: np.ndarray, T: float, blend: float) -> list[tuple[float, np.ndarray]]:
    """``(start, coefficients (6, dof))`` of the pieces of the trapezoidal velocity profile
    from rest at ``q0`` to rest at ``q1`` in ``T``, accelerating for the blend time
    ``t_b = blend · T`` (``0 < blend ≤ 1/2``; ``1/2`` leaves no cruise piece); ``start`` is
    the piece's start in the segment's time.

    The acceleration ``a = Δ / (t_b (T − t_b))`` makes the cruise line through the
    midpoint (Siciliano et al. 2009, §4.2.1)."""
    tb = blend * T
    a = (q1 - q0) / (tb * (T - tb))
    v = a * tb
    pieces = [(0.0, _padded(q0, np.zeros_like(q0), a / 2))]
    if T - 2 * tb > 0:
        pieces.append((tb, _padded(q0 + a * tb**2 / 2, v)))
    pieces.append((T - tb, _padded(q1 - v * tb + a * tb**2 / 2, v, -a / 2)))
    return pieces


#: Peak ``ṡ T`` and ``s̈ T²`` of the rest-to-rest polynomial laws (``s`` from 0 to 1 in ``T``).
_PEAKS = {"cubic": (1.5, 6.0), "quintic": (15.0 / 8.0, 10.0 / math.sqrt(3.0))}


def minimum_duration(law: str, velocity: float, acceleration: float) -> tuple[float, float]:
    """``(T, blend)``: the shortest duration of a rest-to-rest segment ``s: 0 → 1`` whose
    ``|ṡ| ≤ velocity`` and ``|s̈| ≤ acceleration`` (``acceleration`` is not used by ``linear``),
    and the blend fraction of ``trapezoidal`` (``t_b / T``; 0 for the other laws).

    The peaks of the polynomial laws are ``ṡ = 1.5/T, s̈ = 6/T²`` (cubic) and
    ``ṡ = 15/(8T), s̈ = 10/(√3 T²)`` (quintic); the trapezoidal law cruises at ``velocity``
    after ``t_b = velocity / acceleration``, or is triangular with ``t_b = √(1/acceleration)``
    when it cannot reach it (Siciliano et al. 2009, §4.2.1)."""
    if law == "linear":
        return 1.0 / velocity, 0.0
    if law == "trapezoidal":
        if velocity**2 / acceleration < 1.0:
            tb = velocity / acceleration
            T = 1.0 / velocity + tb
        else:
            tb = math.sqrt(1.0 / acceleration)
            T = 2.0 * tb
        return T, tb / T
    vpeak, apeak = _PEAKS[law]
    return max(vpeak / velocity, math.sqrt(apeak / acceleration)), 0.0
