"""Cable state of a collidable cable and the path it stands for (§4.1 of Rushton 2022).

A cable runs from its winch (the exit pulley, a circle ``(a, r_0)`` turned in direction
``d_0``, or a point) over a sequence of circular objects to the platform anchor ``b``.
Its *state* is the minimal information that rebuilds the path (§4.1.1, Alg. 4.1): the
objects it touches in order and the wrap direction about each (``+1`` counter-clockwise,
``−1`` clockwise, as in Appendix A).  Every straight segment is the wrap-direction
consistent common tangent of its two end objects (:func:`taut.geometry.directed_tangent`),
so the entry and exit angles follow from the objects; the last one, the *active segment*,
ends at ``b``.

The length is Eq. (4.9), ``l = Σ_j (ν_j + l_j)``: straight segments ``l_j = ‖b_j − a_j‖``
(Eq. 4.11) plus arcs ``ν_j = φ_j r_j`` (Eq. 4.10) with the wrap angle ``φ_j`` about each
object.  Wrap angles about objects are taken in ``[−π/2, 3π/2)`` (a taut cable has
``φ ≥ 0``; one that wrapped more than 3π/2 would cross itself).  On the winch pulley the
arc is counted from a reference angle (the exit angle at which the winch was calibrated,
§6.1.2) with ``φ_0 ∈ [−π, π)``, so that lengths are continuous over the workspace.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §4.1 (§4.1.1, Alg. 4.1), Appendix A. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from taut._checks import as_array
from taut._results import Result
from taut.errors import TautError
from taut.geometry import directed_tangent

#: Lower end of the range of wrap angles about an object (radians).
WRAP_LOW = -0.5 * math.pi
#: Lower end of the range of the winch-pulley arc angle (radians).
WINCH_LOW = -math.pi


def contact_angle(u: npt.ArrayLike, d: npt.ArrayLike) -> np.ndarray:
    """Angle about an object's centre of the point where a cable with direction ``u``
    touches it with wrap direction ``d`` (the point is ``c − d r n``, ``n`` the left normal
    of ``u``; Eqs. 4.1–4.2 turn it back into a point)."""
    u = np.asarray(u, float)
    d = np.asarray(d, float)
    return np.arctan2(-d * u[..., 0], d * u[..., 1])


def wrap_angle(
    theta_in: npt.ArrayLike, theta_out: npt.ArrayLike, d: npt.ArrayLike, low: float = WRAP_LOW
) -> np.ndarray:
    """Wrap angle ``φ = d (θ_out − θ_in)`` brought into ``[low, low + 2π)``."""
    phi = np.asarray(d, float) * (np.asarray(theta_out, float) - np.asarray(theta_in, float))
    return np.mod(phi - low, 2 * math.pi) + low


@dataclass(frozen=True)
class CableState(Result):
    """The state of one cable (§4.1.1): the objects it wraps, in order from the winch, with
    their wrap directions, and the winch pulley's reference angle.

    Attributes
    ----------
    contacts : tuple of (int, int)
        ``(object index, wrap direction)`` (0-based objects; +1 counter-clockwise, −1
        clockwise).
    reference_angle : float
        Winch-pulley angle [rad] from which its arc is counted.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.1.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.wrapping import CableState
    >>> CableState(((0, 1), (2, -1))).objects
    (0, 2)
    """

    contacts: tuple[tuple[int, int], ...]  #: ``(object index, wrap direction ±1)``
    reference_angle: float = 0.0  #: winch-pulley angle where its arc is counted from

    @property
    def objects(self) -> tuple[int, ...]:
        """The wrapped objects, in order from the winch."""
        return tuple(k for k, _ in self.contacts)


@dataclass(frozen=True)
class CablePath(Result):
    """A cable's path (:func:`rebuild_path`).

    Attributes
    ----------
    segments : ndarray, shape (m, 2, 2)
        Straight pieces from the winch to the platform end (the last one is the active
        segment).
    arcs : ndarray, shape (m, 6)
        Per object touched, winch pulley first: ``(centre x, centre y, radius, θ_in, wrap
        angle φ, direction)``.
    length : float
        The cable length [m] (Eq. 4.9).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.1.1, Eqs. 4.9–4.11. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.wrapping import CableState, rebuild_path
    >>> path = rebuild_path([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]], 1, CableState(((0, 1),)), [0.0, 2.0])
    >>> path.segments.shape, round(path.length, 4)
    ((2, 2, 2), 2.0401)
    """

    segments: np.ndarray
    arcs: np.ndarray
    length: float

    def arc_points(self, k: int, n: int = 16) -> np.ndarray:
        """``n`` points along the ``k``-th arc (for drawing)."""
        cx, cy, r, t0, phi, d = self.arcs[k]
        t = t0 + d * np.linspace(0.0, phi, n)
        return np.column_stack([cx + r * np.cos(t), cy + r * np.sin(t)])


def rebuild_path(circles: npt.ArrayLike, winch_direction: int, state: CableState, b: npt.ArrayLike) -> CablePath:
    """The path of a cable in a given state (§4.1.1, Alg. 4.1).

    Parameters
    ----------
    circles : array_like, shape (K + 1, 3)
        ``(x, y, r)`` [m] of the objects, the winch pulley last.
    winch_direction : int
        +1 (counter-clockwise) or −1.
    state : CableState
    b : array_like, shape (2,)
        The platform end [m].

    Returns
    -------
    CablePath

    Raises
    ------
    TautError
        A tangent does not exist (``b`` inside an object), or a state that wraps objects
        not among ``circles``.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.1.1, Alg. 4.1. (docs/references.bib: rushton2022)

    Examples
    --------
    A cable from the origin over the left side of a disc (counter-clockwise) to ``(0, 2)``:

    >>> from taut.wrapping import CableState, rebuild_path
    >>> path = rebuild_path([[0.0, 1.0, 0.2], [0.0, 0.0, 0.0]], 1, CableState(((0, 1),)), [0.0, 2.0])
    >>> round(path.length, 4), path.arcs.shape
    (2.0401, (2, 6))
    """
    circles = as_array(circles, "circles", shape=(None, 3))
    K = len(circles) - 1
    if any(not 0 <= k < K for k in state.objects):
        raise TautError(f"the state {list(state.contacts)} wraps objects that are not among the {K} circles")
    chain = [(K, winch_direction)] + [(int(k), int(d)) for k, d in state.contacts]
    ends = [(as_array(b, "the platform end b", shape=(2,)), 0.0, 1)]
    segs, arcs = [], []
    theta_in = state.reference_angle
    length = 0.0
    for j, (k, d) in enumerate(chain):
        nk, nd = chain[j + 1] if j + 1 < len(chain) else (None, 1)
        c1, r1 = circles[k, :2], circles[k, 2]
        if nk is None:
            c2, r2 = ends[0][0], 0.0
        else:
            c2, r2 = circles[nk, :2], circles[nk, 2]
        x1, x2, u, L, ok = directed_tangent(c1, r1, d, c2, r2, nd)
        if not ok:
            raise TautError(
                f"no tangent from object {k + 1} to {'the platform anchor' if nk is None else f'object {nk + 1}'}"
            )
        theta_out = float(contact_angle(u, d))
        phi = float(wrap_angle(theta_in, theta_out, d, WINCH_LOW if j == 0 else WRAP_LOW))
        arcs.append((c1[0], c1[1], r1, theta_in, phi, d))
        segs.append((x1, x2))
        length += phi * r1 + float(L)
        theta_in = float(contact_angle(u, nd))
    return CablePath(np.array(segs, float), np.array(arcs, float), float(length))


def contacts_text(contacts: Iterable[tuple[int, int]]) -> str:
    """A cable's contacts as users read them: 1-based object numbers with the wrap direction.

    Parameters
    ----------
    contacts : iterable of (int, int)
        ``(object index, direction ±1)`` (0-based objects).

    Returns
    -------
    str
        Empty for a straight cable.

    Raises
    ------
    TautError
        Contacts that are not pairs of integers.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §4.1. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.wrapping import contacts_text
    >>> contacts_text([(1, 1), (2, -1)])
    '2+ 3-'
    """
    try:
        pairs = [(int(k), int(d)) for k, d in contacts]
    except (TypeError, ValueError):
        raise TautError(f"contacts: expected [(object, direction ±1), ...], got {contacts!r}") from None
    return " ".join(f"{k + 1}{'+' if d > 0 else '-'}" for k, d in pairs)
