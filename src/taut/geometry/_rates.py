"""Angular velocity and acceleration of a platform from the rates of its orientation angles.

For the three-angle conventions of :mod:`taut.geometry._rotation`, ``R = A₁(t₁) A₂(t₂) A₃(t₃)``
is a product of rotations about coordinate axes ``e_k`` whose angles ``t = T q`` are linear in
the pose angles ``q``.  Differentiating the product gives the angular velocity in the fixed
frame, ``ω = Σ_k (A₁ ⋯ A_{k-1}) e_k ṫ_k = E(q) q̇``, with ``E = [u₁ u₂ u₃] T`` (the rate
matrix), and the angular acceleration ``α = E q̈ + Ė q̇`` with
``u̇_k = (Σ_{m<k} u_m ṫ_m) × u_k``: the k-th axis is carried by the rotations before it.
Angle differences are never used, so the rates are right in every convention and at any
angle, and ``E`` is singular exactly at the convention's gimbal lock.  Angles, rates and
accelerations are arrays ``(..., 3)`` whose batch axes broadcast; anything else raises
:class:`~taut.errors.ArgumentError`.

References
----------
.. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning and
   Control", Springer, 2009, §3.6 (analytical Jacobian, Eq. 3.64).
   (docs/references.bib: siciliano2009)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut.errors import ArgumentError
from taut.geometry._rotation import check_convention, rotation_matrix

#: Per convention: the axis of each factor of ``R`` and ``T`` with ``t = T q``.
_FACTORS: dict[str, tuple[tuple[int, int, int], np.ndarray]] = {
    "xyz-fixed": ((2, 1, 0), np.array([[0.0, 0, 1], [0, 1, 0], [1, 0, 0]])),
    "xyz-moving": ((0, 1, 2), np.eye(3)),
    "tilt-torsion": ((2, 1, 2), np.array([[1.0, 0, 0], [0, 1, 0], [-1, 0, 1]])),
}


def _triples(values: npt.ArrayLike, what: str) -> np.ndarray:
    """``values`` as a float array ``(..., 3)``, else an ``ArgumentError`` naming ``what`` they are."""
    try:
        arr = np.asarray(values, dtype=float)
    except (TypeError, ValueError):
        raise ArgumentError(f"{what} must be numbers, got {values!r}") from None
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ArgumentError(f"{what} are three numbers (..., 3), got shape {arr.shape}")
    return arr


def _times(M: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``M v`` over the batch axes of matrices ``(..., 3, 3)`` and vectors ``(..., 3)``."""
    try:
        return np.einsum("...ij,...j->...i", M, v)
    except ValueError:
        raise ArgumentError(
            f"angles and rates of batch shapes {M.shape[:-2]} and {v.shape[:-1]} do not broadcast"
        ) from None


def _factor_axes(q: np.ndarray, convention: str) -> tuple[np.ndarray, np.ndarray]:
    """The carried axes ``u`` ``(..., 3, 3)`` (``u[..., :, k] = u_k``) and ``T``."""
    check_convention(convention)
    axes, T = _FACTORS[convention]
    t = q @ T.T
    eye = np.eye(3)
    u = np.empty(q.shape[:-1] + (3, 3))
    P = np.broadcast_to(eye, q.shape[:-1] + (3, 3))
    for k, ax in enumerate(axes):
        u[..., :, k] = P[..., :, ax]
        P = P @ rotation_matrix(_single_axis_angles(ax, t[..., k]), "xyz-moving")
    return u, T


def _single_axis_angles(axis: int, angle: np.ndarray) -> np.ndarray:
    """``xyz-moving`` angles of a rotation by ``angle`` about coordinate axis ``axis``."""
    a = np.zeros(angle.shape + (3,))
    a[..., axis] = angle
    return a


def rate_matrix(angles: npt.ArrayLike, convention: str = "xyz-fixed") -> np.ndarray:
    """``E(q)`` ``(..., 3, 3)`` with ``ω = E(q) q̇``: the angular velocity in the fixed frame
    from the rates of the angles ``q`` ``(..., 3)`` in ``convention``.

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §3.6, Eq. 3.64. (docs/references.bib: siciliano2009)
    """
    q = _triples(angles, "orientation angles")
    u, T = _factor_axes(q, convention)
    return u @ T


def rate_matrix_derivative(angles: npt.ArrayLike, rates: npt.ArrayLike, convention: str = "xyz-fixed") -> np.ndarray:
    """``Ė(q, q̇)`` ``(..., 3, 3)``, so that the angular acceleration is ``α = E q̈ + Ė q̇``.

    References
    ----------
    .. [1] B. Siciliano, L. Sciavicco, L. Villani, G. Oriolo, "Robotics: Modelling, Planning
       and Control", Springer, 2009, §3.6, Eq. 3.64. (docs/references.bib: siciliano2009)
    """
    q = _triples(angles, "orientation angles")
    try:
        qd = np.broadcast_to(_triples(rates, "angle rates"), q.shape)
    except ValueError:
        raise ArgumentError(f"angle rates of shape {np.shape(rates)} for angles of shape {q.shape}") from None
    u, T = _factor_axes(q, convention)
    td = qd @ T.T
    ud = np.zeros_like(u)
    partial = np.zeros(q.shape)
    for k in range(3):
        ud[..., :, k] = np.cross(partial, u[..., :, k])
        partial = partial + u[..., :, k] * td[..., k, None]
    return ud @ T


def angular_velocity(angles: npt.ArrayLike, rates: npt.ArrayLike, convention: str = "xyz-fixed") -> np.ndarray:
    """``ω = E(q) q̇`` ``(..., 3)`` in the fixed frame."""
    E = rate_matrix(angles, convention)
    return _times(E, _triples(rates, "angle rates"))


def angular_acceleration(
    angles: npt.ArrayLike, rates: npt.ArrayLike, accelerations: npt.ArrayLike, convention: str = "xyz-fixed"
) -> np.ndarray:
    """``α = E(q) q̈ + Ė(q, q̇) q̇`` ``(..., 3)`` in the fixed frame."""
    qd = _triples(rates, "angle rates")
    E = rate_matrix(angles, convention)
    Ed = rate_matrix_derivative(angles, qd, convention)
    return _times(E, _triples(accelerations, "angle accelerations")) + _times(Ed, qd)
