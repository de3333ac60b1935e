"""Workspace of a planar VSCR from its structure atlas, and pruning (§5.3.1, Alg. 5.2 of Rushton 2022).

Within a chart the VSCR is a standard CDPR whose exit points are ``A(p)`` (Eq. 5.5), so
any workspace condition of :mod:`taut.workspace._conditions` that tests structure
matrices (``wrench-closure``, ``wrench-feasible``, ``static``) decides a point:
``W = [u_i]`` with ``u_i = (a_i − b_i)/‖a_i − b_i‖``, ``b_i = p + R(θ) r_i`` the anchor,
and for a rigid platform the moment row ``(R(θ) r_i) × u_i`` (poses at the page's ``θ``).  As in §5.3.1 each chart's
sub-workspace is its domain discretised on a grid (one global grid of step ``step``, so
that overlapping charts share points).  Alg. 5.2 visits the charts from the initial one:
a chart with an empty sub-workspace is pruned; otherwise its adjacent charts are visited
when the shared edge holds a feasible point (the edge is sampled every ``step``; on it
both structures have the same exit points).  Charts never visited are pruned too.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, §5.3.1, Alg. 5.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
import shapely

from taut._checks import as_number
from taut._results import Result, jsonable
from taut.atlas._atlas import PROBE, StructureAtlas
from taut.atlas._chart import chart_lengths
from taut.errors import TautError
from taut.workspace import WorkspaceCondition, WrenchCondition, make_condition

#: Grid points along the longer side of the atlas when no step is given.
DEFAULT_RESOLUTION = 200


@dataclass(frozen=True)
class AtlasWorkspace(Result):
    """The workspace of a structure atlas (Alg. 5.2, :func:`atlas_workspace`).

    Attributes
    ----------
    condition : str
        The workspace condition's name.
    step : float
        Grid step [m].
    points : ndarray, shape (M, 2)
        The grid points of the workspace (union over the charts).
    charts : tuple of int
        The charts kept: reachable from the first, with a non-empty sub-workspace.
    pruned : tuple of int
        The charts removed.
    sub_workspaces : dict of int to ndarray, shape (K, 2)
        Chart → its feasible grid points.
    area : float
        Workspace area [m²]: grid cells of the feasible points (a property).

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.1, Alg. 5.2. (docs/references.bib: rushton2022)

    Examples
    --------
    >>> from taut.atlas import atlas_workspace, build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> atlas = build_atlas(robot, robot.reference.poses["initial"])
    >>> ws = atlas_workspace(atlas, "static", step=0.05)
    >>> len(ws.charts), len(ws.pruned), round(ws.area, 4)
    (5, 26, 0.5775)
    """

    condition: str
    step: float  #: grid step [m]
    points: np.ndarray  #: ``(M, 2)`` grid points of the workspace (union over charts)
    charts: tuple[int, ...]  #: the charts kept (reachable with a non-empty sub-workspace)
    pruned: tuple[int, ...]  #: the charts removed
    sub_workspaces: dict[int, np.ndarray]  #: chart → ``(K, 2)`` feasible grid points

    def __post_init__(self) -> None:
        views = {c: p.view() for c, p in self.sub_workspaces.items()}
        for v in views.values():
            v.flags.writeable = False
        object.__setattr__(self, "sub_workspaces", views)
        super().__post_init__()

    @property
    def area(self) -> float:
        """Workspace area: grid cells of the feasible points."""
        return float(len(self.points)) * self.step**2

    def as_dict(self) -> dict:
        """``condition``, ``step``, ``area``, ``charts`` and ``pruned`` (0-based) and the
        workspace's grid ``points``, in plain JSON types (the sub-workspaces are the points
        of each kept chart's domain)."""
        return {
            "condition": self.condition,
            "step": self.step,
            "area": self.area,
            "charts": list(self.charts),
            "pruned": list(self.pruned),
            "points": jsonable(self.points),
        }


def _feasible(atlas: StructureAtlas, cond: WrenchCondition, chart: int, P: np.ndarray) -> np.ndarray:
    if not len(P):
        return np.zeros(0, bool)
    _, _, A = chart_lengths(atlas.trees, atlas.charts[chart].nodes, P, offsets=atlas.offsets)
    off = atlas.offsets
    D = A - (P[:, None, :] + off[None])
    L = np.hypot(D[..., 0], D[..., 1])
    ok = (L > 1e-12).all(axis=1)
    U = D / np.where(L > 1e-12, L, 1.0)[..., None]
    W = np.swapaxes(U, 1, 2)
    if not atlas.robot.is_point_mass:  # moment row (R r_i) × u_i
        mom = off[None, :, 0] * U[..., 1] - off[None, :, 1] * U[..., 0]
        W = np.concatenate([W, mom[:, None, :]], axis=1)
    out = np.zeros(len(P), bool)
    if ok.any():
        out[ok] = cond.test(atlas.robot, atlas.poses(P[ok]), W[ok])
    return out


def atlas_workspace(
    atlas: StructureAtlas,
    condition: str | WorkspaceCondition | type[WorkspaceCondition] = "wrench-feasible",
    *,
    step: float | None = None,
    progress: Callable[[int, int | None], None] | None = None,
) -> AtlasWorkspace:
    """The workspace of a structure atlas and its pruned charts (Alg. 5.2): each chart's
    domain on a grid, visited from the first chart across edges that hold a feasible point.

    Parameters
    ----------
    atlas : StructureAtlas
    condition : str or WorkspaceCondition, optional
        A condition on the structure matrix (``wrench-closure``, ``wrench-feasible``,
        ``static``), by name or as a :class:`~taut.workspace.WrenchCondition`.
    step : float, optional
        Grid step [m] (default the atlas's extent over :data:`DEFAULT_RESOLUTION`).
    progress : callable, optional
        ``progress(done, charts)`` as charts are decided (visited, or pruned unvisited at
        the end).

    Returns
    -------
    AtlasWorkspace

    Raises
    ------
    TautError
        A condition that does not test structure matrices, or a bad ``step``.

    References
    ----------
    .. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University
       of Waterloo, 2022, §5.3.1, Alg. 5.2. (docs/references.bib: rushton2022)

    Examples
    --------
    The static workspace of the T-shaped robot: most charts are pruned.

    >>> from taut.atlas import atlas_workspace, build_atlas
    >>> from taut.model import example
    >>> robot = example("vscr-t-shaped")
    >>> atlas = build_atlas(robot, robot.reference.poses["initial"])
    >>> ws = atlas_workspace(atlas, "static", step=0.05)
    >>> sorted(ws.charts + ws.pruned) == list(range(len(atlas.charts))), ws.condition
    (True, 'static')
    """
    cond = make_condition(condition)
    if not isinstance(cond, WrenchCondition):
        raise TautError(
            f"the atlas workspace needs a condition on the structure matrix (wrench-closure, wrench-feasible, static), got {cond.name!r}"
        )
    x0, y0, x1, y1 = atlas.reachable_area().bounds
    step = max(x1 - x0, y1 - y0) / DEFAULT_RESOLUTION if step is None else as_number(step, "step", positive=True)
    gx = np.arange(x0 + 0.5 * step, x1, step)
    gy = np.arange(y0 + 0.5 * step, y1, step)
    G = np.stack(np.meshgrid(gx, gy, indexing="xy"), axis=-1).reshape(-1, 2)
    in_ws = np.zeros(len(G), bool)
    subs: dict[int, np.ndarray] = {}
    visited, kept = set(), []
    queue = [0]
    while queue:
        c = queue.pop(0)
        if c in visited:
            continue
        visited.add(c)
        if progress is not None:
            progress(len(visited), len(atlas.charts))
        dom = atlas.charts[c].domain
        inside = np.flatnonzero(shapely.contains_xy(dom, G[:, 0], G[:, 1]))
        ok = _feasible(atlas, cond, c, G[inside])
        if not ok.any():
            continue
        kept.append(c)
        subs[c] = G[inside[ok]]
        in_ws[inside[ok]] = True
        for nb, idx in atlas.charts[c].neighbours.items():
            if nb in visited:
                continue
            for k in idx:
                e = atlas.edges[k]
                a, b = e.segment
                m = max(3, int(math.ceil(np.hypot(*(b - a)) / step)) + 1)
                S = a + np.linspace(0.0, 1.0, m)[:, None] * (b - a) - PROBE * e.normal
                if _feasible(atlas, cond, c, S).any():
                    queue.append(nb)
                    break
    pruned = tuple(c for c in range(len(atlas.charts)) if c not in subs)
    if progress is not None and len(visited) < len(atlas.charts):  # the rest: pruned unvisited
        progress(len(atlas.charts), len(atlas.charts))
    return AtlasWorkspace(cond.name, float(step), G[in_ws], tuple(sorted(kept)), pruned, subs)
