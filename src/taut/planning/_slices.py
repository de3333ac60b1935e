"""The discretised wrench-feasible C-space of a two-dimensional slice (Fig. 5 of Bohigas et
al. 2013): :func:`slice_map` classifies a grid over two pose coordinates, the others held,
as feasible, some tension out of range, or some cable length out of range.

References
----------
.. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of Cable-Driven
   Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots, Mechanisms and
   Machine Science 12, Springer, 2013, §5, Fig. 5. (docs/references.bib: bohigas2013)
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import numpy.typing as npt

from taut._results import Result
from taut.errors import PoseError, TautError
from taut.planning._manifold import POSE_NAMES, WrenchFeasibleManifold

__all__ = ["SliceMap", "slice_map"]

#: Default points along the two axes of a slice map.
DEFAULT_RESOLUTION = (90, 46)


@dataclass(frozen=True)
class SliceMap(Result):
    """The classes of a grid over the pose coordinates ``axes`` of a slice:
    ``classes[i, j]`` at ``(u[i], v[j])`` is :attr:`FEASIBLE`, :attr:`FORCE_OUT` (some
    ``f_0,i ∓ v_ii`` outside the tension bounds, or ``J`` singular) or :attr:`LENGTH_OUT`
    (some cable length outside its bounds)."""

    FEASIBLE: ClassVar[int] = 0
    FORCE_OUT: ClassVar[int] = 1
    LENGTH_OUT: ClassVar[int] = 2

    axes: tuple[str, str]  #: names of the two pose coordinates (:data:`POSE_NAMES`)
    u: np.ndarray  #: ``(U,)`` values of ``axes[0]``
    v: np.ndarray  #: ``(V,)`` values of ``axes[1]``
    classes: np.ndarray  #: ``(U, V)`` int


def _angle_limits(manifold: WrenchFeasibleManifold) -> dict[str, tuple[float, float]]:
    """The natural range of the angular coordinates of a slice: the window of ``φ``, ``θ ∈ [0, π]``."""
    lo, hi = (float(a) for a in manifold.phi_window)
    return {"phi": (lo, hi), "theta": (0.0, float(np.pi))}


def _default_limits(
    manifold: WrenchFeasibleManifold, axes: Sequence[str], span: np.ndarray | None
) -> list[tuple[float, float]]:
    angles = _angle_limits(manifold)
    out = []
    for a in axes:
        if a in angles:
            out.append(angles[a])
        elif span is not None:
            c = span[:, POSE_NAMES.index(a)]
            lo, hi = float(c.min()), float(c.max())
            pad = max(0.1 * (hi - lo), 0.1)
            out.append((lo - pad, hi + pad))
        else:
            raise TautError(f"slice_map needs limits for {a}: only phi and theta have default limits (or give span)")
    return out


def slice_map(
    manifold: WrenchFeasibleManifold,
    pose: npt.ArrayLike,
    *,
    axes: Sequence[str] = ("phi", "theta"),
    limits: Sequence[tuple[float, float]] | None = None,
    span: npt.ArrayLike | None = None,
    resolution: tuple[int, int] = DEFAULT_RESOLUTION,
) -> SliceMap:
    """Classify a grid over the two pose coordinates ``axes`` of the slice of ``manifold``
    through ``pose`` (the other coordinates held at ``pose``'s), as Fig. 5 of Bohigas et
    al. (2013).

    Parameters
    ----------
    manifold
        The wrench-feasible manifold (its tension and length bounds, its wrench set).
    pose
        ``(6,)`` ``[x, y, z, φ, θ, σ]``: the coordinates that are not ``axes``.
    axes
        Two distinct names of :data:`~taut.planning._manifold.POSE_NAMES`.
    limits
        ``(low, high)`` of each axis; ``None``: ``φ`` over the manifold's window, ``θ`` over
        ``[0, π]``, a position coordinate over the range of ``span`` padded by a tenth (at
        least 0.1 m).
    span
        Poses ``(N, 6)`` (e.g. the chart centres of a planned path) whose range sets the
        default limits of a position coordinate.
    resolution
        Points along ``axes[0]`` and ``axes[1]``.

    Returns
    -------
    SliceMap
        The grid and its classes.

    Raises
    ------
    PoseError
        ``axes`` that are not two distinct pose coordinates, a ``pose`` that is not six
        finite numbers.
    TautError
        A position axis without ``limits`` or ``span``, limits not one pair per axis, or no
        point along an axis.

    References
    ----------
    .. [1] O. Bohigas, M. Manubens, L. Ros, "Navigating the Wrench-Feasible C-Space of
       Cable-Driven Hexapods", in T. Bruckmann, A. Pott (eds.), Cable-Driven Parallel Robots,
       Mechanisms and Machine Science 12, Springer, 2013, §5, Fig. 5.
       (docs/references.bib: bohigas2013)

    Examples
    --------
    >>> import taut
    >>> from taut.planning import slice_map
    >>> from taut.planning._manifold import WrenchFeasibleManifold
    >>> robot = taut.example("robocrane")
    >>> m = slice_map(WrenchFeasibleManifold.from_robot(robot), robot.reference.poses["q1"], resolution=(4, 3))
    >>> m.classes.shape
    (4, 3)
    """
    axes = tuple(axes)
    if len(axes) != 2 or axes[0] == axes[1] or any(a not in POSE_NAMES for a in axes):
        raise PoseError(f"a slice map is over two distinct pose coordinates of {', '.join(POSE_NAMES)}, got {axes}")
    idx = [POSE_NAMES.index(a) for a in axes]
    if limits is None:
        around = None if span is None else np.asarray(span, float).reshape(-1, len(POSE_NAMES))
        limits = _default_limits(manifold, axes, around)
    if len(limits) != 2:
        raise TautError(f"slice_map needs (low, high) limits for each of its two axes, got {len(limits)}")
    if len(resolution) != 2 or min(int(r) for r in resolution) < 1:
        raise TautError(f"slice_map needs at least one point along each axis, got resolution {resolution}")
    (u0, u1), (v0, v1) = limits
    u = np.linspace(float(u0), float(u1), int(resolution[0]))
    v = np.linspace(float(v0), float(v1), int(resolution[1]))
    try:
        q = np.array(pose, float).ravel()
    except (TypeError, ValueError):
        q = np.empty(0)
    if q.size != len(POSE_NAMES) or not np.all(np.isfinite(q)):
        raise PoseError(f"a pose is [{', '.join(POSE_NAMES)}], got {pose!r}")
    cls = np.empty((u.size, v.size), int)
    for i, a in enumerate(u):
        for j, b in enumerate(v):
            q[idx[0]], q[idx[1]] = a, b
            ext = manifold.extreme_tensions(q)
            if ext is None:
                cls[i, j] = SliceMap.FORCE_OUT
                continue
            _, _, rho, f0, V = ext
            d = np.diag(V)
            if not (np.all(rho > manifold.rho_min) and np.all(rho < manifold.rho_max)):
                cls[i, j] = SliceMap.LENGTH_OUT
            elif np.all(f0 - d > manifold.f_min) and np.all(f0 + d < manifold.f_max):
                cls[i, j] = SliceMap.FEASIBLE
            else:
                cls[i, j] = SliceMap.FORCE_OUT
    return SliceMap((axes[0], axes[1]), u, v, cls)
