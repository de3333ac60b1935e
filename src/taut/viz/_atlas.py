"""Figures of a structure atlas (Figs. 5.4 and 5.9 of Rushton 2022):
:func:`plot_atlas` — the charts in grey (darker where they overlap) with their traversable
edges, the start point (and a rigid platform's outline there, at the page's orientation),
and, given a workspace (Alg. 5.2), the workspace in purple over the charts kept.

References
----------
.. [1] M. Rushton, "Variable-Structure Cable-Driven Parallel Robots", PhD thesis, University of
   Waterloo, 2022, Figs. 5.4 and 5.9, Alg. 5.2. (docs/references.bib: rushton2022)
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING

import numpy as np

from taut.geometry import planar_rotation
from taut.viz._robot import draw_scene_2d
from taut.viz._style import empty_figure

if TYPE_CHECKING:
    from matplotlib.axes import Axes
    from matplotlib.figure import Figure
    from shapely.geometry.base import BaseGeometry

    from taut.atlas import AtlasWorkspace, StructureAtlas

__all__ = ["plot_atlas"]

WORKSPACE = "#7b2cbf"


def _fill_chart(ax: Axes, domain: BaseGeometry, label: str | None) -> None:
    """A chart's domain (a polygon or several, with holes) in translucent grey."""
    from matplotlib.patches import PathPatch
    from matplotlib.path import Path

    for g in getattr(domain, "geoms", [domain]):
        if g.is_empty:
            continue
        rings = [np.asarray(g.exterior.coords)] + [np.asarray(r.coords) for r in g.interiors]
        verts = np.concatenate(rings)
        codes = np.concatenate([[Path.MOVETO] + [Path.LINETO] * (len(r) - 2) + [Path.CLOSEPOLY] for r in rings])
        ax.add_patch(
            PathPatch(Path(verts, codes), fc="0.35", ec="none", alpha=0.18, zorder=0.2, label=label, gid="chart")
        )
        label = None


def _draw_charts(ax: Axes, atlas: StructureAtlas, charts: Iterable[int], title: str) -> None:
    draw_scene_2d(atlas.robot, ax, labels=False)
    for k, c in enumerate(charts):
        _fill_chart(ax, atlas.charts[c].domain, "chart (darker: overlap)" if k == 0 else None)
    keep = set(charts)
    first = True
    for e in atlas.edges:
        if e.charts[0] in keep and e.charts[1] in keep:
            ax.plot(
                *e.segment.T, color="0.15", lw=1.2, zorder=2, label="traversable edge" if first else None, gid="edge"
            )
            first = False
    ax.plot(*atlas.start, marker="o", color="black", ms=5, zorder=5, label="start", gid="start")
    robot, shape = atlas.robot, atlas.robot.platform.shape
    if not robot.is_point_mass and shape is not None and shape.polygon:  # at the start, at the page's orientation
        M = np.asarray(shape.polygon, float) @ planar_rotation(atlas.theta).T
        ax.fill(
            *(M + atlas.start).T,
            fc="none",
            ec="black",
            lw=1.0,
            zorder=5,
            label=f"platform (θ = {atlas.theta:.3g} rad)",
            gid="platform",
        )
    ax.set_aspect("equal")
    ax.autoscale_view()
    ax.set_title(title, fontsize=10)


def plot_atlas(atlas: StructureAtlas, workspace: AtlasWorkspace | None = None, fig: Figure | None = None) -> Figure:
    """Figure: the atlas (Fig. 5.4 / 5.9b) and, with ``workspace``, the workspace over the
    charts kept by Alg. 5.2 (Fig. 5.9c) in a second panel; laid out on the empty figure
    ``fig`` (``None``: a new one; a figure that already has axes raises
    :class:`~taut.errors.ArgumentError`), which is returned."""
    panels = 2 if workspace is not None else 1
    fig = empty_figure(fig, "a structure atlas", (6.5 * panels, 5.5))
    axes = fig.subplots(1, panels, squeeze=False)
    ax = axes[0, 0]
    _draw_charts(
        ax,
        atlas,
        range(len(atlas.charts)),
        f"{atlas.robot.name}: {len(atlas.charts)} charts, {atlas.n_edges} adjacent pairs",
    )
    ax.legend(loc="best", fontsize=7)
    if workspace is not None:
        ax = axes[0, 1]
        _draw_charts(
            ax,
            atlas,
            workspace.charts,
            f"{workspace.condition} workspace: {workspace.area:.4g} m², {len(workspace.pruned)} charts pruned",
        )
        P = workspace.points
        if len(P):
            ax.scatter(
                P[:, 0],
                P[:, 1],
                s=(72 * 0.6 * workspace.step / max(np.ptp(P[:, 0]), 1e-9) * 6) ** 2,
                marker="s",
                color=WORKSPACE,
                alpha=0.5,
                lw=0,
                zorder=1.5,
                label="workspace",
                gid="workspace",
            )
        ax.legend(loc="best", fontsize=7)
    fig.tight_layout()
    return fig
