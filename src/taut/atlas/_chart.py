"""Charts of a point-mass VSCR: structure, domain and length map (§5.1.1, Eqs. 5.1–5.6 of Rushton 2022).

A *structure* ``S = {s_1, …, s_n}`` (Eq. 5.1) is one cable state per cable, here the
nodes of the cables' state trees (:class:`taut.wrapping.CableStateTree`).  Its
*chart* ``C = {l_0, ν(p), A(p), Q}`` (Eq. 5.2) holds

* ``l_0`` (Eq. 5.3): the length of each cable up to the point where it reaches its last
  object — static segments and the arcs between them (:meth:`taut.wrapping.CableStateTree.static_length`);
* ``ν(p)`` (Eq. 5.4): the arc wrapped about the last object, ``r φ(p)``;
* ``A(p)`` (Eq. 5.5): where the active segment leaves the last object (the exit points of
  the equivalent standard CDPR);
* ``Q``: the component containing the seed point of the *structure-reachable area*
  ``SRA^S = ∩_i CRA^{s_i}`` (Eq. 5.6), the cable-reachable areas of
  :mod:`taut.atlas._reachable` — a shapely polygon.

The cable length at ``p ∈ Q`` is Eq. (4.9): ``l_i = l_{0,i} + ν_i(p) + ‖a_i(p) − p‖``.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.1.1, Eqs. 5.1–5.6; Eq. 4.9. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
import numpy.typing as npt
import shapely
import shapely.affinity
from shapely.geometry import MultiPolygon, Polygon

from taut._checks import as_array
from taut._results import Result, jsonable
from taut.atlas._reachable import close_cracks
from taut.errors import PoseError, TautError
from taut.wrapping import CableStateTree

if TYPE_CHECKING:
    from shapely.geometry.base import BaseGeometry


@dataclass(frozen=True)
class StructureChart(Result):
    """One chart of the structure atlas (Eq. 5.2): a structure and its domain.

    Attributes
    ----------
    index : int
        Its index in the atlas.
    nodes : tuple of int
        The structure ``S`` (Eq. 5.1): the state-tree node of each cable.
    domain : shapely.Polygon
        ``Q``, the component of the structure-reachable area holding the seed.
    seed : ndarray, shape (2,)
        The point [m] the chart was built from.
    states : tuple of tuple of (int, int)
        Per cable, the wrapped objects ``((object, ±1), ...)`` (0-based objects).
    neighbours : dict of int to tuple of int
        Adjacent chart index → the indices of the atlas's edges to it.
    area : float
        Area [m²] of the domain (a property).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.1.1, Eqs. 5.1–5.6. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> chart = atlas.charts[0]
    >>> chart.states, round(chart.area, 4), sorted(chart.neighbours)
    (((), (), (), (), (), ()), 0.1282, [1, 2, 3, 4])
    """

    index: int
    nodes: tuple[int, ...]  #: the structure S (Eq. 5.1) as CST nodes, one per cable
    domain: Polygon  #: Q, the SRA component containing the seed
    seed: np.ndarray  #: the point the chart was built from
    states: tuple[tuple[tuple[int, int], ...], ...] = ()  #: per cable, the wrapped objects ``((object, ±1), ...)``
    #: adjacent chart index → the indices of the edges (transitions) to it
    neighbours: dict[int, tuple[int, ...]] = field(default_factory=dict)

    @property
    def area(self) -> float:
        """Area of the domain [m²]."""
        return float(self.domain.area)

    def as_dict(self) -> dict:
        """The chart as ``taut atlas --out`` writes it, 0-based: ``index``, ``structure``
        (per cable, the wrapped ``[object, direction]`` pairs), ``area``, ``seed``,
        ``domain`` (the exterior ring of each polygon) and ``neighbours``."""
        return {
            "index": self.index,
            "structure": jsonable(self.states),
            "area": self.area,
            "seed": jsonable(self.seed),
            "domain": [jsonable(np.asarray(g.exterior.coords)) for g in getattr(self.domain, "geoms", [self.domain])],
            "neighbours": sorted(self.neighbours),
        }


def chart_lengths(
    trees: Sequence[CableStateTree],
    nodes: Sequence[int],
    points: npt.ArrayLike,
    *,
    offsets: npt.ArrayLike | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The cable lengths of a structure at reference points: Eq. (4.9) with the chart
    elements of Eqs. (5.3)–(5.5), vectorised.

    Parameters
    ----------
    trees : sequence of CableStateTree
        Each cable's state tree.
    nodes : sequence of int
        The structure: a node of each tree.
    points : array_like, shape (N, 2)
        Reference points [m].
    offsets : array_like, shape (n, 2), optional
        Cable ``i`` is attached at ``points + offsets[i]`` (the anchor offsets ``R(θ) r_i``
        of a rigid platform at a fixed orientation; default 0).

    Returns
    -------
    lengths : ndarray, shape (N, n)
        ``l = l_0 + ν + ‖a − b‖`` [m].
    wrapped : ndarray, shape (N, n)
        ``l_0 + ν`` [m]: the length up to where the active segment leaves its object.
    exits : ndarray, shape (N, n, 2)
        ``A``: where the active segments leave their last objects.

    Raises
    ------
    PoseError
        Points that are not rows of two finite numbers.
    TautError
        Nodes or offsets that do not match the trees.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eqs. 4.9 and 5.3–5.5. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> import numpy as np
    >>> from taut.atlas import build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> lengths, _, _ = chart_lengths(atlas.trees, atlas.charts[0].nodes, [start])
    >>> np.round(lengths, 4)
    array([[0.8374, 0.8374, 0.8374, 0.8374, 0.8374, 0.8374]])
    """
    n = len(trees)
    if len(nodes) != n:
        raise TautError(f"nodes: expected one CST node per cable ({n}), got {len(nodes)}")
    P0 = as_array(
        np.atleast_2d(as_array(points, "points", error=PoseError)), "points", shape=(None, 2), error=PoseError
    )
    off = np.zeros((n, 2)) if offsets is None else as_array(offsets, "offsets", shape=(n, 2))
    L_out = np.empty((len(P0), n))
    wrapped = np.empty((len(P0), n))
    A = np.empty((len(P0), n, 2))
    for i, (tree, node) in enumerate(zip(trees, nodes)):
        P = P0 + off[i]
        k = tree.obstacle(node)
        cx, cy, r = tree.circles[k]
        d = tree.direction(node)
        Dx, Dy = P[:, 0] - cx, P[:, 1] - cy
        L = np.sqrt(np.maximum(Dx * Dx + Dy * Dy - r * r, 0.0))
        phi = np.arctan2(Dy, Dx) - np.arctan2(-d * r, L)
        ux, uy = np.cos(phi), np.sin(phi)
        theta = np.arctan2(-d * ux, d * uy)
        low = -math.pi if node == 0 else -0.5 * math.pi
        w = np.mod(d * (theta - tree.theta_in(node)) - low, 2 * math.pi) + low
        wrapped[:, i] = tree.static_length(node) + r * w
        L_out[:, i] = wrapped[:, i] + L
        A[:, i, 0] = cx + d * r * uy
        A[:, i, 1] = cy - d * r * ux
    return L_out, wrapped, A


def structure_reachable_area(
    cras: list[BaseGeometry], *, offsets: npt.ArrayLike | None = None, pra: BaseGeometry | None = None
) -> Polygon | MultiPolygon:
    """The structure-reachable area ``SRA^S = ∩_i CRA^{s_i}`` (Eq. 5.6) of the cables'
    reachable areas; for a rigid platform at orientation ``θ``,
    ``SRA^{S,θ} = (∩_i (CRA^{s_i} − R(θ) r_i)) ∩ PRA^{S,θ}`` (Eq. 5.15).

    Parameters
    ----------
    cras : list of shapely geometries
        The cable-reachable areas of the structure's states (:func:`cable_reachable_area`).
    offsets : array_like, shape (n, 2), optional
        ``R(θ) r_i`` [m] of a rigid platform.
    pra : shapely geometry, optional
        The platform-reachable area (:func:`platform_reachable_area`).

    Returns
    -------
    shapely.Polygon or shapely.MultiPolygon

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, Eqs. 5.6 and 5.15. (docs/references.bib: rushton2022)

    Examples
    --------
    The first chart's domain is the structure-reachable area of its states:

    >>> import numpy as np
    >>> from taut.atlas import build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> start = robot.reference.poses["initial"]
    >>> atlas = build_atlas(robot, start)
    >>> from taut.atlas import cable_reachable_area, structure_reachable_area
    >>> chart = atlas.charts[0]
    >>> space = robot.installation_space
    >>> cras = [cable_reachable_area(t, n, installation_space=space) for t, n in zip(atlas.trees, chart.nodes)]
    >>> round(structure_reachable_area(cras).area, 4), round(chart.area, 4)
    (0.1282, 0.1282)
    """
    if offsets is not None:
        cras = [
            shapely.affinity.translate(a, -float(o[0]), -float(o[1])) if (o[0] or o[1]) else a
            for a, o in zip(cras, np.asarray(offsets, float))
        ]
    sra = shapely.intersection_all(cras)
    if pra is not None:
        sra = sra.intersection(pra)
    return close_cracks(sra)


def component_containing(area: BaseGeometry, point: npt.ArrayLike, *, tol: float = 1e-9) -> Polygon | None:
    """The component of ``area`` that contains ``point`` (within ``tol``), or ``None``."""
    parts = [g for g in getattr(area, "geoms", [area]) if isinstance(g, Polygon) and not g.is_empty]
    if not parts:
        return None
    pt = shapely.Point(point)
    dist = np.array([g.distance(pt) for g in parts])
    j = int(np.argmin(dist))
    return parts[j] if dist[j] <= tol else None
