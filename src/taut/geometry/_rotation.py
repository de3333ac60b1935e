"""Rotation matrices for the orientation conventions of ``docs/architecture.md`` §2.3.

* ``xyz-fixed``: ``R = Rz(c) Ry(b) Rx(a)`` — rotations about the fixed x, y, z axes
  (the convention of Tables 4.3–4.6 of Berti 2015).
* ``xyz-moving``: ``R = Rx(a) Ry(b) Rz(c)`` — Eq. (3.1.1) of Lieskovský (2020).
* ``tilt-torsion``: ``R = Rz(φ) Ry(θ) Rz(σ − φ)`` — Eq. (1) of Bohigas et al. (2013);
  the angles are given in the order ``(φ, θ, σ)``.

All functions work over arrays: angles of shape ``(..., 3)`` give matrices ``(..., 3, 3)``.

References
----------
.. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
   interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and Università
   di Bologna, 2015, Tables 4.3–4.6. (docs/references.bib: berti2015)
.. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
   Bachelor thesis, Czech Technical University in Prague, 2020, Eq. 3.1.1.
   (docs/references.bib: lieskovsky2020)
.. [3] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, Eq. 1. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut.errors import ArgumentError

#: The orientation conventions of three angles (docs/architecture.md §2.3), by name.
CONVENTIONS = ("xyz-fixed", "xyz-moving", "tilt-torsion")


def check_convention(convention: str) -> None:
    """Raise :class:`~taut.errors.ArgumentError` unless ``convention`` is one of :data:`CONVENTIONS`."""
    if convention not in CONVENTIONS:
        raise ArgumentError(f"unknown orientation convention {convention!r}; expected one of {', '.join(CONVENTIONS)}")


def _numbers(values: npt.ArrayLike, what: str) -> np.ndarray:
    return as_array(values, what, finite=False, error=ArgumentError)


def planar_rotation(theta: npt.ArrayLike) -> np.ndarray:
    """Planar rotation matrices ``R(θ)``.

    Parameters
    ----------
    theta : array_like, shape (...)
        Angles [rad], counter-clockwise.

    Returns
    -------
    ndarray, shape (..., 2, 2)

    Examples
    --------
    >>> np.round(planar_rotation(np.pi / 2) @ [1.0, 0.0], 12)
    array([0., 1.])
    """
    theta = _numbers(theta, "planar rotation angles")
    c, s = np.cos(theta), np.sin(theta)
    return np.stack([np.stack([c, -s], -1), np.stack([s, c], -1)], -2)


def _axis(k: int, t: np.ndarray) -> np.ndarray:
    """Rotations ``(..., 3, 3)`` by the angles ``t`` about axis ``k`` (0: x, 1: y, 2: z)."""
    c, s = np.cos(t), np.sin(t)
    M = np.zeros(t.shape + (3, 3))
    i, j = (k + 1) % 3, (k + 2) % 3
    M[..., k, k] = 1.0
    M[..., i, i], M[..., i, j], M[..., j, i], M[..., j, j] = c, -s, s, c
    return M


def rotation_matrix(angles: npt.ArrayLike, convention: str = "xyz-fixed") -> np.ndarray:
    """Rotation matrices from three angles in an orientation convention
    (``docs/architecture.md`` §2.3).

    ``xyz-fixed``: ``R = Rz(c) Ry(b) Rx(a)``, rotations about the fixed axes (Berti 2015,
    Tables 4.3–4.6); ``xyz-moving``: ``R = Rx(a) Ry(b) Rz(c)`` (Lieskovský 2020, Eq. 3.1.1);
    ``tilt-torsion``: ``R = Rz(φ) Ry(θ) Rz(σ − φ)`` with angles ``(φ, θ, σ)`` (Bohigas et al.
    2013, Eq. 1).

    Parameters
    ----------
    angles : array_like, shape (..., 3)
        Angles [rad].
    convention : str, default "xyz-fixed"
        One of :data:`CONVENTIONS`: it says what the angles mean.

    Returns
    -------
    ndarray, shape (..., 3, 3)

    Raises
    ------
    TautError
        For an unknown convention.

    Raises :class:`~taut.errors.ArgumentError` for an unknown convention or angles that are
    not numbers ``(..., 3)``.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, Tables 4.3–4.6. (docs/references.bib: berti2015)
    .. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, Eq. 3.1.1.
       (docs/references.bib: lieskovsky2020)
    .. [3] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, Eq. 1.
       (docs/references.bib: bohigas2013)

    Examples
    --------
    A quarter turn about ``z`` takes ``x`` to ``y``:

    >>> np.round(rotation_matrix([0.0, 0.0, np.pi / 2]) @ [1.0, 0.0, 0.0], 12)
    array([0., 1., 0.])
    """
    check_convention(convention)
    arr = _numbers(angles, "rotation angles")
    if arr.ndim == 0 or arr.shape[-1] != 3:
        raise ArgumentError(f"a rotation takes three angles (..., 3), got shape {arr.shape}")
    a, b, c = np.moveaxis(arr, -1, 0)
    if convention == "xyz-fixed":
        return _axis(2, c) @ _axis(1, b) @ _axis(0, a)
    if convention == "xyz-moving":
        return _axis(0, a) @ _axis(1, b) @ _axis(2, c)
    return _axis(2, a) @ _axis(1, b) @ _axis(2, c - a)


def angles_from_matrix(R: npt.ArrayLike, convention: str = "xyz-fixed") -> np.ndarray:
    """The angles of rotation matrices in a convention: the inverse of :func:`rotation_matrix`,
    with the middle angle in ``[−π/2, π/2]`` (``[0, π]`` for ``tilt-torsion``).

    Parameters
    ----------
    R : array_like, shape (..., 3, 3)
        Rotation matrices.
    convention : str, default "xyz-fixed"
        One of :data:`CONVENTIONS`.

    Returns
    -------
    ndarray, shape (..., 3)
        Angles [rad].

    Raises
    ------
    TautError
        For an unknown convention.

    References
    ----------
    .. [1] A. Berti, "Kinematics and statics of cable-driven parallel robots by
       interval-analysis-based methods", PhD thesis, Université Nice Sophia Antipolis and
       Università di Bologna, 2015, Tables 4.3–4.6. (docs/references.bib: berti2015)
    .. [2] J. Lieskovský, "Cable-driven Parallel Manipulator With Adjustable Platform Geometry",
       Bachelor thesis, Czech Technical University in Prague, 2020, Eq. 3.1.1.
       (docs/references.bib: lieskovsky2020)
    .. [3] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, Eq. 1.
       (docs/references.bib: bohigas2013)

    Examples
    --------
    >>> angles_from_matrix(rotation_matrix([0.1, 0.2, 0.3], "xyz-moving"), "xyz-moving")
    array([0.1, 0.2, 0.3])
    """
    check_convention(convention)
    R = _numbers(R, "rotation matrices")
    if R.shape[-2:] != (3, 3):
        raise ArgumentError(f"rotation matrices are (..., 3, 3), got shape {R.shape}")
    flat = np.ascontiguousarray(R.reshape(-1, 3, 3))
    from taut.geometry._rotation_kernels import matrix_angles

    return matrix_angles(flat, CONVENTIONS.index(convention)).reshape(R.shape[:-2] + (3,))
