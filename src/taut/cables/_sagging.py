"""One sagging cable: end forces, unstrained length, shape and sag of the elastic catenary
(the kernels of :mod:`taut.cables._catenary`), vectorised over any number of cables.

References
----------
.. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3 (the elastic catenary).
   (docs/references.bib: irvine1981)
.. [2] K. Kozak, Q. Zhou, J. Wang, "Static analysis of cable-driven manipulators with
   non-negligible cable mass", IEEE Transactions on Robotics 22(3), 2006, §II.
   (docs/references.bib: kozak2006)
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array, as_count
from taut._results import Result
from taut.cables import _catenary as K
from taut.errors import ArgumentError, UnreachableLengthsError


@dataclass(frozen=True)
class Catenary(Result):
    """Elastic catenaries, one per entry of the broadcast arguments (shape ``S``).

    The cable runs from the platform end (``s = 0``) to the exit point (``s = L0``) in the
    vertical plane of its chord; the platform end is the origin, ``x`` horizontal towards the
    exit and ``z`` up (against gravity).

    Attributes
    ----------
    span, rise : ndarray, shape S
        Horizontal distance from the platform end to the exit and height of the exit above it [m].
    unstrained_lengths : ndarray, shape S
        ``L0`` [m].
    weight : ndarray, shape S
        Weight per unit unstrained length ``w`` [N/m].
    stiffness : ndarray, shape S
        Axial stiffness ``EA`` [N], ``inf`` for an inextensible cable.
    horizontal_forces : ndarray, shape S
        ``H`` [N]: the horizontal force on the platform, towards the exit, and on the exit,
        towards the platform.
    vertical_forces : ndarray, shape S
        ``V`` [N]: the vertical force on the platform, upwards.
    exit_vertical_forces : ndarray, shape S
        ``V + w L0`` [N]: the exit holds the cable up with it.
    platform_tensions, exit_tensions : ndarray, shape S
        ``√(H² + V²)`` and ``√(H² + (V + w L0)²)`` [N].
    sag : ndarray, shape S
        The largest distance of the cable from its chord [m].
    flexibility : ndarray, shape S + (2, 3)
        ``∂(span, rise)/∂(H, V, L0)``, Irvine's flexibility (its ``2 × 2`` block is symmetric).

    Examples
    --------
    >>> c = catenary_forces(10.0, 0.0, 10.05, 10.0)
    >>> round(float(c.horizontal_forces), 1), round(float(c.vertical_forces), 2), round(float(c.sag), 3)
    (288.9, -50.25, 0.434)
    """

    span: np.ndarray
    rise: np.ndarray
    unstrained_lengths: np.ndarray
    weight: np.ndarray
    stiffness: np.ndarray
    horizontal_forces: np.ndarray
    vertical_forces: np.ndarray
    exit_vertical_forces: np.ndarray
    platform_tensions: np.ndarray
    exit_tensions: np.ndarray
    sag: np.ndarray
    flexibility: np.ndarray


def _inputs(
    span: npt.ArrayLike,
    rise: npt.ArrayLike,
    third: tuple[npt.ArrayLike, str],
    weight: npt.ArrayLike,
    stiffness: npt.ArrayLike,
) -> list[np.ndarray]:
    """The five arguments as float arrays of one shape, checked: a span > 0, weights >= 0,
    stiffnesses > 0 (``inf`` allowed); ``third`` (a value and its name) finite."""
    named = [(span, "span"), (rise, "rise"), third, (weight, "weight"), (stiffness, "stiffness")]
    arrays = [as_array(v, what, finite=what != "stiffness", error=ArgumentError) for v, what in named]
    try:
        out = [np.array(a, dtype=float) for a in np.broadcast_arrays(*arrays)]
    except ValueError:
        shapes = ", ".join(f"{what} {np.shape(a)}" for a, (_, what) in zip(arrays, named))
        raise ArgumentError(f"the arrays do not broadcast together: {shapes}") from None
    span, _, _, w, ea = out
    if np.any(span <= 0):
        raise ArgumentError("span: a sagging cable's chord must have a positive horizontal span")
    if np.any(w < 0):
        raise ArgumentError(f"weight: expected weights per unit length >= 0, got {w[w < 0].flat[0]:g}")
    if np.any(np.isnan(ea)) or np.any(ea <= 0):
        raise ArgumentError("stiffness: expected axial stiffnesses EA > 0 (inf: inextensible)")
    return out


def _catenary(
    span: np.ndarray, rise: np.ndarray, L0: np.ndarray, w: np.ndarray, ea: np.ndarray, H: np.ndarray, V: np.ndarray
) -> Catenary:
    _, _, J = K.ends(H, V, L0, w, ea)
    flex = np.stack([np.stack(J[:3], axis=-1), np.stack(J[3:], axis=-1)], axis=-2)
    V1 = V + w * L0
    sag = K.largest_sag(span, rise, H, V, L0, w, ea)
    return Catenary(span, rise, L0, w, ea, H, V, V1, np.hypot(H, V), np.hypot(H, V1), sag, flex)


def catenary_forces(
    span: npt.ArrayLike,
    rise: npt.ArrayLike,
    unstrained_lengths: npt.ArrayLike,
    weight: npt.ArrayLike,
    stiffness: npt.ArrayLike = np.inf,
) -> Catenary:
    """The end forces of elastic catenaries of given unstrained lengths between given points.

    Solves Irvine's two equations of the elastic catenary for ``(H, V)`` by Newton's method
    with their analytic Jacobian (module :mod:`taut.cables._catenary`).

    Parameters
    ----------
    span : array_like
        Horizontal distance from the platform end to the exit [m], ``> 0``.
    rise : array_like
        Height of the exit above the platform end [m] (negative below it).
    unstrained_lengths : array_like
        ``L0`` [m], ``> 0``.
    weight : array_like
        Weight per unit unstrained length [N/m], ``≥ 0``; ``0`` needs a finite ``stiffness``
        (a weightless inextensible cable's tension is not determined by its ends).
    stiffness : array_like, default inf
        Axial stiffness ``EA`` [N], ``> 0``; ``inf`` for an inextensible cable.
        The arguments broadcast together.

    Returns
    -------
    Catenary

    Raises
    ------
    ArgumentError
        Arguments that are not finite numbers or do not broadcast, a span ``≤ 0``, a negative
        weight, a stiffness ``≤ 0``, a weightless inextensible cable.
    UnreachableLengthsError
        An inextensible cable shorter than (or as long as) its chord.

    References
    ----------
    .. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3.
       (docs/references.bib: irvine1981)

    Examples
    --------
    A 10.05 m cable of 10 N/m over a 10 m horizontal span: each end carries half its weight.

    >>> c = catenary_forces(10.0, 0.0, 10.05, 10.0)
    >>> float(c.exit_vertical_forces - c.vertical_forces)  # w L0
    100.5
    >>> round(float(c.platform_tensions), 2) == round(float(c.exit_tensions), 2)
    True
    """
    span, rise, L0, w, ea = _inputs(span, rise, (unstrained_lengths, "unstrained_lengths"), weight, stiffness)
    if np.any(L0 <= 0):
        raise ArgumentError("unstrained_lengths: expected lengths > 0")
    if np.any((w == 0) & np.isinf(ea)):
        raise ArgumentError("a weightless inextensible cable: its tension is not determined by its ends")
    chord = np.hypot(span, rise)
    short = np.isinf(ea) & (L0 <= chord)
    if short.any():
        k = np.argwhere(short)[0] if short.ndim else ()
        raise UnreachableLengthsError(
            f"an inextensible cable of unstrained length {float(L0[tuple(k)]):g} m is not longer than its chord "
            f"of {float(chord[tuple(k)]):g} m"
        )
    H, V, ok = K.solve_forward(span, rise, L0, w, ea)
    if not ok.all():
        raise ArgumentError("no elastic catenary found for these ends and lengths (Newton did not converge)")
    return _catenary(span, rise, L0, w, ea, H, V)


def catenary_lengths(
    span: npt.ArrayLike,
    rise: npt.ArrayLike,
    horizontal_forces: npt.ArrayLike,
    weight: npt.ArrayLike,
    stiffness: npt.ArrayLike = np.inf,
) -> Catenary:
    """The unstrained lengths (and vertical forces) of elastic catenaries between given points
    with a given horizontal force: the inverse of :func:`catenary_forces`.

    For an inextensible cable the catenary ``z = a cosh(x/a)``, ``a = H/w``, through both
    ends gives them in closed form; an elastic cable's follow from it by Newton's method.

    Parameters
    ----------
    span : array_like
        Horizontal distance from the platform end to the exit [m], ``> 0``.
    rise : array_like
        Height of the exit above the platform end [m].
    horizontal_forces : array_like
        ``H`` [N], ``> 0``.
    weight : array_like
        Weight per unit unstrained length [N/m], ``≥ 0``.
    stiffness : array_like, default inf
        Axial stiffness ``EA`` [N], ``> 0`` or ``inf``.

    Returns
    -------
    Catenary

    Raises
    ------
    ArgumentError
        Arguments that are not finite numbers or do not broadcast, a span or force ``≤ 0``, a
        negative weight, a stiffness ``≤ 0``, a cable so slack that its catenary overflows.

    References
    ----------
    .. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.2–1.3.
       (docs/references.bib: irvine1981)

    Examples
    --------
    >>> c = catenary_lengths(10.0, 0.0, 288.8914, 10.0)
    >>> round(float(c.unstrained_lengths), 3)
    10.05
    """
    span, rise, H, w, ea = _inputs(span, rise, (horizontal_forces, "horizontal_forces"), weight, stiffness)
    if np.any(H <= 0):
        raise ArgumentError("horizontal_forces: expected forces > 0")
    L0, V, ok = K.solve_inverse(span, rise, H, w, ea)
    if not ok.all():
        raise ArgumentError("no elastic catenary found for these ends and forces (the cable is too slack)")
    return _catenary(span, rise, L0, w, ea, H, V)


def catenary_tensions(
    span: npt.ArrayLike,
    rise: npt.ArrayLike,
    platform_tensions: npt.ArrayLike,
    weight: npt.ArrayLike,
    stiffness: npt.ArrayLike = np.inf,
    *,
    start: Catenary | None = None,
) -> Catenary:
    """The elastic catenaries between given points whose tension at the platform end is given:
    their unstrained lengths and the direction of their pull on the platform.

    Newton's method on the angle of the end force above the horizontal and the unstrained
    length, with the analytic Jacobian of Irvine's two equations (module
    :mod:`taut.cables._catenary`, compiled for one cable in :mod:`taut.cables._kernels`), from ``start`` (a catenary of the same shape near the
    answer: the last one of a motion) or from the catenary whose horizontal force is the
    tension's share along the chord.

    Parameters
    ----------
    span : array_like
        Horizontal distance from the platform end to the exit [m], ``> 0``.
    rise : array_like
        Height of the exit above the platform end [m].
    platform_tensions : array_like
        ``√(H² + V²)`` [N], ``> 0``.
    weight : array_like
        Weight per unit unstrained length [N/m], ``≥ 0``.
    stiffness : array_like, default inf
        Axial stiffness ``EA`` [N], ``> 0`` or ``inf``.  The arguments broadcast together.
    start : Catenary, optional
        Catenaries of the broadcast shape to start from.

    Returns
    -------
    Catenary

    Raises
    ------
    ArgumentError
        Arguments that are not finite numbers or do not broadcast, a span or tension ``≤ 0``,
        a negative weight, a stiffness ``≤ 0``, a ``start`` of another shape, or a tension too
        low for a catenary through the ends (Newton does not converge).

    References
    ----------
    .. [1] H. M. Irvine, "Cable Structures", MIT Press, 1981, Ch. 1, §1.3.
       (docs/references.bib: irvine1981)

    Examples
    --------
    The 10.05 m cable of :func:`catenary_forces` pulled with its own platform-end tension:

    >>> c = catenary_forces(10.0, 0.0, 10.05, 10.0)
    >>> t = catenary_tensions(10.0, 0.0, c.platform_tensions, 10.0)
    >>> round(float(t.unstrained_lengths), 6), round(float(t.vertical_forces), 2)
    (10.05, -50.25)
    """
    from taut.cables._kernels import tension_catenaries

    span, rise, T0, w, ea = _inputs(span, rise, (platform_tensions, "platform_tensions"), weight, stiffness)
    if np.any(T0 <= 0):
        raise ArgumentError("platform_tensions: expected tensions > 0")
    if start is not None and (not isinstance(start, Catenary) or start.span.shape != span.shape):
        raise ArgumentError(f"start: expected a Catenary of shape {span.shape}")
    size = span.size
    if start is None:
        phi, lengths = np.zeros(size), np.zeros(size)
    else:
        phi = np.arctan2(start.vertical_forces, start.horizontal_forces).ravel()
        lengths = np.array(start.unstrained_lengths, dtype=float).ravel()
    forces, converged = np.empty((2, size)), np.empty(size, dtype=bool)
    flat = np.ascontiguousarray(np.stack([span, rise, T0, w, ea]).reshape(5, size))
    tension_catenaries(
        flat[0], flat[1], flat[2], flat[3], flat[4], phi, lengths, start is None, forces[0], forces[1], converged
    )
    H, V = forces.reshape((2, *span.shape))
    L0, ok = lengths.reshape(span.shape), converged.reshape(span.shape)
    if not ok.all():
        k = np.argwhere(~ok)[0] if ok.ndim else ()
        raise ArgumentError(
            f"no elastic catenary with a platform-end tension of {float(T0[tuple(k)]):g} N through a span of "
            f"{float(span[tuple(k)]):g} m and a rise of {float(rise[tuple(k)]):g} m (too slack)"
        )
    return _catenary(span, rise, L0, w, ea, H, V)


def catenary_shape(catenary: Catenary, samples: int = 50) -> np.ndarray:
    """Points of the cables, evenly spaced in unstrained length from the platform end to the exit.

    Parameters
    ----------
    catenary : Catenary
        Cables of shape ``S``.
    samples : int, default 50
        Points per cable, ``≥ 2``.

    Returns
    -------
    ndarray, shape S + (samples, 2)
        ``(x, z)`` in the cable's plane [m], the platform end at the origin.

    Raises
    ------
    TautError
        ``samples`` not a whole number ``≥ 2``, ``catenary`` not a :class:`Catenary`.

    Examples
    --------
    >>> c = catenary_forces(10.0, 0.0, 10.05, 10.0)
    >>> (catenary_shape(c, 3) + 0.0).round(3)
    array([[ 0.   ,  0.   ],
           [ 5.   , -0.434],
           [10.   ,  0.   ]])
    """
    if not isinstance(catenary, Catenary):
        raise ArgumentError(f"catenary: expected a Catenary, got {type(catenary).__name__}")
    n = as_count(samples, "samples", minimum=2)
    s = catenary.unstrained_lengths[..., None] * np.linspace(0.0, 1.0, n)
    c = catenary
    x, z = K.points(
        c.horizontal_forces[..., None], c.vertical_forces[..., None], c.weight[..., None], c.stiffness[..., None], s
    )
    return np.stack([x, z], axis=-1)
